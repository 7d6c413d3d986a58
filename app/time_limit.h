// `--max-seconds`, shared by `delpsc mesh` and `delpsc protect`: a wall-clock limit on a run,
// counted from the command's start (reading the model included), polled by Protect
// (ProtectOptions::stop) and by the mesher (MesherOptions::stop) between units of work of a
// few milliseconds (a few whole-sample sorts excepted: up to ~1 s on a 10^6-point sample). What
// comes after the stop still runs - `mesh`'s checks, its distances to the input (sampled at
// about one point per vertex after a stop instead of eight) and writing - and takes time in
// proportion to the mesh reached, typically a half to once refinement's own.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include "command.h"

namespace delpsc::app {

class TimeLimit {
 public:
  using Clock = std::chrono::steady_clock;

  /// `seconds` <= 0: no limit. Starts counting now.
  explicit TimeLimit(double seconds) : seconds_(seconds), start_(Clock::now()) {}

  bool active() const { return seconds_ > 0; }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// Remembers when it first answered true (the moment a poll stopped the run).
  bool passed() const {
    if (passed_at_ >= 0) return true;
    if (!active()) return false;
    const double t = elapsed();
    if (t < seconds_) return false;
    passed_at_ = t;
    return true;
  }

  /// For ProtectOptions::stop and MesherOptions::stop: empty without a limit (nothing is polled).
  /// The limit must outlive the function.
  std::function<bool()> poll() const {
    if (!active()) return {};
    return [this] { return passed(); };
  }

  /// "stopped at --max-seconds 10 (after 10.2 s)", the time when passed() first said so.
  std::string stopped() const {
    char text[96];
    std::snprintf(text, sizeof text, "stopped at --max-seconds %g (after %.3g s)", seconds_,
                  passed_at_ >= 0 ? passed_at_ : elapsed());
    return text;
  }

  /// Ends the command with exit code 1 when the limit has passed before `what` (nothing has
  /// been written yet at the points where this is called).
  void check_before(const std::string& input, const char* what) const {
    if (passed()) throw Failure{kCheckFailed, input + ": " + stopped() + " before " + what + "; nothing written"};
  }

 private:
  double seconds_;
  Clock::time_point start_;
  mutable double passed_at_ = -1;
};

/// Registers `--max-seconds` on a subcommand.
inline void add_max_seconds_option(CLI::App& app, double& seconds, const char* what_is_written) {
  app.add_option("--max-seconds", seconds,
                 std::string("Stop after this many seconds of wall-clock time from the start (reading the model "
                             "counts); ") +
                     what_is_written + ", exit code 1 (default 0: no limit)")
      ->check(range_not_nan(0.0, 1e9));
}

}  // namespace delpsc::app
