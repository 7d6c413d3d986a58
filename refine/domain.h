// The domain oracle: everything the mesher asks of the piecewise smooth complex it meshes, and
// nothing about how the complex is represented. The paper's only domain-dependent computations
// are (i) where a curve leaves a ball (seg_σ(b), §2.1) and (ii) where a Voronoi edge meets the
// surface patches (§2.3, restricted triangles and their sizes) - Dey & Levine, DelPSC, §5. This
// interface offers exactly those, plus the incidences and a few conveniences, in the spirit of
// CGAL's MeshDomainWithFeatures_3 concept but as a plain virtual interface.
//
// Identifiers are dense indices: corners 0..corner_count()-1, curves 0..curve_count()-1,
// patches 0..patch_count()-1. Curves are oriented from their start corner to their end corner
// and parametrised by arc length s in [0, curve_length]; a closed curve (start == end corner)
// accepts any real s, taken modulo its length. Lengths are in the units of the coordinates.
//
// Implementations: refine/polygon_domain.h (a polygon mesh through protect::Complex and an AABB
// tree). All queries are const and must be safe to call from several threads at once.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

#include "initial_sample.h"

namespace delpsc::refine {

/// A point where a segment or ray meets a patch.
struct SurfaceHit {
  Vec3 point = Vec3::Zero();
  /// Parameter along the query: point = a + t (b - a) for a segment (t in [0, 1]),
  /// origin + t direction for a ray (t >= 0).
  double t = 0;
  std::uint32_t patch = 0;
  /// The query runs inside the patch's surface there instead of crossing it (a degenerate,
  /// measure-zero event): the patch reports the two ends of that overlap, both flagged.
  bool coplanar = false;
};

/// The piece of a curve inside a ball: arc-length interval [s0, s1] (see curve_segment_in_ball).
struct CurveSegment {
  double s0 = 0, s1 = 0;
  bool whole = false;  ///< the whole curve lies in the ball
};

/// The point of the domain's surface closest to a query point.
struct ClosestSurfacePoint {
  Vec3 point = Vec3::Zero();
  std::uint32_t patch = 0;
  double squared_distance = 0;
  /// A normal of the input where the point lies, in the input's own winding (for a polygon model
  /// (b - a) x (c - a) of the closest input triangle, not normalised); zero where there is none.
  Vec3 normal = Vec3::Zero();
};

/// A triangle of a patch's representation (for a polygon model, one of its triangles).
struct PatchTriangle {
  std::array<Vec3, 3> corners;
  std::uint32_t patch = 0;
};

class Domain {
 public:
  virtual ~Domain() = default;

  /// A box containing every corner, curve and patch.
  virtual kernel::Box3 bounding_box() const = 0;

  // ---- corners (0-faces) ----------------------------------------------------------------------
  virtual std::uint32_t corner_count() const = 0;
  virtual Vec3 corner_point(std::uint32_t corner) const = 0;
  /// Curves ending at the corner, once per curve end (a closed curve through it twice).
  virtual std::span<const std::uint32_t> corner_curves(std::uint32_t corner) const = 0;
  /// Patches containing the corner, distinct, increasing.
  virtual std::span<const std::uint32_t> corner_patches(std::uint32_t corner) const = 0;
  /// Where `patch` touches itself at the corner (a pinch: its triangles there form several
  /// fans sharing no edge), the fans: each the two curves bounding it at the corner (an open
  /// fan, a wedge), or kNoElement twice (a closed fan, the patch all round the corner). Empty
  /// where the patch has one fan there - the common case, and the default.
  virtual std::span<const std::array<std::uint32_t, 2>> corner_pinch_fans(std::uint32_t /*corner*/, std::uint32_t /*patch*/) const {
    return {};
  }

  // ---- curves (1-faces) -----------------------------------------------------------------------
  virtual std::uint32_t curve_count() const = 0;
  virtual double curve_length(std::uint32_t curve) const = 0;
  virtual bool curve_closed(std::uint32_t curve) const = 0;
  virtual std::uint32_t curve_start_corner(std::uint32_t curve) const = 0;
  virtual std::uint32_t curve_end_corner(std::uint32_t curve) const = 0;
  /// The point at arc length s.
  virtual Vec3 curve_point(std::uint32_t curve, double s) const = 0;
  /// d_σ: length of the curve piece from s0 to s1; |s1 - s0| on an open curve, the forward arc
  /// ((s1 - s0) mod length) on a closed one.
  virtual double curve_distance(std::uint32_t curve, double s0, double s1) const = 0;
  /// seg_σ(b) for the ball b = B(curve_point(s), r), r > 0: the connected piece of the curve in
  /// the closed ball containing its centre, s0 <= s <= s1 (s reduced to [0, length) first; on a
  /// closed curve the interval is unwrapped and may leave [0, length]; on an open curve it stops
  /// at the ends). whole, with [0, length], when the entire curve lies in the ball.
  virtual CurveSegment curve_segment_in_ball(std::uint32_t curve, double s, double r) const = 0;
  /// Parameter of the point of the curve closest to p.
  virtual double curve_closest_parameter(std::uint32_t curve, const Vec3& p) const = 0;
  /// curve_closest_parameter for each of `points` (out.size() == points.size()), for callers
  /// with many points on one curve; an override may answer a batch faster than point by point.
  virtual void curve_closest_parameters(std::uint32_t curve, std::span<const Vec3> points, std::span<double> out) const {
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = curve_closest_parameter(curve, points[i]);
  }
  /// Patches along the curve, with multiplicity (a patch on both sides of the curve twice).
  virtual std::span<const std::uint32_t> curve_patches(std::uint32_t curve) const = 0;

  // ---- patches (2-faces) ----------------------------------------------------------------------
  virtual std::uint32_t patch_count() const = 0;
  /// Curves bounding the patch, with multiplicity (a curve with the patch on both sides twice);
  /// empty for a patch without boundary (a sphere, a torus).
  virtual std::span<const std::uint32_t> patch_curves(std::uint32_t patch) const = 0;
  /// A point in the interior of the patch, away from its boundary: a seed for patches without
  /// boundary, which have no protected curve to start the mesh from.
  virtual Vec3 patch_interior_point(std::uint32_t patch) const = 0;

  /// Fills `out` (cleared first) with every point where the closed segment [a, b] meets a patch,
  /// sorted by t then patch: once per patch per crossing, also where the segment passes exactly
  /// through an edge or vertex shared by several triangles of the patch's representation. A
  /// point on a curve or corner belongs to several patches and is reported once for each.
  virtual void intersect_segment(const Vec3& a, const Vec3& b, std::vector<SurfaceHit>& out) const = 0;
  /// The same for the ray {origin + t direction, t >= 0}; direction != 0.
  virtual void intersect_ray(const Vec3& origin, const Vec3& direction, std::vector<SurfaceHit>& out) const = 0;
  /// The closest point of all patches to x; nullopt for an empty domain. With a finite
  /// `below_squared`, only a point at squared distance below it counts (nullopt when there is
  /// none): a caller that only asks whether x lies within some distance of the domain bounds the
  /// search by it from the start, which spares most of it.
  virtual std::optional<ClosestSurfacePoint> closest_point(const Vec3& x, double below_squared = HUGE_VAL) const = 0;
  /// Fills `out` (cleared first) with the triangles of the patches' representation whose boxes
  /// meet `box` (closed; a superset of the triangles meeting it). The mesher clips them to a
  /// power cell where no segment finds the surface inside it (cell_surface_point.h). The default
  /// reports none: that last resort then finds nothing. O(log T + k) for a tree over T triangles.
  virtual void triangles_in_box(const kernel::Box3& box, std::vector<PatchTriangle>& out) const {
    (void)box;
    out.clear();
  }

  /// Appends candidate points for the mesher's initial sample (initial_sample.h) to `points`,
  /// each with its patch in `patches`: points of the patches, about 4 per spacing² of area and
  /// spread evenly over it (the mesher keeps ~1 in 6; a gap is no error, refinement fills it);
  /// the same points on every call. None at all when the cover and the random points would be
  /// more than `budget`; the net alone is left out when it does not fit in what they leave. Returns
  /// the parts they form (CandidateParts): a cover to be chosen from first, and a net to be
  /// chosen from last whose radius the mesher may rely on (a promise: every point of every patch
  /// within net_radius of a net point). The default appends none: the mesher then starts from
  /// the balls and the seeds alone, as the paper does.
  virtual CandidateParts surface_candidates(double spacing, std::size_t budget, kernel::LargeVector<Vec3>& points,
                                            kernel::LargeVector<std::uint32_t>& patches) const {
    (void)spacing, (void)budget, (void)points, (void)patches;
    return {};
  }
};

}  // namespace delpsc::refine
