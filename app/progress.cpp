#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace delpsc::app {

ProgressLine::ProgressLine(ProgressMode mode) : mode_(mode), start_(Clock::now()) {
  phase_start_ = last_draw_ = start_;
}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::phase(const std::string& name, std::size_t vertices) {
  phase_ = name;
  vertices_ = phase_start_vertices_ = vertices;
  counting_ = vertices > 0;
  phase_start_ = Clock::now();
  draw();
}

void ProgressLine::vertices(std::size_t count) {
  vertices_ = count;
  counting_ = true;
  const auto every = mode_ == ProgressMode::log ? std::chrono::milliseconds(10'000) : std::chrono::milliseconds(200);
  if (enabled() && Clock::now() - last_draw_ > every) draw();
}

void ProgressLine::draw() {
  if (!enabled()) return;
  const bool terminal = mode_ == ProgressMode::terminal;
  const auto now = Clock::now();
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double in_phase = std::chrono::duration<double>(now - phase_start_).count();
  std::fprintf(stderr, terminal ? "\rdelpsc: %-13s" : "delpsc: %-13s", phase_.c_str());
  if (counting_) std::fprintf(stderr, " %9zu vertices", vertices_);
  // The rate only once it means something (a second into the phase, some vertices added).
  if (in_phase > 1 && vertices_ > phase_start_vertices_)
    std::fprintf(stderr, " %8.0f/s", static_cast<double>(vertices_ - phase_start_vertices_) / in_phase);
  std::fprintf(stderr, terminal ? " %7.1f s\033[K" : " %7.1f s\n", elapsed);
  std::fflush(stderr);
  drawn_ = terminal;  // a log's lines stay
}

void ProgressLine::clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

ProgressMode progress_wanted(bool quiet, bool asked) {
  if (quiet) return ProgressMode::off;
  if (isatty(STDERR_FILENO)) return ProgressMode::terminal;
  return asked ? ProgressMode::log : ProgressMode::off;
}

}  // namespace delpsc::app
