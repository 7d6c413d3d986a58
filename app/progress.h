// A progress line on stderr for long runs of `delpsc mesh`: the phase (protect, refine, check,
// output), the number of vertices, their rate in this phase and the time elapsed, redrawn in
// place at most a few times a second. Silent unless enabled (the command enables it when stderr
// is a terminal and -q is not given), so logs and pipes never see carriage returns.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace delpsc::app {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Starts a phase named `name` with `vertices` so far (0: none to show until vertices() is
  /// called); the rate counts vertices from here. Draws at once.
  void phase(const std::string& name, std::size_t vertices = 0);
  /// The vertex count now; redraws if the last drawing is older than 0.2 s.
  void vertices(std::size_t count);
  /// Erases the line (also done by the destructor), so the report that follows starts clean.
  void clear();

  bool enabled() const { return enabled_; }

 private:
  using Clock = std::chrono::steady_clock;
  void draw();

  bool enabled_;
  bool drawn_ = false;
  bool counting_ = false;  // this phase has a vertex count to show
  std::string phase_;
  std::size_t vertices_ = 0, phase_start_vertices_ = 0;
  Clock::time_point start_, phase_start_, last_draw_;
};

/// True when progress should be shown: stderr is a terminal and -q was not given.
bool progress_wanted(bool quiet);

}  // namespace delpsc::app
