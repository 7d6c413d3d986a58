// The Domain of a polygon mesh: the piecewise smooth complex of protect::build_complex answers
// the corner, curve and incidence queries, an AABB tree over its triangles the intersections.
//
// Intersections are classified exactly (kernel::intersect_segment_triangle), so a segment
// through an edge or vertex of the mesh is seen by every triangle around it with the same
// feature; the hits are then merged by (patch, mesh vertex / mesh edge / triangle), which
// reports such a crossing once per patch. Coplanar overlaps (the segment runs inside a planar
// part of a patch) are merged per patch into their extreme parameters, reported as two hits
// flagged coplanar; a crossing of the same patch within that span is absorbed into it.
//
// Cost: construction O(T log T) for the tree (the complex is built beforehand); a segment query
// O(log T + k) box tests and exact triangle tests for k triangles met, plus O(k log k) merging.
// Closest points come from a ClosestPointIndex over the same triangles (closest_point_index.h:
// the tree, with fans of thin triangles searched by angle).
//
// Coordinates: the predicates are exact anywhere, but the mesher's constructions (orthocentres,
// surface points) lose a bit for every doubling of the model's distance from the origin over its
// size; a model far out (millions of diagonals: G1 fails by rounding; 10^9: refinement rejects its own
// points for minutes) should first be moved next to the origin, exactly, by io::move_near_origin
// (io/model_frame.h), as `delpsc mesh` does.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <delpsc/protect/certified_fans.h>
#include <delpsc/protect/complex.h>

#include "closest_point_index.h"
#include "domain.h"

namespace delpsc::refine {

class PolygonDomain final : public Domain {
 public:
  /// Takes the complex (moved in) and builds the tree over its triangles. With `search_fans`
  /// (the default), the certified fans of at least ClosestPointIndex::kMinFanDegree triangles
  /// (protect/certified_fans.h) are taken out of the tree for segment queries and searched by
  /// angle instead, exactly; false keeps every triangle in the tree (the tests compare both).
  /// Precondition for meshing: no two triangles cross or overlap other than along a shared edge
  /// or vertex (protect::find_self_intersections finds those that do; `delpsc` refuses them).
  /// Along such a crossing the disk condition cannot hold, and a Mesher stops only at
  /// MesherOptions::max_vertices.
  explicit PolygonDomain(protect::Complex complex, bool search_fans = true);
  /// Convenience: builds the complex of `soup` first.
  explicit PolygonDomain(const io::TriangleSoup& soup, const protect::ComplexOptions& options = {});

  const protect::Complex& complex() const { return complex_; }
  const kernel::AabbTree& tree() const { return tree_; }
  /// The fans searched by angle for segment queries (0 without, or with search_fans false).
  std::size_t segment_fan_count() const { return segment_fans_.size(); }
  /// Closest points on the triangles, fans of thin triangles searched by angle (closest_point_index.h).
  const ClosestPointIndex& closest_point_index() const { return closest_; }
  PolygonDomain(const PolygonDomain&) = delete;
  PolygonDomain& operator=(const PolygonDomain&) = delete;

  kernel::Box3 bounding_box() const override { return tree_.bounds(); }

  std::uint32_t corner_count() const override { return static_cast<std::uint32_t>(complex_.corner_count()); }
  Vec3 corner_point(std::uint32_t k) const override { return complex_.vertices[complex_.corner_vertex[k]]; }
  std::span<const std::uint32_t> corner_curves(std::uint32_t k) const override { return complex_.corner_curve_ids(k); }
  std::span<const std::uint32_t> corner_patches(std::uint32_t k) const override { return complex_.corner_patch_ids(k); }
  std::span<const std::array<std::uint32_t, 2>> corner_pinch_fans(std::uint32_t k, std::uint32_t patch) const override {
    return complex_.corner_pinch_fans(k, patch);
  }

  std::uint32_t curve_count() const override { return static_cast<std::uint32_t>(complex_.curve_count()); }
  double curve_length(std::uint32_t c) const override { return complex_.curves[c].length; }
  bool curve_closed(std::uint32_t c) const override { return complex_.curves[c].closed; }
  std::uint32_t curve_start_corner(std::uint32_t c) const override { return complex_.curves[c].start_corner; }
  std::uint32_t curve_end_corner(std::uint32_t c) const override { return complex_.curves[c].end_corner; }
  Vec3 curve_point(std::uint32_t c, double s) const override { return complex_.point_at(c, s); }
  double curve_distance(std::uint32_t c, double s0, double s1) const override { return complex_.curve_distance(c, s0, s1); }
  CurveSegment curve_segment_in_ball(std::uint32_t c, double s, double r) const override;
  double curve_closest_parameter(std::uint32_t c, const Vec3& p) const override { return complex_.closest_parameter(c, p); }
  void curve_closest_parameters(std::uint32_t c, std::span<const Vec3> points, std::span<double> out) const override {
    complex_.closest_parameters(c, points, out);
  }
  std::span<const std::uint32_t> curve_patches(std::uint32_t c) const override { return complex_.curve_patch_ids(c); }

  std::uint32_t patch_count() const override { return static_cast<std::uint32_t>(complex_.patch_count()); }
  std::span<const std::uint32_t> patch_curves(std::uint32_t p) const override { return complex_.patch_curve_ids(p); }
  Vec3 patch_interior_point(std::uint32_t p) const override { return patch_points_[p]; }

  void intersect_segment(const Vec3& a, const Vec3& b, std::vector<SurfaceHit>& out) const override;
  void intersect_ray(const Vec3& origin, const Vec3& direction, std::vector<SurfaceHit>& out) const override;
  std::optional<ClosestSurfacePoint> closest_point(const Vec3& x, double below_squared = HUGE_VAL) const override;
  void triangles_in_box(const kernel::Box3& box, std::vector<PatchTriangle>& out) const override;
  /// The triangles the closed segment [a, b] meets, before merging into per-patch hits, in
  /// increasing triangle order: those of kernel::AabbTree::intersect_segment over all of them,
  /// with fans searched by angle (the angular search's predicates take only points in their
  /// exact range, kernel::in_exact_range; other segments go to the whole tree). Clears `out`.
  void triangle_hits(const Vec3& a, const Vec3& b, std::vector<kernel::TriangleIntersection>& out) const;
  /// First a jittered lattice on each cluster of nearly parallel triangles (triangle_clusters.h,
  /// normals within kClusterAngle of the seed's) of at least spacing² / 2 (surface_lattice.h;
  /// the count returned), then per triangle a number of uniform random points proportional to
  /// its area, in a cluster with a lattice only within ~2.5 spacings of the cluster's boundary
  /// (deterministic: the generator is seeded by the triangle's index), then the net: every
  /// vertex of a triangle and each triangle's triangle_samples at kNetRadius spacings, when it
  /// fits in what the budget leaves. O(T log T + points).
  CandidateParts surface_candidates(double spacing, std::size_t budget, kernel::LargeVector<Vec3>& points,
                                    kernel::LargeVector<std::uint32_t>& patches) const override;

 private:
  // Merges the tree's per-triangle hits into per-patch hits (see the file comment). `b` is the
  // segment's end or, for a ray, origin + direction (t is in units of b - a either way).
  void merge_hits(std::vector<kernel::TriangleIntersection>& hits, const Vec3& a, const Vec3& b,
                  std::vector<SurfaceHit>& out) const;

  /// The triangles the segment meets into `out` (cleared), unsorted: the tree's, or with fans
  /// intersect_segment_with_fans'.
  void collect_hits(const Vec3& a, const Vec3& b, std::vector<kernel::TriangleIntersection>& out) const;
  /// Appends to `hits` the triangles the segment meets, as tree_.intersect_segment would:
  /// rest_tree_'s, and each fan's near the segment's shadow (the fans' own triangles only).
  void intersect_segment_with_fans(const Vec3& a, const Vec3& b, std::vector<kernel::TriangleIntersection>& hits) const;

  protect::Complex complex_;
  kernel::AabbTree tree_;
  ClosestPointIndex closest_;  // over tree_ and complex_'s arrays: the domain is neither copied nor moved
  std::vector<Vec3> patch_points_;  // centroid of each patch's largest triangle
  // Segment queries around fans of thin triangles (every box there holds the fan's centre, and a
  // dual edge near it visited them all): each fan's own triangles (those of two fans belong to
  // the first) searched by angle, the others in rest_tree_. Empty without fans. With fans there
  // are three trees: tree_ (rays, segments outside the predicates' range, callers), this one,
  // and closest_'s own over the triangles of its fans, which differ: an exact segment search
  // needs fans certified disjoint (protect/certified_fans.h), a closest-point bound any axis
  // (a corner's fan with its two side triangles is one there and not here).
  struct SegmentFan {
    protect::detail::Fan fan;
    kernel::Box3 box;
    /// Three corners spanning the plane holding all the fan's own triangles (a flat cap), or
    /// none: a segment with both ends strictly on one side of it meets none of them.
    std::optional<std::array<Vec3, 3>> plane;
  };
  std::vector<SegmentFan> segment_fans_;
  std::vector<std::uint32_t> fan_owner_;  // per triangle: its SegmentFan, or protect::detail::kNoFan
  std::vector<std::array<std::uint32_t, 3>> rest_triangles_;
  std::vector<std::uint32_t> rest_ids_;
  kernel::AabbTree rest_tree_;
};

}  // namespace delpsc::refine
