// What in the input made protecting balls shrink past their floor (protect::ProtectionError's
// where()), for the error message: a fold within λ of that ball (libcgal-demo's hand.off, 2.1°;
// mech-holes-shark.off, 8°: no --angle helps there), else a corner within λ where two curves
// leave less than 15° apart (triceratops.off: a needle triangle whose three edges are all sharp;
// dino.off). Wedges of 1° to 10° mesh (the acceptance tests): only a failure names one.
#pragma once

#include <cstdio>
#include <string>

#include <delpsc/kernel/point.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/folds.h>

namespace delpsc::app {

inline constexpr double kDefectDegrees = 15;

/// A sentence naming the defect near `where`, or empty when none is found. O(edges).
inline std::string input_defect_near(const protect::Complex& complex, const Vec3& where, double lambda) {
  char text[400] = "";
  if (const auto fold = protect::sharpest_fold_near(complex, where, lambda, kDefectDegrees)) {
    const Vec3& a = complex.vertices[complex.edges[fold->edge][0]];
    const Vec3& b = complex.vertices[complex.edges[fold->edge][1]];
    std::snprintf(text, sizeof text,
                  "the input folds back on itself there: its two triangles on the edge from (%.6g, %.6g, %.6g) to "
                  "(%.6g, %.6g, %.6g) are %.2g degrees apart - repair the model there",
                  a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), fold->dihedral_degrees);
  } else if (const auto wedge = protect::narrowest_corner_near(complex, where, lambda, kDefectDegrees)) {
    const Vec3& c = complex.vertices[complex.corner_vertex[wedge->corner]];
    std::snprintf(text, sizeof text,
                  "curves %u and %u leave the corner at (%.6g, %.6g, %.6g) only %.2g degrees apart - a needle or a "
                  "sliver of the surface between them? repair the model there",
                  wedge->curves[0], wedge->curves[1], c.x(), c.y(), c.z(), wedge->angle_degrees);
  }
  return text;
}

}  // namespace delpsc::app
