// `--max-seconds`, shared by `delpsc mesh` and `delpsc protect`: a wall-clock limit on a run,
// counted from the command's start (reading the model included), polled by Protect
// (ProtectOptions::stop) and by the mesher (MesherOptions::stop) between units of work of a
// few milliseconds (a few whole-sample sorts excepted: up to ~1 s on a 10^6-point sample). What
// comes after refinement still runs - `mesh`'s checks, its distances to the input (sampled at
// about one point per vertex after a stop instead of eight) and writing - and takes time in
// proportion to the mesh reached, typically a half to once refinement's own; but on inputs
// where the checks are slow (fans of thin triangles: four times refinement's time) they are
// cut short at twice the limit (grace()), so that the command ends within about twice it.
#pragma once

#include <atomic>
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
  /// Remembers when it first answered true (the moment a poll stopped the run). Safe to call
  /// from several threads (the distance measurement polls from two).
  bool passed() const { return active() && reached(seconds_, passed_at_); }

  /// For ProtectOptions::stop and MesherOptions::stop: empty without a limit (nothing is polled).
  /// The limit must outlive the function.
  std::function<bool()> poll() const {
    if (!active()) return {};
    return [this] { return passed(); };
  }

  /// For what follows refinement (the checks, the distances to the input): true once twice the
  /// limit has passed, so that they still run after a stop at the limit (a report of the mesh
  /// reached) but cannot keep the command going long past it. Empty without a limit; thread-safe.
  std::function<bool()> grace() const {
    if (!active()) return {};
    return [this] { return reached(2 * seconds_, grace_ended_at_); };
  }

  /// "stopped at --max-seconds 10 (after 20 s, twice the limit)", the time when grace() first
  /// said so.
  std::string grace_ended() const {
    char text[112];
    const double at = grace_ended_at_.load(std::memory_order_relaxed);
    std::snprintf(text, sizeof text, "stopped at --max-seconds %g (after %.3g s, twice the limit)", seconds_,
                  at >= 0 ? at : elapsed());
    return text;
  }

  /// "stopped at --max-seconds 10 (after 10.2 s)", the time when passed() first said so.
  std::string stopped() const {
    char text[96];
    const double at = passed_at_.load(std::memory_order_relaxed);
    std::snprintf(text, sizeof text, "stopped at --max-seconds %g (after %.3g s)", seconds_, at >= 0 ? at : elapsed());
    return text;
  }

  /// Ends the command with exit code 1 when the limit has passed before `what` (nothing has
  /// been written yet at the points where this is called).
  void check_before(const std::string& input, const char* what) const {
    if (passed()) throw Failure{kCheckFailed, input + ": " + stopped() + " before " + what + "; nothing written"};
  }

 private:
  /// Whether `limit` seconds have passed; the first time it says so is kept in `at` (-1 before),
  /// and from then on the answer is true without reading the clock.
  bool reached(double limit, std::atomic<double>& at) const {
    if (at.load(std::memory_order_relaxed) >= 0) return true;
    const double t = elapsed();
    if (t < limit) return false;
    double unset = -1;
    at.compare_exchange_strong(unset, t, std::memory_order_relaxed);
    return true;
  }

  double seconds_;
  Clock::time_point start_;
  mutable std::atomic<double> passed_at_{-1};
  mutable std::atomic<double> grace_ended_at_{-1};
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
