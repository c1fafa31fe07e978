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

// Stokes drag on each sphere of a simple cubic array at solid fraction phi, as a multiple K of
// the lone sphere's 3 pi mu d U (U the superficial velocity relative to the spheres):
// Hasimoto's series as extended by Sangani & Acrivos (1982),
// 1/K = 1 - 1.7601 phi^(1/3) + phi - 1.5593 phi^2 + 3.9799 phi^(8/3) - 3.0734 phi^(10/3).
// Within 0.1% of Zick & Homsy's exact values up to phi = 0.125 (2.008, 2.810, 4.292); a sphere
// settling in a periodic box of side L is such an array, phi = (pi/6) (d/L)^3, and sinks at
// v_Stokes / K. Refused above phi = 0.125.
double cubic_array_drag_factor(double phi);

}  // namespace isphdem
