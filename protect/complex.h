// The piecewise smooth complex (PSC) approximated by a polygon mesh: corners (0-faces), curves
// (1-faces) and surface patches (2-faces), as in Dey & Levine, DelPSC, §1.1.
//
// build_complex turns a TriangleSoup into a Complex in seven steps, each in its own file:
//  1. triangle_cleanup.cpp: exactly coincident vertices are welded; zero-area triangles (repeated
//     vertex, or three exactly collinear vertices - the exact kernel predicate decides) are
//     reported and kept out. A collinear "cap" (c strictly between a and b) is not just dropped,
//     which would open a fake boundary along a-b: the triangle (a, b, x) across its long edge is
//     split at c into (a, c, x) and (c, b, x), the classic cap removal by an edge flip. The split
//     covers exactly the same surface, so geometry is unchanged and the T-junction is healed.
//     A "flat cap", a triangle whose largest angle is within 1e-4 radians of 180°, is healed the
//     same way (the surface moves by its height): its two long edges would otherwise be curves
//     leaving a corner at an angle no ball size can separate.
//  2. edge_table.cpp: unique undirected edges, their incident triangles, each triangle's edges.
//     t_junctions.cpp then heals T-junctions without a cap - a boundary edge with boundary edges
//     running along it through vertices on it - by splitting its triangle into a fan at those
//     vertices (the same surface, now glued there), and the table is made again. "On it" is
//     exact, or off it by rounding (an angle within kCrackRadians = 1e-3 of 180° with its ends;
//     the surface moves by that distance), also when both sides have vertices on the other's.
//  3. feature_edges.cpp: an edge is a feature when it is a boundary edge (1 triangle), a
//     non-manifold edge (3 or more), a manifold edge whose two triangle normals make an angle
//     above the feature angle (consistently oriented first, so a badly oriented soup does not
//     turn flat regions into features), or an edge of a user polyline.
//  4. patches.cpp: patches are the connected components of triangles across non-feature edges;
//     the cut surface of each (the patch cut open along its features) gives its Euler
//     characteristic and boundary loop count; a vertex around which one patch's triangles form
//     two fans sharing no edge is a pinch (Complex::pinches).
//  5. curves.cpp: corners and curves. A feature vertex is a corner when its feature degree is
//     not 2, when its curve turns by more than the corner angle, when the patches along its two
//     feature edges differ (the interior of a curve must see the same patches everywhere, or the
//     complex would not be a complex), or when separate sheets meet only at it (more than one
//     fan of triangles around it, even without features), or when it is a cone's tip (no
//     feature edge, its triangles' angles there summing below kApexAngleDegrees). Curves are
//     the maximal feature polylines between corners; a loop of features with no corner gets one
//     at its smallest vertex index and becomes a closed curve (start corner == end corner).
//  6. patches.cpp (link_incidences): the incidence lists and each patch's topology.
//  7. pinch_fans.cpp: each pinch's fans, the curves bounding each (Complex::pinch_fans), which the
//     mesher's disk condition asks for one disk each; the pinches it cannot follow that way.
//
// Conventions: curves are oriented from start_corner to end_corner, parametrised by arc length
// s in [0, length]. On a closed curve parameters are taken modulo the length (any real s is
// accepted and wrapped), and curve_distance measures the forward arc (in the curve's direction),
// so d(x, y) + d(y, x) = length; the shorter way is min(d(x, y), d(y, x)).
//
// Storage is flat: every per-element list is a CSR pair (offsets of size count + 1, values).
// Complexity of build_complex: O(T + V) expected time for T triangles and V vertices (O(T) edge
// table by bucketing on the smaller vertex, hashed weld), plus one O(T) scan per cap-healing
// round (at most 16) when the soup has zero-area caps. Memory: about 90 bytes per triangle
// (85 MB for a 1M-triangle torus, measured), transiently some 50 more while building.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <delpsc/io/triangle_soup.h>
#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

namespace delpsc::protect {

inline constexpr std::uint32_t kNoIndex = 0xffffffffu;

struct ComplexOptions {
  /// A manifold edge is a feature when the angle between its two triangles' normals exceeds
  /// this, in degrees in [0, 180]: a flat surface has 0°, a cube edge 90°.
  double feature_angle_degrees = 60;
  /// A feature vertex of degree 2 is a corner when the curve turns there by more than this, in
  /// degrees (angle between the directions of the two feature edges; 0° going straight on).
  /// A value >= 180 disables the rule.
  double corner_angle_degrees = 60;
  /// Extra feature polylines as chains of soup vertex indices; each consecutive pair must be an
  /// edge of the mesh (std::invalid_argument otherwise). A closed chain repeats its first index.
  std::vector<std::vector<std::uint32_t>> feature_polylines;
  /// What the caller subtracted from the file's coordinates to bring the model near the origin
  /// (io::move_near_origin; zero if nothing): crack healing judges rounding against the
  /// coordinates as the file wrote them (t_junctions.cpp).
  std::array<double, 3> file_offset{0, 0, 0};  // plain doubles: the options stay a literal type
};

/// Why an edge is a feature (bit flags; 0 = not a feature).
enum FeatureFlag : std::uint8_t {
  kSharpEdge = 1,        ///< dihedral angle above the feature angle
  kBoundaryEdge = 2,     ///< one incident triangle
  kNonManifoldEdge = 4,  ///< three or more incident triangles
  kPolylineEdge = 8,     ///< on a user polyline
};

/// Why a vertex is a corner (bit flags).
enum CornerFlag : std::uint8_t {
  kCornerDegree = 1,     ///< feature degree not 2
  kCornerTurn = 2,       ///< the curve turns by more than the corner angle
  kCornerIncidence = 4,  ///< the two feature edges see different patches
  kCornerSheets = 8,     ///< several separate fans of triangles meet at the vertex
  kCornerLoop = 16,      ///< chosen on a loop of features that had no corner
  kCornerApex = 32,      ///< a cone's tip: no feature edge, its triangles' angles there sum below kApexAngleDegrees
};

/// A vertex with no feature edge whose triangles' angles at it sum to less than this many
/// degrees is a corner (kCornerApex): the tip of a cone of half-angle below 30 degrees (the sum
/// is 360 sin(half-angle)), where the surface is no smooth patch - a 0-face of the complex (§1.1).
/// Refined as a smooth point, the tip looks the same at every scale and refinement never ended.
inline constexpr double kApexAngleDegrees = 180;

/// A fan at a pinch whose two curves leave the vertex at a smaller angle than this many degrees
/// makes the pinch unsupported (Complex::unsupported_pinches): libcgal-demo's
/// cylinder_locally_refined.off has a fan of one needle triangle there (1.3 degrees, folded at
/// 0.5 degrees against its neighbour along a crack 1e-5 of the diagonal wide), at which
/// refinement ran past two million vertices; the other pinches of the libcgal-demo models have
/// fans of 39 degrees or more.
inline constexpr double kNarrowestPinchWedgeDegrees = 10;

struct Curve {
  std::uint32_t first = 0;  ///< offset of its polyline in curve_vertices and curve_arclength
  std::uint32_t count = 0;  ///< polyline vertices, >= 2; a closed curve repeats its first vertex
  std::uint32_t start_corner = kNoIndex, end_corner = kNoIndex;
  bool closed = false;  ///< start_corner == end_corner
  double length = 0;
};

struct Patch {
  int euler_characteristic = 0;    ///< V - E + F of the patch cut open along its features
  std::uint32_t boundary_loops = 0;  ///< boundary components of that cut surface
};

/// The piece of a curve inside a ball, as an interval of arc length (see segment_in_ball).
struct CurveInterval {
  double s0 = 0, s1 = 0;
  bool whole = false;  ///< the whole curve is inside the ball
};

/// What the cleanup saw in the input.
struct CleanupReport {
  std::size_t welded_vertices = 0;  ///< vertices merged into an earlier one with equal coordinates
  std::vector<std::uint32_t> zero_area_triangles;  ///< soup indices, increasing
  /// Triangles added by splitting: one for each cap flipped at its middle vertex, k for a
  /// T-junction of k vertices (t_junctions)
  std::size_t split_triangles = 0;
  std::size_t dropped_caps = 0;  ///< caps that could not be flipped (long edge not shared by exactly one other triangle)
  /// Boundary edges with vertices on them and no cap between (T-junctions): each one's
  /// triangle split into a fan at those vertices, gluing it to the triangles along it
  /// (t_junctions.cpp). The surface is unchanged where they lie exactly on the edge.
  std::size_t t_junctions = 0;
  /// Of those, the ones with vertices off the edge by rounding (at an angle within 1e-3 of 180°
  /// with its ends); the fan moves the surface by up to t_junction_gap there.
  std::size_t near_t_junctions = 0;
  double t_junction_gap = 0;  ///< the largest distance of such a vertex from its edge (model units)
  /// soup indices, increasing: triangles whose largest angle is within 1e-4 radians of 180°,
  /// healed as caps (kept as they are where their long edge is not shared by exactly one other
  /// triangle)
  std::vector<std::uint32_t> flat_caps;
  /// Triangles that repeat an earlier one (the same three vertices once welded): m copies count
  /// m - 1. Such a model overlaps itself; the commands refuse it (find_duplicate_triangles).
  std::size_t duplicate_triangles = 0;
  /// Soup indices of the first repeat found and the triangle it repeats (kNoIndex without one).
  std::array<std::uint32_t, 2> first_duplicate{kNoIndex, kNoIndex};
};

// The arrays are kernel::LargeVector (std::vector on the huge-page pool of kernel/large_array.h):
// with 4 KiB pages building fandisk's complex took ~400 page faults, ~4 ms on our machines.
class Complex {
 public:
  // ---- the cleaned triangle mesh ------------------------------------------------------------
  kernel::LargeVector<Vec3> vertices;  ///< the soup's vertices, same indices (welded copies unused)
  kernel::LargeVector<std::array<std::uint32_t, 3>> triangles;  ///< non-degenerate, soup orientation
  kernel::LargeVector<std::uint32_t> triangle_source;  ///< soup triangle it is (a split part of)
  kernel::LargeVector<std::uint32_t> triangle_patch;

  /// Undirected edges (u < v), sorted; edge k of a triangle is opposite its vertex k (from
  /// vertex k+1 to k+2, mod 3), the convention of kernel::TriangleFeature.
  kernel::LargeVector<std::array<std::uint32_t, 2>> edges;
  kernel::LargeVector<std::array<std::uint32_t, 3>> triangle_edges;
  kernel::LargeVector<std::uint32_t> edge_triangle_offsets, edge_triangles;
  kernel::LargeVector<std::uint8_t> edge_feature;  ///< FeatureFlag bits
  kernel::LargeVector<std::uint32_t> edge_curve;   ///< curve of a feature edge, kNoIndex otherwise

  // ---- corners ------------------------------------------------------------------------------
  kernel::LargeVector<std::uint32_t> corner_vertex;  ///< vertex of each corner
  kernel::LargeVector<std::uint8_t> corner_flags;    ///< CornerFlag bits
  kernel::LargeVector<std::uint32_t> vertex_corner;  ///< corner of each vertex, kNoIndex if none
  /// Curves ending at each corner, once per curve end (a closed curve twice): as many as the
  /// corner's feature degree.
  kernel::LargeVector<std::uint32_t> corner_curve_offsets, corner_curves;
  kernel::LargeVector<std::uint32_t> corner_patch_offsets, corner_patches;  ///< distinct, increasing

  // ---- curves -------------------------------------------------------------------------------
  kernel::LargeVector<Curve> curves;
  kernel::LargeVector<std::uint32_t> curve_vertices;  ///< polylines, concatenated
  kernel::LargeVector<double> curve_arclength;        ///< arc length at each polyline vertex (0 first)
  /// Patches along each curve with multiplicity (a patch on both sides of a slit twice),
  /// increasing: the patches of the triangles on each of its edges.
  kernel::LargeVector<std::uint32_t> curve_patch_offsets, curve_patches;

  // ---- patches ------------------------------------------------------------------------------
  kernel::LargeVector<Patch> patches;
  kernel::LargeVector<std::uint32_t> patch_triangle_offsets, patch_triangles;  ///< increasing
  /// Boundary curves with multiplicity (a curve with the patch on both sides twice), increasing.
  kernel::LargeVector<std::uint32_t> patch_curve_offsets, patch_curves;
  /// Corners that are vertices of the patch's triangles, increasing.
  kernel::LargeVector<std::uint32_t> patch_corner_offsets, patch_corners;
  /// Where a patch touches itself only at a vertex: (vertex, patch) pairs, increasing, for
  /// each vertex around which the patch's triangles form more than one fan through shared
  /// edges (both sides of a slit share the slit's edges: one fan). The patch is then no
  /// 2-manifold with boundary there, which DelPSC assumes (§1.1): its umbrella at that vertex
  /// can never be one disk (D1). The mesher follows a pinch at a corner fan by fan (pinch_fans);
  /// it refuses the others (unsupported_pinches).
  kernel::LargeVector<std::array<std::uint32_t, 2>> pinches;
  /// For each pinch, in the same order, its patch's fans at its vertex (CSR by pinch): each the
  /// two curves whose edges at the vertex bound the fan (a wedge; the same curve twice for a
  /// loop). (Domain::corner_pinch_fans also allows a closed fan, kNoIndex twice, which the
  /// complex never lists: see unsupported_pinches.)
  kernel::LargeVector<std::uint32_t> pinch_fan_offsets;
  kernel::LargeVector<std::array<std::uint32_t, 2>> pinch_fans;
  /// The pinches the mesher refuses, increasing: the vertex is no corner, or a fan is not a
  /// wedge of kNarrowestPinchWedgeDegrees or more between two curves there - bounded by one or
  /// more than two curve edges, or by none (a closed fan: cones of the patch meeting at their
  /// tips, whose umbrellas triangles across the tip joined at every scale in probes), or narrow.
  /// Their pinch_fans ranges are empty.
  kernel::LargeVector<std::array<std::uint32_t, 2>> unsupported_pinches;

  CleanupReport cleanup;
  ComplexOptions options;  ///< as used (feature_polylines in soup indices)

  // ---- counts and lists -----------------------------------------------------------------------
  std::size_t corner_count() const { return corner_vertex.size(); }
  std::size_t curve_count() const { return curves.size(); }
  std::size_t patch_count() const { return patches.size(); }
  std::size_t closed_curve_count() const;
  std::size_t patches_without_boundary() const;

  std::span<const std::uint32_t> edge_triangle_ids(std::uint32_t e) const { return csr(edge_triangle_offsets, edge_triangles, e); }
  std::span<const std::uint32_t> corner_curve_ids(std::uint32_t k) const { return csr(corner_curve_offsets, corner_curves, k); }
  /// The fans of `patch` at corner k where the patch is pinched (pinch_fans); empty where it has
  /// one fan there, or the pinch is unsupported. O(log P) for P pinches.
  std::span<const std::array<std::uint32_t, 2>> corner_pinch_fans(std::uint32_t k, std::uint32_t patch) const;
  std::span<const std::uint32_t> corner_patch_ids(std::uint32_t k) const { return csr(corner_patch_offsets, corner_patches, k); }
  std::span<const std::uint32_t> curve_patch_ids(std::uint32_t c) const { return csr(curve_patch_offsets, curve_patches, c); }
  std::span<const std::uint32_t> patch_triangle_ids(std::uint32_t p) const { return csr(patch_triangle_offsets, patch_triangles, p); }
  std::span<const std::uint32_t> patch_curve_ids(std::uint32_t p) const { return csr(patch_curve_offsets, patch_curves, p); }
  std::span<const std::uint32_t> patch_corner_ids(std::uint32_t p) const { return csr(patch_corner_offsets, patch_corners, p); }
  /// Vertex indices of a curve's polyline, from its start corner to its end corner.
  std::span<const std::uint32_t> curve_polyline(std::uint32_t c) const {
    return {curve_vertices.data() + curves[c].first, curves[c].count};
  }
  /// Arc length at each polyline vertex; the last one is the curve's length.
  std::span<const double> curve_parameters(std::uint32_t c) const {
    return {curve_arclength.data() + curves[c].first, curves[c].count};
  }

  // ---- curve geometry (curves.cpp); c < curve_count() --------------------------------------------

  /// s reduced to [0, length): modulo the length on a closed curve, clamped to [0, length] on an
  /// open one. O(1).
  double wrap_parameter(std::uint32_t c, double s) const;

  /// The point at arc length s (wrapped). Exactly the polyline vertex at a vertex's parameter.
  /// O(log n) for n polyline vertices.
  Vec3 point_at(std::uint32_t c, double s) const;

  /// Length d_σ of the curve piece from parameter s0 to s1: |s1 - s0| on an open curve (both
  /// clamped), the forward arc ((s1 - s0) mod length) on a closed one. O(1).
  double curve_distance(std::uint32_t c, double s0, double s1) const;

  /// seg_σ(b) of DelPSC §2.1 for the ball b = B(point_at(s), r), r > 0: the connected piece of
  /// the curve inside the closed ball that contains the centre, as [s0, s1] with s0 <= s <= s1
  /// (s wrapped first). Found by walking the polyline from s both ways to the first point where
  /// it leaves the ball (whether a vertex is inside is decided exactly on the rounded ball; the
  /// exit point is a double segment-sphere intersection). On an open curve [s0, s1] is within
  /// [0, length] and stops at the curve's ends; on a closed curve s0 may be negative and s1 may
  /// exceed the length (unwrapped, s1 - s0 <= length); whole is set, with [0, length], when the
  /// entire curve lies in the ball. O(log n + k) for k polyline vertices inside the ball.
  CurveInterval segment_in_ball(std::uint32_t c, double s, double r) const;

  /// Parameter of the point of the curve closest to p (the first in curve order among equally
  /// close ones). O(n).
  double closest_parameter(std::uint32_t c, const Vec3& p) const;

  /// The parameter of a point of the curve closest to each of `points` (out.size() ==
  /// points.size()), faster than closest_parameter for many: an AABB tree over the segments,
  /// built once (O(n log n)), then O(log n) a point on or near the curve (the G1 check's ball
  /// centres), O(n) at worst (a circle's centre). Among equally close points (that centre, or a
  /// closed curve's start, at 0 and at its length) it may name another than closest_parameter;
  /// the distance is the same up to rounding.
  void closest_parameters(std::uint32_t c, std::span<const Vec3> points, std::span<double> out) const;

  /// Parameter of the polyline vertex with the given vertex index, or nullopt if the curve does
  /// not pass through it (on a closed curve the start corner gives 0). O(n).
  std::optional<double> parameter_of_vertex(std::uint32_t c, std::uint32_t vertex) const;

 private:
  static std::span<const std::uint32_t> csr(const kernel::LargeVector<std::uint32_t>& offsets,
                                            const kernel::LargeVector<std::uint32_t>& values, std::uint32_t i) {
    return {values.data() + offsets[i], offsets[i + 1] - offsets[i]};
  }
};

/// Builds the complex of a triangle soup (see the file comment). Throws std::invalid_argument
/// for a vertex index out of range, non-finite coordinates, angles outside [0, 180] (the corner
/// angle may be larger, which disables it), or a polyline pair that is not a mesh edge. An
/// empty soup, or one whose triangles all have zero area, gives an empty complex.
Complex build_complex(const io::TriangleSoup& soup, const ComplexOptions& options = {});

}  // namespace delpsc::protect
