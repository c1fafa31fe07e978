#pragma once
// Analytic answers that [reference] metrics compare with, callable in their formulas
// (diagnostics_expression.hpp). Written from the textbook formulas, independently of the drag
// laws in coupling/unresolved/, so that a metric checks a law rather than repeating it. SI units;
// nu is the kinematic viscosity.
namespace isphdem {

// Stokes terminal velocity of a sphere: (rho_p - rho_f) g d^2 / (18 rho_f nu). Re << 1 only.
double stokes_velocity(double d, double rho_p, double rho_f, double nu, double g);

// Terminal velocity of a sphere with the Schiller-Naumann drag coefficient
// C_d = 24/Re (1 + 0.15 Re^0.687), Re = d v / nu: the v at which C_d (pi d^2/8) rho_f v^2 equals
// the buoyant weight (rho_p - rho_f) g pi d^3 / 6. Valid to Re ~ 1000.
double schiller_naumann_velocity(double d, double rho_p, double rho_f, double nu, double g);

// Ergun's pressure gradient through a packed bed of spheres of diameter d and porosity eps at
// superficial velocity U: 150 rho nu (1-eps)^2 U / (eps^3 d^2) + 1.75 rho (1-eps) U^2 / (eps^3 d).
double ergun_gradient(double eps, double d, double nu, double rho, double u);

}  // namespace isphdem
