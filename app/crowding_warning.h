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
/// boeing 10, blade 21, mpi and mpi_triang 46, hand 56 (a flap folded back at 2.1°),
/// mech-holes-shark 61.
inline constexpr double kCrowdedRun = 8;
/// The share of the vertices in the densest box below which the warning adds that the rest lie
/// elsewhere.
inline constexpr double kOneSpot = 0.25;

/// The warning's text, or empty when `mesh` has at most kCrowdedRun times `expected` vertices.
/// O(vertices + input edges).
inline std::string crowding_warning(const io::SurfaceMesh& mesh, const protect::Complex& complex, double lambda,
                                    double expected, const std::string& size_text) {
  const auto n = static_cast<double>(mesh.vertices.size());
  if (!(expected > 0) || n <= kCrowdedRun * expected) return {};
  const refine::VertexCrowd crowd = refine::densest_crowd(mesh.vertices, lambda);
  const std::string defect = input_defect_near(complex, crowd.centre, 2 * lambda);
  const Vec3 centre = in_file_frame(crowd.centre);
  // The densest box may hold most of them (hand.off: 97%) or a few (blade.off at 2%: 4%; a
  // fold along a long edge spreads them along it): the share says which, and the defect named is
  // the one at the box, not necessarily the cause of the rest.
  const double share = static_cast<double>(crowd.vertices) / n;
  const char* otherwise = "no fold or narrow corner there: parts of the model thinner than λ, or closer to each "
                          "other, need vertices at their own scale";
  char text[1200];
  std::snprintf(text, sizeof text,
                "%zu vertices, %.0f times what --size %s needs on this model's area; the densest box 3 λ wide, "
                "around (%.6g, %.6g, %.6g), holds %zu of them (%.0f%%)%s: %s",
                mesh.vertices.size(), n / expected, size_text.c_str(), centre.x(), centre.y(), centre.z(), crowd.vertices, 100 * share,
                share < kOneSpot ? ", the rest elsewhere" : "", defect.empty() ? otherwise : defect.c_str());
  return text;
}

}  // namespace delpsc::app
