#include "run/energy_growth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isphdem {

double grain_mean_square_speed(const DemState& state) {
  double sum = 0.0, volume = 0.0;
  auto add = [&](const Vec3& v, double vol) {
    sum += vol * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    volume += vol;
  };
  for (const DemBody& b : state.bodies) add(b.v, b.volume);
  for (const DemAtom& a : state.atoms)
    if (a.body == -1) add(a.v, 4.0 / 3.0 * M_PI * a.radius * a.radius * a.radius);
  return volume > 0.0 ? sum / volume : 0.0;
}

EnergyGrowthMonitor::EnergyGrowthMonitor(double floor_speed, int window, double factor)
    : floor2_(floor_speed * floor_speed), window_(window), factor_(factor) {}

std::optional<EnergyGrowth> EnergyGrowthMonitor::observe(double q) {
  history_.push_back(q);
  if (history_.size() > static_cast<std::size_t>(2 * window_)) history_.pop_front();
  if (history_.size() < static_cast<std::size_t>(2 * window_)) return std::nullopt;
  const auto mid = history_.begin() + window_;
  const double before = *std::max_element(history_.begin(), mid);
  const double now = *std::max_element(mid, history_.end());
  // Growth is counted from an earlier window above floor / sqrt(factor), so that the present one
  // is above the floor; a ratio against grains at rest means nothing. A non-finite speed is the
  // NaN stop's to report.
  const bool growing = std::isfinite(now) && before > floor2_ / factor_ && now > factor_ * before;
  growing_ = growing ? growing_ + 1 : 0;
  if (growing_ < window_) return std::nullopt;
  return EnergyGrowth{before, now};
}

std::vector<double> EnergyGrowthMonitor::state() const {
  std::vector<double> s(history_.begin(), history_.end());
  s.push_back(double(growing_));
  return s;
}

void EnergyGrowthMonitor::restore(const std::vector<double>& state) {
  if (state.empty()) throw std::runtime_error("energy growth: an empty checkpoint state");
  history_.assign(state.begin(), state.end() - 1);
  growing_ = int(state.back());
}

}  // namespace isphdem
