#pragma once
// The velocity an unresolved grain's own drag induces where the coupling samples the fluid for
// it (docs/unresolved.md, "A lone grain's own wake").
//
// The coupling spreads a grain's reaction over its porosity kernel W and reads the fluid's
// velocity for the grain's drag over the same kernel. In a linearised fluid the reaction F
// drags the sampled velocity along by u_self = F / (6 pi mu) * I, with
//   I = <G(x - y)>_{W(x) W(y)} * 6 pi mu = (3 / 2pi) int_0^inf w(q)^2 q^2/(q^2 + L^-2) g(a) dq,
// w(q) the kernel's Fourier transform, L the Brinkman screening length of the other grains'
// resistance around it (infinite for a lone grain), and g(a) = int_-1^1 (1 - c^2)/(1 + a^2 c^2) dc
// the Oseen factor of the slip U at a = U q / (nu (q^2 + L^-2)): the regularised Stokeslet,
// screened and advected, as Evrard, Denner & van Wachem (2020) and Chandran, Evrard & van Wachem
// (2025) form it for grid codes. In the Stokes limit I is <1/|x - y|> over two independent
// draws from W: 0.826 / dx for the Wendland C2 kernel at h = 1.3 dx. Drag laws for a lone sphere
// are written for the velocity without that disturbance; the coupling recovers it.
//
// 3D only: a 2D fluid's disturbance of a line force has no finite Stokes limit.
#include <cmath>
#include <vector>

#include "kernel.hpp"

namespace isphdem {

class SelfInducedVelocity {
 public:
  // The porosity kernel's shape and the fluid's kinematic viscosity [m^2/s]. Tabulates I h over
  // the slip's and the screening's dimensionless ranges, for every smoothing length h.
  SelfInducedVelocity(isph::KernelType kernel, double kinematic_viscosity);

  // I [1/m] of a kernel of smoothing length h > 0 [m] at slip speed U >= 0 [m/s] and screening
  // length L > 0 [m] (infinity: none).
  double inverse_radius(double slip_speed, double screening_length, double h) const;
  // The Stokes limit, U = 0 and no screening.
  double stokes_inverse_radius(double h) const { return std::exp(table_.front()) / h; }

 private:
  double table_value(double oseen, double screening) const;  // I h at U h / nu and h / L

  double nu_;
  // log(I h) on [oseen][screening], log1p-spaced axes: I falls as a power of both far out.
  std::vector<double> table_;
};

}  // namespace isphdem
