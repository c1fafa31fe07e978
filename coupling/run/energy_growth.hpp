// The grains' kinetic energy growing faster than the fluid step can follow: the sign of an
// unstable coupling (a drag or PMS force exchanged once per step that overshoots, a body too
// light for the explicit exchange), which the fluid's CFL stop sees only once the fluid has
// caught up, and which nothing stops when the grains run away inside the fluid step.
//
// Measured is the grains' mean square speed, weighted by volume (bodies by their own volume,
// free spheres by 4/3 pi r^3; rotation is not counted): proportional to their kinetic energy at
// one density. A step counts as growing when the largest value of the last kEnergyGrowthWindow
// steps is more than kEnergyGrowthFactor times the largest of the window before, and that one's
// mean speed is above a hundredth of dx/dt, so the present one's above a tenth (a grain moving a
// tenth of a fluid spacing per fluid step); the run stops after kEnergyGrowthWindow growing steps
// in a row. Energy growing at a steady rate is caught when its e-folding time is below 20 / ln 100
// = 4.3 steps: no motion the step resolves grows that fast. Window maxima, not single values, let
// an oscillation that grows count at its zero crossings and keep a stable one from looking like
// growth there; the speed floor and the growth held over a whole window keep a start from rest (a
// ratio against almost nothing, which falls as the motion goes on) from looking like it: a speed
// rising as t, t^2 or t^3 from rest counts as growing for 3, 10 and 18 steps.
#ifndef ISPHDEM_RUN_ENERGY_GROWTH_HPP
#define ISPHDEM_RUN_ENERGY_GROWTH_HPP

#include <deque>
#include <optional>
#include <vector>

#include "dem_state.hpp"

namespace isphdem {

constexpr int kEnergyGrowthWindow = 20;
constexpr double kEnergyGrowthFactor = 100.0;

// Volume-weighted mean square speed of the grains: bodies by their centre of mass, free spheres
// (body == -1) each; 0 without grains.
double grain_mean_square_speed(const DemState& state);

struct EnergyGrowth {
  double before = 0.0, now = 0.0;  // the two windows' largest mean square speeds
};

class EnergyGrowthMonitor {
 public:
  // floor_speed: the mean speed the growth must reach, at least (m/s).
  explicit EnergyGrowthMonitor(double floor_speed, int window = kEnergyGrowthWindow,
                               double factor = kEnergyGrowthFactor);
  // Feeds the value after one more step; the growth once it has held for a window of steps.
  std::optional<EnergyGrowth> observe(double mean_square_speed);
  // What it has seen (a checkpoint's part): the values of the last windows, then the count of
  // growing steps; restore() takes what state() gave.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

 private:
  double floor2_;
  int window_;
  double factor_;
  std::deque<double> history_;  // the last 2 x window values, oldest first
  int growing_ = 0;             // steps in a row that counted as growing
};

}  // namespace isphdem

#endif
