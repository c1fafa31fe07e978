#pragma once
// One-line progress display for long runs (simulated time, steps/s, ETA). It redraws the same
// terminal line and stays silent when stderr is not a terminal (logs, CI).
#include <string>

namespace isphdem {

class ProgressLine {
 public:
  explicit ProgressLine(double t_end, bool enabled);
  ~ProgressLine();
  void update(double t, long step);
  void finish();
  bool enabled() const { return enabled_; }

 private:
  double t_end_;
  bool enabled_;
  double start_, last_draw_;
  double t_start_ = -1.0;
  long step_start_ = 0;
  bool drawn_ = false;
};

// "1h02m", "3m05s", "12.3s"
std::string format_duration(double seconds);

}  // namespace isphdem
