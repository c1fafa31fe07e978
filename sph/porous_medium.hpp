#pragma once
// Porous terms of the unified Darcy-Brinkman equations (seed Eqs. (1)-(2)). Particles carry the
// Darcy velocity v_D = eps v_f; per particle the coupling sets the porosity eps, the solid
// velocity v_s and the resistance coefficient K [1/s] of F_r* = -K (v_D/eps - v_s) before the
// step (sph/ knows no drag law: K comes as data). Dividing Eq. (2) by C_r/eps,
//   dv_D/dt = (eps/C_r)(-grad p/rho + g + nu_E lap v_D) - (K/C_r)(v_D - eps v_s),
// with the resistance implicit (it is stiff where eps is small):
//   predictor  u* = (v_D + dt (eps/C_r)(nu_E lap v_D + g) + dt (K/C_r) eps v_s) / (1 + dt K/C_r)
//   corrector  v_D = u* - dt (c/rho) grad p,   c = eps / (C_r (1 + dt K/C_r))
//   PPE        div(c grad p) = rho/dt div u* (+ the density-invariance term),
// the variable coefficient taken per pair as the harmonic mean of c_i and c_j (flux continuity
// across a jump of c, as for conductivities in Cleary & Monaghan 1999). Brinkman viscosity
// nu_E = (nu + nu_T)/eps: Eq. (2) is written per unit fluid mass for the interstitial velocity
// v_f = v_D/eps, whose viscous term nu lap v_f is (nu/eps) lap v_D for slowly varying eps (Nield
// & Bejan's mu/eps); it tends to nu in clear fluid, so the two regions join without a switch.
// Particles move with v_D: its divergence vanishes, so the particle set keeps its uniform
// number density through the bed; moving them with v_D/eps would pile them up where eps drops.
//
// With eps = 1 and K = 0 everywhere every factor is exactly 1 or 0, and the solver keeps its
// clear-fluid code path (active() false): results stay bit-identical.
#include <vector>

#include "neighbors.hpp"
#include "particles.hpp"
#include "row_share.hpp"

namespace isph {

// Virtual-mass coefficient C_r(eps) = 1 + 0.34 (1 - eps)/eps of Eq. (2).
inline double virtual_mass_coefficient(double porosity) {
  return 1.0 + 0.34 * (1.0 - porosity) / porosity;
}

template <int Dim>
class PorousMedium {
 public:
  // Checks eps and K, decides whether any porous term acts and computes c per particle (walls:
  // the Shepard average over fluid neighbours, so that their u* and their pairs in the PPE match
  // the fluid beside them). Throws std::invalid_argument naming the particle on bad data.
  // share: the rows are shared between processes (sph/row_share.hpp), the coefficients are
  // exchanged once computed.
  void prepare(const Particles<Dim>& P, const Neighbors<Dim>& nb, double dt,
               const RowShare* share = nullptr);

  bool active() const { return active_; }
  // c_i (dimensionless; the PPE coefficient is c_i/rho).
  const std::vector<double>& pressure_coefficient() const { return coefficient_; }
  double pressure_coefficient(int i) const { return coefficient_[i]; }

  // u* of a fluid particle from its Laplacian of velocity, eddy viscosity and body acceleration.
  Vec<Dim> predict(const Particles<Dim>& P, int i, double dt, double nu, double nu_t,
                   const Vec<Dim>& laplacian_v, const Vec<Dim>& g) const;

 private:
  bool active_ = false;
  std::vector<double> coefficient_;
};

}  // namespace isph
