#include "unresolved/drag_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isphdem {

double wen_yu_drag_coefficient(double reynolds) {
  if (!(reynolds > 0.0)) throw std::domain_error("drag coefficient needs Re > 0");
  if (reynolds > 1000.0) return 0.44;
  return 24.0 * (1.0 + 0.15 * std::pow(reynolds, 0.687)) / reynolds;
}

SeedResistance::SeedResistance(const SeedResistanceParameters& p) : p_(p) {
  if (!(p.grain_diameter > 0.0)) throw std::invalid_argument("drag: grain diameter must be > 0");
  if (!(p.kinematic_viscosity > 0.0))
    throw std::invalid_argument("drag: kinematic viscosity must be > 0");
  if (!(p.alpha >= 0.0) || !(p.beta >= 0.0))
    throw std::invalid_argument("drag: Ergun constants must be >= 0");
  if (!(p.switch_porosity > 0.0 && p.switch_porosity <= 1.0))
    throw std::invalid_argument("drag: switch porosity must be in (0, 1]");
  if (p.blend && !(p.blend_half_width > 0.0))
    throw std::invalid_argument("drag: blend half width must be > 0");
}

namespace {
void check_porosity(double eps) {
  if (!(eps > 0.0 && eps <= 1.0)) throw std::domain_error("drag: porosity must be in (0, 1]");
}
void check_diameter(double d) {
  if (!(d > 0.0)) throw std::domain_error("drag: grain diameter must be > 0");
}
}  // namespace

double SeedResistance::a_star(double eps, double d) const {
  return p_.alpha * p_.kinematic_viscosity * (1.0 - eps) * (1.0 - eps) / (eps * eps * eps * d * d);
}

double SeedResistance::b_star(double eps, double d) const {
  return p_.beta * (1.0 - eps) / (eps * eps * eps * d);
}

double SeedResistance::reynolds(double eps, double speed, double d) const {
  return eps * eps * d * speed / p_.kinematic_viscosity;
}

double SeedResistance::c_star(double eps, double speed, double d) const {
  return 0.75 * wen_yu_drag_coefficient(reynolds(eps, speed, d)) * (1.0 - eps) /
         (std::pow(eps, p_.wen_yu_exponent) * d);
}

ResistanceCoefficients SeedResistance::ergun(double eps, double d) const {
  check_porosity(eps);
  check_diameter(d);
  return {a_star(eps, d) * eps, b_star(eps, d) * eps * eps};
}

ResistanceCoefficients SeedResistance::wen_yu(double eps, double speed, double d) const {
  check_porosity(eps);
  check_diameter(d);
  const double shape = 0.75 * (1.0 - eps) / (std::pow(eps, p_.wen_yu_exponent) * d);
  const double re = reynolds(eps, speed, d);
  if (re > 1000.0) return {0.0, shape * 0.44};
  // c* |v_r| = shape * C_d |v_r|; C_d |v_r| = (24 nu / (eps^2 d)) (1 + 0.15 Re^0.687) stays finite
  // as |v_r| -> 0, so the Stokes part goes to A and only the correction to B.
  const double stokes = shape * 24.0 * p_.kinematic_viscosity / (eps * eps * d);
  const double b = speed > 0.0 ? stokes * 0.15 * std::pow(re, 0.687) / speed : 0.0;
  return {stokes, b};
}

double SeedResistance::wen_yu_weight(double eps) const {
  if (!p_.blend) return eps >= p_.switch_porosity ? 1.0 : 0.0;
  const double s = (eps - (p_.switch_porosity - p_.blend_half_width)) / (2.0 * p_.blend_half_width);
  return std::min(1.0, std::max(0.0, s));
}

ResistanceCoefficients SeedResistance::coefficients(double eps, double speed, double d) const {
  check_porosity(eps);
  if (!(speed >= 0.0)) throw std::domain_error("drag: relative speed must be >= 0");
  const double w = wen_yu_weight(eps);
  if (w <= 0.0) return ergun(eps, d);
  if (w >= 1.0) return wen_yu(eps, speed, d);
  const ResistanceCoefficients e = ergun(eps, d);
  const ResistanceCoefficients y = wen_yu(eps, speed, d);
  return {(1.0 - w) * e.linear + w * y.linear, (1.0 - w) * e.quadratic + w * y.quadratic};
}

}  // namespace isphdem
