// Folds of the input: edges whose two triangles nearly lie on each other (a dihedral angle of a
// few degrees, the surface turning back on itself). DelPSC resolves any dihedral angle in
// principle, but near a fold of angle θ the surface's two sheets are d sin θ apart at distance d
// from the edge, so the balls and samples there must shrink with θ; at a scanned model's 2° fold
// refinement reaches balls 10^4 times below the size first (the 'floor' of protect::
// options_for_size). This names the fold for the message that reports it, or a corner where two
// curves leave at a small angle.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include <delpsc/kernel/point.h>
#include <delpsc/protect/complex.h>

namespace delpsc::protect {

struct Fold {
  std::uint32_t edge = kNoIndex;  ///< index into Complex::edges
  double dihedral_degrees = 180;  ///< angle between its two triangles: 180 flat, 0 folded shut
};

/// Which edges sharpest_fold_near looks at: all, or only those on no feature curve (a sharp edge
/// there is one the feature angle left out, which refinement must then resolve as smooth surface).
enum class FoldEdges { all, off_curves };

/// The edge with exactly two triangles and the smallest dihedral angle below `below_degrees`
/// among those within `radius` of `where` (and of `which`), or nullopt. The angle is measured
/// between the two triangles' third vertices around the edge, so it does not depend on their
/// orientation. Rounded arithmetic: a diagnostic, never a combinatorial decision. O(edges).
std::optional<Fold> sharpest_fold_near(const Complex& complex, const Vec3& where, double radius,
                                       double below_degrees, FoldEdges which = FoldEdges::all);

/// Two feature curves leaving a corner at a small angle: a narrow wedge of the surface between
/// them, or a needle triangle whose edges are all sharp (libcgal-demo's triceratops.off, 5.3°).
/// Balls along both curves must shrink with the angle near the corner.
struct NarrowCorner {
  std::uint32_t corner = kNoIndex;                  ///< index into Complex::corner_vertex
  std::uint32_t curves[2] = {kNoIndex, kNoIndex};   ///< the two curves (equal for a loop)
  double angle_degrees = 180;                       ///< between their first edges at the corner
  /// The nearest curve not through the corner and its distance from it (kNoIndex and infinity
  /// if there is none). The corner's ball stays within it (C3.b), and where it ends the two
  /// curves are only about 2 clearance sin(angle / 2) apart: the balls they need there.
  std::uint32_t nearest_curve = kNoIndex;
  double clearance = std::numeric_limits<double>::infinity();
};

/// Among the corners within `radius` of `where`, the pair of feature edges leaving one of them
/// at the smallest angle below `below_degrees`, or nullopt. Rounded arithmetic, a diagnostic like
/// sharpest_fold_near. O(edges + corners).
std::optional<NarrowCorner> narrowest_corner_near(const Complex& complex, const Vec3& where, double radius,
                                                  double below_degrees);

/// A curve passing near a point: its id and its distance.
struct NearCurve {
  std::uint32_t curve = kNoIndex;
  double distance = std::numeric_limits<double>::infinity();
};

/// The feature curve nearest to `where`, at a distance above zero, among those not in
/// `excluded`, or nullopt if there is none: the gap that forces balls small there, for messages
/// (Protect's failure at its floor, narrowest_corner_near's clearance). Rounded arithmetic, a
/// diagnostic. O(edges).
std::optional<NearCurve> nearest_curve_except(const Complex& complex, const Vec3& where,
                                              std::span<const std::uint32_t> excluded);

/// A patch passing near a point: its id and its distance.
struct NearPatch {
  std::uint32_t patch = kNoIndex;
  double distance = std::numeric_limits<double>::infinity();
};

/// The patch nearest to `where`, at a distance above zero, among those not in `excluded`, or
/// nullopt if there is none: for Protect's failure at its floor, a surface nearly touching a
/// curve it does not bound (a fin's edge hovering over a sheet) rather than another curve.
/// Rounded arithmetic, a diagnostic. O(triangles).
std::optional<NearPatch> nearest_patch_except(const Complex& complex, const Vec3& where,
                                              std::span<const std::uint32_t> excluded);

/// Where curve c comes back near its own point at parameter s: the nearest point of c farther
/// along the curve from s than 3 times its distance (a hairpin: a sheet folded over, its boundary
/// returning close by), as {c, distance}; nullopt if none. The gap nearest_curve_except cannot
/// see, since it leaves the ball's own curve out. Rounded arithmetic, a diagnostic. O(n) for n
/// polyline vertices.
std::optional<NearCurve> curve_returning_near(const Complex& complex, std::uint32_t c, double s);

}  // namespace delpsc::protect
