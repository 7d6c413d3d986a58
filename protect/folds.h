// Folds of the input: edges whose two triangles nearly lie on each other (a dihedral angle of a
// few degrees, the surface turning back on itself). DelPSC resolves any dihedral angle in
// principle, but near a fold of angle θ the surface's two sheets are d sin θ apart at distance d
// from the edge, so the balls and samples there must shrink with θ; at a scanned model's 2° fold
// refinement reaches balls 10^4 times below the size first (the 'floor' of protect::
// options_for_size). This names the fold for the message that reports it.
#pragma once

#include <cstdint>
#include <optional>

#include <delpsc/kernel/point.h>
#include <delpsc/protect/complex.h>

namespace delpsc::protect {

struct Fold {
  std::uint32_t edge = kNoIndex;  ///< index into Complex::edges
  double dihedral_degrees = 180;  ///< angle between its two triangles: 180 flat, 0 folded shut
};

/// The edge with exactly two triangles and the smallest dihedral angle below `below_degrees`
/// among those within `radius` of `where`, or nullopt. The angle is measured between the two
/// triangles' third vertices around the edge, so it does not depend on their orientation.
/// Rounded arithmetic: a diagnostic, never a combinatorial decision. O(edges).
std::optional<Fold> sharpest_fold_near(const Complex& complex, const Vec3& where, double radius,
                                       double below_degrees);

}  // namespace delpsc::protect
