// The warning of `delpsc mesh` when a run makes far more vertices than its size needs on the
// model's area: where they crowd (refine/vertex_crowding.h) and the defect of the input there
// (input_defects.h), so that the user knows what to repair instead of wondering at the count.
#pragma once

#include <cstdio>
#include <string>

#include <delpsc/io/surface_mesh.h>
#include <delpsc/protect/complex.h>
#include <delpsc/refine/vertex_crowding.h>

#include "input_defects.h"

namespace delpsc::app {

/// Runs above this many times expected_vertices() are warned about. At 2% the seven models of
/// the CGAL table mesh at 0.93-1.53 times it; six of the 121 valid libcgal-demo models exceed 8:
/// boeing 10, blade 21, mpi 30 and 46, hand 56 (a flap folded back at 2.1°), mech-holes-shark 61.
inline constexpr double kCrowdedRun = 8;
/// The share of the vertices in the densest box above which the warning speaks of one spot.
inline constexpr double kOneSpot = 0.25;

/// The warning's text, or empty when `mesh` has at most kCrowdedRun times `expected` vertices.
/// O(vertices + input edges).
inline std::string crowding_warning(const io::SurfaceMesh& mesh, const protect::Complex& complex, double lambda,
                                    double expected, const std::string& size_text) {
  const auto n = static_cast<double>(mesh.vertices.size());
  if (!(expected > 0) || n <= kCrowdedRun * expected) return {};
  const refine::VertexCrowd crowd = refine::densest_crowd(mesh.vertices, lambda);
  const std::string defect = input_defect_near(complex, crowd.centre, 2 * lambda);
  // One spot holds most of them (hand.off: 97%), or they are spread (blade.off at 2%: 21 times,
  // the densest box 4%): then the model's thin parts need them, wherever they are.
  const double share = static_cast<double>(crowd.vertices) / n;
  const char* spread = share < kOneSpot ? "no one spot, the most:" : "one spot:";
  const char* otherwise = share < kOneSpot ? "parts of the model thinner than λ, or closer to each other, need "
                                             "vertices at their own scale"
                                           : "a thin or folded spot of the input?";
  char text[1200];
  std::snprintf(text, sizeof text,
                "%zu vertices, %.0f times what --size %s needs on this model's area; %s %zu of them (%.0f%%) lie in a "
                "box 3 λ wide around (%.6g, %.6g, %.6g): %s",
                mesh.vertices.size(), n / expected, size_text.c_str(), spread, crowd.vertices, 100 * share,
                crowd.centre.x(), crowd.centre.y(), crowd.centre.z(), defect.empty() ? otherwise : defect.c_str());
  return text;
}

}  // namespace delpsc::app
