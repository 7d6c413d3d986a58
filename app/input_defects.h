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
/// An edge on no curve whose triangles' normals differ by more than the default feature angle
/// (less a degree, for rounding) was left out of the curves by a larger --angle: the mesh must
/// then resolve it as smooth surface, which DelPSC's input class does not promise (§1: the sharp
/// edges are curves). Below this dihedral angle such an edge is named.
inline constexpr double kUnmarkedSharpDihedral = 180 - protect::ComplexOptions{}.feature_angle_degrees - 1;

/// The sharpest edge on no curve within `radius` of `where` whose triangles' normals differ by
/// more than the default feature angle, or nullopt (always with the default --angle). O(edges).
inline std::optional<protect::Fold> unmarked_sharp_edge_near(const protect::Complex& complex, const Vec3& where,
                                                             double radius) {
  return protect::sharpest_fold_near(complex, where, radius, kUnmarkedSharpDihedral, protect::FoldEdges::off_curves);
}

/// "the edge from (a) to (b)" in the file's frame.
inline std::string edge_words(const protect::Complex& complex, std::uint32_t edge) {
  const Vec3 a = in_file_frame(complex.vertices[complex.edges[edge][0]]);
  const Vec3 b = in_file_frame(complex.vertices[complex.edges[edge][1]]);
  char text[200];
  std::snprintf(text, sizeof text, "the edge from (%.6g, %.6g, %.6g) to (%.6g, %.6g, %.6g)", a.x(), a.y(), a.z(), b.x(),
                b.y(), b.z());
  return text;
}

/// A warning when the feature angle leaves sharp edges off the curves (see
/// kUnmarkedSharpDihedral), naming the sharpest, or empty. `mesh` prints it before refining.
inline std::string unmarked_sharp_edge_warning(const protect::Complex& complex, double feature_angle,
                                               const std::string& path) {
  const auto edge = unmarked_sharp_edge_near(complex, Vec3::Zero(), std::numeric_limits<double>::infinity());
  if (!edge) return {};
  char text[640];
  std::snprintf(text, sizeof text,
                "%s: %s is sharp - its triangles' normals differ by %.3g degrees - but no feature curve at --angle "
                "%g; refinement must then resolve such edges as smooth surface, which can take many times the "
                "vertices the size asks for or fail, and a smaller --angle (the default is %g) makes them curves",
                path.c_str(), edge_words(complex, edge->edge).c_str(), 180 - edge->dihedral_degrees, feature_angle,
                protect::ComplexOptions{}.feature_angle_degrees);
  return text;
}

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
  char text[640];
  std::snprintf(text, sizeof text,
                "%s: two triangles meet at only %.3g degrees, on %s (a fold of the surface, or a very sharp edge); "
                "`delpsc mesh` samples the two sheets apart there, which can take many times the vertices the size "
                "asks for",
                path.c_str(), fold->dihedral_degrees, edge_words(complex, fold->edge).c_str());
  return text;
}

/// A sentence naming the defect near `where`, or empty when none is found. O(edges).
inline std::string input_defect_near(const protect::Complex& complex, const Vec3& where, double lambda) {
  char text[640] = "";
  // First an edge that a larger --angle left off the curves: a fold nearby is then no defect of
  // its own (a 2° wedge meshes when its 90° edges are curves, and fails when they are not).
  if (const auto sharp = unmarked_sharp_edge_near(complex, where, lambda)) {
    std::snprintf(text, sizeof text,
                  "%s is sharp (its triangles' normals differ by %.3g degrees) but no feature curve at this "
                  "--angle: a smaller --angle makes it one",
                  edge_words(complex, sharp->edge).c_str(), 180 - sharp->dihedral_degrees);
  } else if (const auto fold = protect::sharpest_fold_near(complex, where, lambda, kDefectDegrees)) {
    std::snprintf(text, sizeof text, "the input folds back on itself there: its two triangles on %s are %.3g degrees apart - repair the model there",
                  edge_words(complex, fold->edge).c_str(), fold->dihedral_degrees);
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
