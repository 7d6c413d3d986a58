// Progress on stderr for long runs of `delpsc mesh`: the phase (protect, refine, check, output),
// the number of vertices, their rate in this phase and the time elapsed. On a terminal one line
// redrawn in place at most a few times a second; in a log (`--progress` with stderr a file or a
// pipe: a batch job's log) plain lines, one when a phase starts and one every ten seconds while
// vertices are counted (refinement), with no carriage returns or terminal codes. Silent
// otherwise, and with -q.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace delpsc::app {

/// Where progress goes: nowhere, a line redrawn in place, or lines appended to a log.
enum class ProgressMode { off, terminal, log };

class ProgressLine {
 public:
  explicit ProgressLine(ProgressMode mode);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Starts a phase named `name` with `vertices` so far (0: none to show until vertices() is
  /// called); the rate counts vertices from here. Draws at once.
  void phase(const std::string& name, std::size_t vertices = 0);
  /// The vertex count now; redraws if the last drawing is older than 0.2 s (a log: 10 s).
  void vertices(std::size_t count);
  /// Erases the line (also done by the destructor), so the report that follows starts clean.
  void clear();

  bool enabled() const { return mode_ != ProgressMode::off; }

 private:
  using Clock = std::chrono::steady_clock;
  void draw();

  ProgressMode mode_;
  bool drawn_ = false;
  bool counting_ = false;  // this phase has a vertex count to show
  std::string phase_;
  std::size_t vertices_ = 0, phase_start_vertices_ = 0;
  Clock::time_point start_, phase_start_, last_draw_;
};

/// How progress is shown: off with -q (`quiet`); on a terminal when stderr is one; else in a log
/// when asked for (`--progress`), else off.
ProgressMode progress_wanted(bool quiet, bool asked);

}  // namespace delpsc::app
