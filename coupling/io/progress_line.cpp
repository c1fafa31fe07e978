#include "io/progress_line.hpp"

#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace isphdem {

std::string format_duration(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%dm%02ds", int(s / 60), int(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%dh%02dm", int(s / 3600), int(s / 60) % 60);
  return buf;
}

ProgressLine::ProgressLine(double t_end, bool enabled)
    : t_end_(t_end),
      enabled_(enabled && isatty(STDERR_FILENO)),
      start_(omp_get_wtime()),
      last_draw_(0) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(double t, long step) {
  if (!enabled_) return;
  const double now = omp_get_wtime();
  if (t_start_ < 0) {
    t_start_ = t;
    step_start_ = step;
  }
  if (now - last_draw_ < 0.5) return;
  last_draw_ = now;
  const double elapsed = now - start_;
  const double rate = elapsed > 0 ? (step - step_start_) / elapsed : 0.0;
  const double frac = (t - t_start_) / (t_end_ - t_start_);
  const double eta = frac > 0 ? elapsed * (1.0 - frac) / frac : NAN;
  std::fprintf(stderr, "\r  t = %.4g / %.4g s  step %ld  %.0f steps/s  ETA %s   ", t, t_end_, step,
               rate, format_duration(eta).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace isphdem
