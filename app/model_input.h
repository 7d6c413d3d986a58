// Reading a model for a subcommand: io errors become a bad-input exit with the reader's message,
// and the reader's warnings go to stderr unless -q.
#pragma once

#include <delpsc/io/error.h>
#include <delpsc/io/read_model.h>
#include <delpsc/protect/complex.h>
#include <stdexcept>

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

}  // namespace delpsc::app
