// Reading a model for a subcommand: io errors become a bad-input exit with the reader's message,
// and the reader's warnings go to stderr unless -q.
#pragma once

#include <delpsc/io/error.h>
#include <delpsc/io/read_model.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/self_intersections.h>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "command.h"

namespace delpsc::app {

inline io::ReadResult load_model(const std::string& path, const GlobalOptions& g) {
  io::ReadResult result;
  try {
    result = io::read_model(path);
  } catch (const io::Error& e) {
    throw Failure{kBadInput, e.what()};
  }
  if (!g.quiet) {
    for (const auto& w : result.report.warnings)
      std::fprintf(stderr, "delpsc: warning: %s\n", w.c_str());
    if (!result.report.degenerate_triangles.empty())
      std::fprintf(stderr, "delpsc: warning: %s: %zu zero-area triangle(s) kept out of the complex\n",
                   path.c_str(), result.report.degenerate_triangles.size());
  }
  return result;
}

/// The piecewise smooth complex of a model read by load_model, with the feature and corner
/// angles of the command line; a bad user polyline or similar becomes a bad-input exit naming
/// the file.
inline protect::Complex load_complex(const io::ReadResult& model, const std::string& path,
                                     double feature_angle, double corner_angle) {
  protect::ComplexOptions options;
  options.feature_angle_degrees = feature_angle;
  options.corner_angle_degrees = corner_angle;
  try {
    return protect::build_complex(model.soup, options);
  } catch (const std::invalid_argument& e) {
    throw Failure{kBadInput, path + ": " + e.what()};
  }
}

/// At most this many self-intersecting pairs are looked for (info reports ">= this" as this).
inline constexpr std::size_t kSelfIntersectionsCounted = 100;

/// A bad-input exit when two triangles of the complex cross or overlap other than along a shared
/// edge or vertex (protect/self_intersections.h): such a model is no piecewise smooth complex
/// (§1.1), the disk condition can never hold along the crossing, and refinement would run until
/// it hit a cap or ran out of memory. The message names the first pair and where it is.
inline void reject_self_intersections(const protect::Complex& complex, const std::string& path) {
  const auto pairs = protect::find_self_intersections(complex, kSelfIntersectionsCounted);
  if (pairs.empty()) return;
  const auto [s, t] = pairs.front();
  Vec3 c = Vec3::Zero();
  for (const std::uint32_t v : complex.triangles[s]) c += complex.vertices[v] / 3;
  char message[512];
  std::snprintf(message, sizeof message,
                "%s: the model intersects itself: triangles %u and %u (counted after splitting polygons into "
                "triangles) cross or overlap near (%.6g, %.6g, %.6g), and %s%zu pair(s) in all; DelPSC needs "
                "surfaces that meet only along shared edges and vertices - repair the model "
                "(`delpsc info` counts the pairs)",
                path.c_str(), complex.triangle_source[s], complex.triangle_source[t], c.x(), c.y(), c.z(),
                pairs.size() == kSelfIntersectionsCounted ? "at least " : "", pairs.size());
  throw Failure{kBadInput, message};
}

}  // namespace delpsc::app
