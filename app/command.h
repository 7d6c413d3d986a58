// What every subcommand of the delpsc program shares: how it registers, how it reports, and what
// its exit codes mean.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "report.h"

namespace delpsc::app {

/// Exit codes: 0 success; 1 the job ran but stopped early (a cap) or a check it was asked for
/// failed; 2 bad input or bad usage (unreadable file, malformed model, impossible parameters,
/// a job larger than memory); 3 an internal error (a bug: please report it).
enum ExitCode : int { kOk = 0, kCheckFailed = 1, kBadInput = 2, kInternalError = 3 };

/// Options every subcommand understands.
struct GlobalOptions {
  bool quiet = false;    ///< -q: only the key=value report and errors
  int verbosity = 0;     ///< -v (repeatable): more detail on stderr
  std::string report_path;  ///< --report FILE.json: the final report also as JSON (main writes it)
};

/// Thrown inside a subcommand to end it with a message on stderr and an exit code.
struct Failure {
  ExitCode code;
  std::string message;
};

/// Prints one "key=value" line of the final report on stdout and records it for --report
/// (report.h).
inline void report(const char* key, const std::string& value) { final_report().add(key, value); }
// A string literal would otherwise take the bool overload (a pointer converts to bool before it
// converts to std::string) and print "true": `stopped=true` from info was caught by its test.
inline void report(const char* key, const char* value) { final_report().add(key, std::string(value)); }
inline void report(const char* key, double value) { final_report().add(key, value); }
inline void report(const char* key, long long value) { final_report().add(key, value); }
inline void report(const char* key, std::size_t value) { final_report().add(key, value); }
inline void report(const char* key, bool value) { final_report().add(key, value); }

/// CLI::Range(lo, hi) that also refuses NaN: Range compares, and every comparison with NaN is
/// false, so "--facet-angle nan" passed it and failed inside the mesher as an internal error.
inline CLI::Validator range_not_nan(double lo, double hi) {
  const CLI::Validator not_nan(
      [](std::string& text) {
        return std::isnan(std::strtod(text.c_str(), nullptr)) ? std::string("NaN is not a value here") : std::string();
      },
      "", "not NaN");
  return CLI::Range(lo, hi) & not_nan;
}

/// For a count option: a whole number written in scientific or decimal-point notation ("1e6",
/// "2.5e5", "300000.0") becomes its digits before CLI11 converts it (which reads integers only:
/// "--max-vertices 1e15" was refused as "could not convert" beside a help text saying up to
/// 1e+15). Anything else is left as written, for the conversion and the checks to refuse.
inline CLI::Validator count_in_any_notation() {
  return CLI::Validator(
      [](std::string& text) {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && std::isfinite(x) && x >= 0 && x <= 9e15 && x == std::floor(x) &&
            text.find_first_of(".eE") != std::string::npos)
          text = std::to_string(static_cast<std::uint64_t>(x));
        return std::string();
      },
      "", "count");
}

/// The model to read, the positional IN of every command that reads one.
inline void add_model_input(CLI::App& app, std::string& input) {
  app.add_option("IN", input, "Polygon model: OFF, OBJ, STL (ASCII or binary) or PLY")->required();
}

/// --angle and --corner-angle, which decide the complex (protect::build_complex) for features,
/// protect and mesh alike.
inline void add_feature_angles(CLI::App& app, double& angle, double& corner_angle) {
  app.add_option("--angle", angle, "Feature angle in degrees: an edge whose face normals differ by more is sharp")
      ->check(range_not_nan(0.0, 180.0));
  app.add_option("--corner-angle", corner_angle,
                 "A curve turning by more than this many degrees at a vertex gets a corner there")
      ->check(range_not_nan(0.0, 180.0));
}

/// A subcommand registers its options on `app` and returns the function that runs it.
using Runner = std::function<int(const GlobalOptions&)>;

// One registration function per subcommand, each in its own cmd_*.cpp.
Runner register_triangulate(CLI::App& app);
Runner register_features(CLI::App& app);
Runner register_info(CLI::App& app);
Runner register_protect(CLI::App& app);
Runner register_mesh(CLI::App& app);

}  // namespace delpsc::app
