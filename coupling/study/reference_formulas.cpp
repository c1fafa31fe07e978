#include "study/reference_formulas.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace isphdem {

double stokes_velocity(double d, double rho_p, double rho_f, double nu, double g) {
  return (rho_p - rho_f) * g * d * d / (18.0 * rho_f * nu);
}

double schiller_naumann_velocity(double d, double rho_p, double rho_f, double nu, double g) {
  if (!(d > 0 && rho_f > 0 && nu > 0 && g > 0 && rho_p > rho_f))
    throw std::runtime_error(
        "schiller_naumann_velocity(d, rho_p, rho_f, nu, g) needs d, rho_f, nu, g > 0 and "
        "rho_p > rho_f");
  const double weight = (rho_p - rho_f) * g * M_PI * d * d * d / 6.0;
  auto drag = [&](double v) {
    const double re = d * v / nu;
    const double cd = 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687));
    return cd * M_PI * d * d / 8.0 * rho_f * v * v;
  };
  // Drag grows monotonically with v and is below Stokes drag nowhere: the root lies below the
  // Stokes velocity.
  double lo = 0.0, hi = stokes_velocity(d, rho_p, rho_f, nu, g);
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double v = 0.5 * (lo + hi);
    (drag(v) > weight ? hi : lo) = v;
  }
  return 0.5 * (lo + hi);
}

double ergun_gradient(double eps, double d, double nu, double rho, double u) {
  const double e3 = eps * eps * eps;
  return 150.0 * rho * nu * (1 - eps) * (1 - eps) * u / (e3 * d * d) +
         1.75 * rho * (1 - eps) * u * u / (e3 * d);
}

double cubic_array_drag_factor(double phi) {
  if (!(phi >= 0.0 && phi <= 0.125))
    throw std::runtime_error("cubic_array_drag_factor(phi) holds for 0 <= phi <= 0.125 (got " +
                             std::to_string(phi) + ")");
  const double c = std::cbrt(phi);
  const double c8 = phi * phi * c * c;  // phi^(8/3)
  return 1.0 / (1.0 - 1.7601 * c + phi - 1.5593 * phi * phi + 3.9799 * c8 - 3.0734 * c8 * c * c);
}

}  // namespace isphdem
