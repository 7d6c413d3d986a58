#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace delpsc::app {

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), start_(Clock::now()) {
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
  if (enabled_ && Clock::now() - last_draw_ > std::chrono::milliseconds(200)) draw();
}

void ProgressLine::draw() {
  if (!enabled_) return;
  const auto now = Clock::now();
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double in_phase = std::chrono::duration<double>(now - phase_start_).count();
  std::fprintf(stderr, "\rdelpsc: %-13s", phase_.c_str());
  if (counting_) std::fprintf(stderr, " %9zu vertices", vertices_);
  // The rate only once it means something (a second into the phase, some vertices added).
  if (in_phase > 1 && vertices_ > phase_start_vertices_)
    std::fprintf(stderr, " %8.0f/s", static_cast<double>(vertices_ - phase_start_vertices_) / in_phase);
  std::fprintf(stderr, " %7.1f s\033[K", elapsed);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

bool progress_wanted(bool quiet) { return !quiet && isatty(STDERR_FILENO); }

}  // namespace delpsc::app
