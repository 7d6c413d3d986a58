// What in the input made protecting balls shrink past their floor (protect::ProtectionError's
// where()), for the error message: a fold within λ of that ball (libcgal-demo's hand.off, 2.1°;
// mech-holes-shark.off, 8°: no --angle helps there), else a corner within λ where two curves
// leave less than 15° apart (triceratops.off: a needle triangle whose three edges are all sharp;
// dino.off). Wedges of 1° to 10° mesh (the acceptance tests): only a failure names one.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/point.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/folds.h>

#include "file_frame.h"

namespace delpsc::app {

inline constexpr double kDefectDegrees = 15;

/// The smallest dihedral angle of the model over every edge with two triangles (any radius, any
/// angle below 181°; a flat edge is 180), or nullopt when no edge has two. O(edges).
inline std::optional<protect::Fold> sharpest_fold(const protect::Complex& complex) {
  // Within an infinite radius of any point: every edge (a distance that overflows is still not
  // above infinity).
  return protect::sharpest_fold_near(complex, Vec3::Zero(), std::numeric_limits<double>::infinity(), 181);
}

/// A warning for a fold sharper than kDefectDegrees, or empty: a fold of a few degrees meshes, but
/// refinement must sample its two sheets apart, at their distance rather than at the size
/// (hand.off's 2.1° flap took 96% of 97,899 vertices at 2%; a tetrahedron 1e-6 high, over a
/// minute and 2 GB at 10%). `info` and `mesh` print it before anything long starts.
inline std::string fold_warning(const protect::Complex& complex, const std::optional<protect::Fold>& fold,
                                const std::string& path) {
  if (!fold || !(fold->dihedral_degrees < kDefectDegrees)) return {};
  const Vec3 a = in_file_frame(complex.vertices[complex.edges[fold->edge][0]]);
  const Vec3 b = in_file_frame(complex.vertices[complex.edges[fold->edge][1]]);
  char text[640];
  std::snprintf(text, sizeof text,
                "%s: two triangles meet at only %.3g degrees, on the edge from (%.6g, %.6g, %.6g) to (%.6g, %.6g, "
                "%.6g) (a fold of the surface, or a very sharp edge); `delpsc mesh` samples the two sheets apart "
                "there, which can take many times the vertices the size asks for",
                path.c_str(), fold->dihedral_degrees, a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  return text;
}

/// A sentence naming the defect near `where`, or empty when none is found. O(edges).
inline std::string input_defect_near(const protect::Complex& complex, const Vec3& where, double lambda) {
  char text[640] = "";
  if (const auto fold = protect::sharpest_fold_near(complex, where, lambda, kDefectDegrees)) {
    const Vec3 a = in_file_frame(complex.vertices[complex.edges[fold->edge][0]]);
    const Vec3 b = in_file_frame(complex.vertices[complex.edges[fold->edge][1]]);
    std::snprintf(text, sizeof text,
                  "the input folds back on itself there: its two triangles on the edge from (%.6g, %.6g, %.6g) to "
                  "(%.6g, %.6g, %.6g) are %.3g degrees apart - repair the model there",
                  a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), fold->dihedral_degrees);
  } else if (const auto wedge = protect::narrowest_corner_near(complex, where, lambda, kDefectDegrees)) {
    const Vec3 c = in_file_frame(complex.vertices[complex.corner_vertex[wedge->corner]]);
    // How small the balls must get there (folds.h): the corner's ball stays within the nearest
    // other curve, where the two are this far apart (libcgal-demo's mpi.off: 0.069° and a curve
    // 0.0145 away, balls of 8.7e-6, 2.5e-7 of the diagonal).
    char need[200] = "";
    if (std::isfinite(wedge->clearance)) {
      kernel::Box3 box;
      for (const Vec3& p : complex.vertices) box.extend(p);
      const double half_gap = wedge->clearance * std::sin(wedge->angle_degrees * std::numbers::pi / 360);
      std::snprintf(need, sizeof need,
                    "; curve %u passes %.3g from that corner, so its ball stays within that, where the two are %.2g "
                    "apart: balls of %.2g (%.2g of the bounding-box diagonal) there",
                    wedge->nearest_curve, wedge->clearance, 2 * half_gap, half_gap, half_gap / (box.hi - box.lo).norm());
    }
    std::snprintf(text, sizeof text,
                  "curves %u and %u leave the corner at (%.6g, %.6g, %.6g) only %.3g degrees apart%s - a needle or a "
                  "sliver of the surface between them? repair the model there",
                  wedge->curves[0], wedge->curves[1], c.x(), c.y(), c.z(), wedge->angle_degrees, need);
  }
  return text;
}

}  // namespace delpsc::app
