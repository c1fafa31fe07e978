#include "time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isph {

double TimeStepLimits::min() const { return std::min({cfl, viscous, force}); }

std::string TimeStepLimits::limiting() const {
  const double m = min();
  if (m == cfl) return "CFL";
  if (m == viscous) return "viscous";
  return "force";
}

TimeStepLimits time_step_limits(const TimeStepParams& p, double dx, double max_speed, double nu,
                                double max_accel) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  TimeStepLimits l;
  l.cfl = max_speed > 0.0 ? p.cfl * dx / max_speed : inf;
  l.viscous = nu > 0.0 ? p.viscous * dx * dx / nu : inf;
  l.force = max_accel > 0.0 ? p.force * std::sqrt(dx / max_accel) : inf;
  return l;
}

}  // namespace isph
