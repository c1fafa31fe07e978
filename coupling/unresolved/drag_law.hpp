#pragma once
// Fluid–grain resistance of the unresolved coupling (seed Eqs. (3)–(8); docs/unresolved.md).
//
// Conventions, fixed here because the seed leaves them implicit:
//  * v_r = v_f - v_s is the INTERSTITIAL relative velocity (v_f = v_D / eps, v_D the Darcy
//    velocity the ISPH particles carry). With this reading the seed's a* eps v_r + b* eps^2 |v_r|
//    v_r equals a* U + b* U^2 for a fixed bed with Darcy velocity U, i.e. exactly Ergun's -dp/dz =
//    rho (a* U + b* U^2).
//  * F_r* is a force per unit FLUID mass [m/s^2], the term of the momentum equation (2) written
//    per unit mass of the fluid phase: the force on the fluid in a bulk volume V is
//    eps rho_f V F_r*. It always opposes v_r (the seed's Eq. (6) prints a sign that would not).
//  * Every law is reduced to F_r* = -(A + B |v_r|) v_r so that the solver can treat the term
//    (semi-)implicitly with one scalar coefficient A + B |v_r| per particle.
//  * The grain diameter is an argument, not a constant of the law: the coupling passes each
//    fluid particle's local Sauter mean of the grains its kernel sees (porosity_map.hpp), so a
//    graded soil is dragged by its own sizes. The parameters' grain_diameter is only the
//    default of the two-argument calls (tests, plots).
#include <string>

namespace isphdem {

struct ResistanceCoefficients {
  double linear = 0.0;     // A [1/s]
  double quadratic = 0.0;  // B [1/m]
  // The scalar K with F_r* = -K v_r at the speed the coefficients were evaluated for.
  double total(double relative_speed) const { return linear + quadratic * relative_speed; }
};

class DragLaw {
 public:
  virtual ~DragLaw() = default;
  // porosity in (0, 1], relative_speed = |v_r| >= 0 (interstitial), diameter > 0 [m].
  virtual ResistanceCoefficients coefficients(double porosity, double relative_speed,
                                              double diameter) const = 0;
  virtual std::string name() const = 0;
};

// Wen–Yu standard drag coefficient of a sphere (seed Eq. (7)).
double wen_yu_drag_coefficient(double reynolds);

struct SeedResistanceParameters {
  double grain_diameter = 1e-3;       // d_s [m] of the calls that give none
  double kinematic_viscosity = 1e-6;  // nu_f [m^2/s]
  double alpha = 150.0;               // Ergun viscous constant
  double beta = 1.75;                 // Ergun inertial constant
  double switch_porosity = 0.8;       // Ergun below, Wen–Yu above
  double wen_yu_exponent = 2.7;       // seed's value (Wen & Yu's own is 2.65)
  bool blend = false;                 // false: the seed's hard switch
  double blend_half_width = 0.05;     // linear ramp over [switch - w, switch + w]
};

// The seed's law: Ergun (Akbari & Namin) for eps < 0.8, Wen–Yu for eps >= 0.8, optionally
// blended linearly across the switch because the two branches jump there (about 10% in the
// Stokes limit with the seed's Reynolds number) and a jump in the drag makes the resistance of a
// fluidising bed depend on which side of 0.8 a particle's porosity happens to fall.
class SeedResistance final : public DragLaw {
 public:
  explicit SeedResistance(const SeedResistanceParameters& p);  // throws on bad parameters

  ResistanceCoefficients coefficients(double porosity, double relative_speed,
                                      double diameter) const override;
  // At the parameters' grain_diameter.
  ResistanceCoefficients coefficients(double porosity, double relative_speed) const {
    return coefficients(porosity, relative_speed, p_.grain_diameter);
  }
  std::string name() const override { return "seed"; }

  // The branches on their own, for tests and plots; both valid for any porosity in (0, 1].
  // Without a diameter they take the parameters' grain_diameter.
  ResistanceCoefficients ergun(double porosity) const { return ergun(porosity, p_.grain_diameter); }
  ResistanceCoefficients ergun(double porosity, double diameter) const;
  ResistanceCoefficients wen_yu(double porosity, double relative_speed) const {
    return wen_yu(porosity, relative_speed, p_.grain_diameter);
  }
  ResistanceCoefficients wen_yu(double porosity, double relative_speed, double diameter) const;
  // a*(eps) [1/s] and b*(eps) [1/m] of Eqs. (4)–(5), c*(eps, Re) of Eq. (6) with the sign fixed.
  double a_star(double porosity) const { return a_star(porosity, p_.grain_diameter); }
  double a_star(double porosity, double diameter) const;
  double b_star(double porosity) const { return b_star(porosity, p_.grain_diameter); }
  double b_star(double porosity, double diameter) const;
  double c_star(double porosity, double relative_speed) const {
    return c_star(porosity, relative_speed, p_.grain_diameter);
  }
  double c_star(double porosity, double relative_speed, double diameter) const;
  // Eq. (8): Re = eps_hat rho d eps |v_r| / mu = eps^2 d |v_r| / nu (the apparent density
  // eps rho brings one eps, the seed's explicit eps a second; standard Wen–Yu has only one).
  double reynolds(double porosity, double relative_speed) const {
    return reynolds(porosity, relative_speed, p_.grain_diameter);
  }
  double reynolds(double porosity, double relative_speed, double diameter) const;
  // Weight of the Wen–Yu branch: 0 or 1 for the hard switch, the linear ramp when blending.
  double wen_yu_weight(double porosity) const;

  const SeedResistanceParameters& parameters() const { return p_; }

 private:
  SeedResistanceParameters p_;
};

}  // namespace isphdem
