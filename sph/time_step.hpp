#pragma once
// Time-step limits of the explicit parts of the ISPH step. The pressure is implicit, so only
// advection (CFL), explicit viscosity and body-force acceleration limit the step.
#include <string>

namespace isph {

struct TimeStepParams {
  double cfl = 0.25;       // dt <= cfl * dx / max|u|
  double viscous = 0.125;  // dt <= viscous * dx^2 / nu
  double force = 0.25;     // dt <= force * sqrt(dx / max|a|)
};

struct TimeStepLimits {
  double cfl = 0.0, viscous = 0.0, force = 0.0;  // +inf where a limit does not apply
  double min() const;
  std::string limiting() const;  // "CFL", "viscous" or "force"
};

TimeStepLimits time_step_limits(const TimeStepParams& p, double dx, double max_speed, double nu,
                                double max_accel);

}  // namespace isph
