#pragma once
// Fickian particle shifting (Lind et al. 2012, with Skillen et al. 2013's velocity-scaled
// diffusion coefficient): particles drift down the gradient of the particle concentration so
// that the distribution stays near-uniform, which keeps the corrected operators well conditioned.
// Field values are corrected by a first-order Taylor step to the shifted position.
#include <vector>

#include "domain.hpp"
#include "operators.hpp"
#include "row_share.hpp"

namespace isph {

struct ShiftingParams {
  bool enabled = true;
  double coefficient =
      4.0;  // A in D = A h |u| dt (Skillen et al. 2013: 1-6; 4 tuned on Taylor-Green)
  double max_fraction = 0.2;  // |dr| <= max_fraction * dx
  double tensile_r = 0.2;     // anti-clumping term R (W_ij / W(dx))^4
};

// Returns the shift of every particle. mode[i]: 0 not shifted, 1 tangential only (at and near the
// free surface, where the concentration gradient points out of the fluid: its normal component
// would push particles off the surface; Lind et al. 2012, Khayyer et al. 2017), 2 full.
template <int Dim>
void compute_shifts(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                    const Kernel<Dim>& kernel, const ShiftingParams& params, double dt,
                    const std::vector<uint8_t>& mode, std::vector<Vec<Dim>>& shift,
                    const RowShare* share = nullptr);

// Keeps fluid particles at least `min_distance` apart at the end of the step (an inelastic
// collision, as in MPS: Lee et al. 2011). Shifting is tangential or off at and next to the free
// surface, so nothing else stops pairs from closing up in a thin sheet (the toe of a dam-break
// surge, where pairs 0.3-0.6 dx apart were seen). Such a pair makes the pressure rows stiff and
// the pressure there rose to 1e4-1e5 Pa against a head of 1e2 Pa, and the run broke up. For each
// pair that would end closer than min_distance, both displacements (dt v + shift) are moved
// apart symmetrically and the approaching part of the relative velocity is removed; momentum is
// conserved. It acts near the surface and at splashes, where pairs close up.
// Each particle takes its half of each of its close pairs, all computed from the state before the
// sweep: the same on one process, on shared rows (shift and v whole on every process after the
// call) and decomposed (owned rows corrected).
template <int Dim>
void separate_close_pairs(Particles<Dim>& particles, const Neighbors<Dim>& nb,
                          const Domain<Dim>& domain, double dt, double min_distance,
                          std::vector<Vec<Dim>>& shift, const RowShare* share = nullptr);

}  // namespace isph
