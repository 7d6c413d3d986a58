// How much work a size λ means for a model, known before any work is done, so that a size far
// too small for the model is refused at once with a message instead of ending at a cap minutes
// (or gigabytes) later.
//  - Protection (§2): a ball of radius at most λ covers at most 2λ of a curve, so the curves need
//    at least (total curve length) / 2λ balls; more than protect's max_balls cannot succeed.
//  - Refinement (§3): with facet_size λ alone the output has 0.66 A / λ² vertices for surface
//    area A on every libcgal-demo model (fandisk, part, anchor, joint, elephant at 0.5%); about
//    1.5 KB of memory per vertex while meshing (joint at 0.25%: 237,452 vertices, 354 MB peak RSS;
//    BENCHMARKS.md, "Input checks and memory of delpsc mesh").
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

#include <delpsc/protect/complex.h>

#include "command.h"

namespace delpsc::app {

/// Expected output vertices for facet_size λ (see above).
inline double expected_vertices(const protect::Complex& complex, double lambda) {
  double area = 0;
  for (const auto& t : complex.triangles) {
    const Vec3& a = complex.vertices[t[0]];
    area += 0.5 * (complex.vertices[t[1]] - a).cross(complex.vertices[t[2]] - a).norm();
  }
  return 0.66 * area / (lambda * lambda);
}

/// Refused without an explicit --max-vertices: about 15 GB while meshing.
inline constexpr double kMostExpectedVertices = 1e7;

/// The cap on vertices when --max-vertices is not given: 50 times the expected count, at least
/// two million (the 1° wedge at 0.5% needs 438,000), at most twenty million (memory).
inline std::size_t automatic_vertex_cap(double expected) {
  return static_cast<std::size_t>(std::clamp(50 * expected, 2e6, 2e7));
}

/// Bad-input exit when the curves alone need more than `max_balls` balls at λ.
inline void reject_size_for_balls(const protect::Complex& complex, double lambda, std::size_t max_balls,
                                  const std::string& size_text) {
  double length = 0;
  for (const protect::Curve& c : complex.curves) length += c.length;
  const double least = length / (2 * lambda);
  if (least <= static_cast<double>(max_balls)) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "--size %s is too small for this model: its feature curves (%.6g long in all) need at least %.3g "
                "protecting balls, more than the cap of %zu; choose a larger size",
                size_text.c_str(), length, least, max_balls);
  throw Failure{kBadInput, message};
}

/// Bad-input exit when meshing at λ would need more than kMostExpectedVertices vertices and the
/// user did not ask for a vertex cap.
inline void reject_size_for_vertices(double expected, const std::string& size_text) {
  if (expected <= kMostExpectedVertices) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "--size %s is too small for this model: about %.3g vertices (%.3g GB of memory while meshing); "
                "choose a larger size, or give --max-vertices to try anyway",
                size_text.c_str(), expected, expected * 1.5e-6);
  throw Failure{kBadInput, message};
}

/// Bad-input exit when facet_distance is below λ / 10^4 and the user did not ask for a vertex
/// cap: on a surface of curvature radius R a triangle of circumradius r stands about r² / 2R off
/// it, so the distance d asks for r ≈ sqrt(2 R d); at d = λ / 10^4 and R = 20 λ that is λ / 16,
/// some 250 times the vertices λ alone gives - past the automatic cap, after minutes.
inline void reject_facet_distance(double distance, double lambda, const std::string& text, bool capped) {
  if (capped || distance >= 1e-4 * lambda) return;
  throw Failure{kBadInput, "--facet-distance " + text +
                               " is below 1/10000 of --size: on any curved part that asks for hundreds of times "
                               "the vertices the size alone needs; choose a larger distance, or give "
                               "--max-vertices to try anyway"};
}

}  // namespace delpsc::app
