// Stage 6 of a step: particle shifting (free inside the fluid, tangential at the free surface)
// and the limited Taylor correction of velocities to the shifted positions.
#include <algorithm>

#include "isph_solver.hpp"

namespace isph {

template <int Dim>
void IsphSolver<Dim>::shift(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  // Fluid with full support shifts freely; at and next to the free surface only tangentially.
  shift_mode_.resize(n);
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    // With surface_refill every particle that is not on the surface shifts freely: voids under
    // the top row (return flow beside the walls) are otherwise closed by nothing.
    const bool free_shift = full_support_[i] || (!surface_depth_.empty() && !P.surface[i]);
    shift_mode_[i] = P.kind[i] != kFluid ? 0 : (free_shift ? 2 : 1);
    // Shifting repairs disorder inside the fluid. A splash tip or a toe particle whose support
    // is mostly wall has no meaningful concentration gradient: its shift came out at the cap,
    // against the flow, and the Taylor correction turned that into a velocity kick every step.
    if (shift_mode_[i] == 1) {
      int nf = 0;
      for (int k = nb_.begin(i); k < nb_.end(i); ++k) nf += P.kind[nb_.index[k]] != kWall;
      if (nf < 3 * Dim) shift_mode_[i] = 0;
    }
  }
  compute_shifts(P, nb_, kernel_, config_.shifting, dt, shift_mode_, shift_, block_share());
  if (!surface_depth_.empty()) {
    // Lift exposed second-row particles onto the surface line (surface_refill).
    const Vec<Dim> up = -config_.gravity.normalized();
    const double cap = config_.shifting.max_fraction * P.spacing;
    for (int i = first_; i < last_; ++i) {
      if (P.kind[i] != kFluid || !(surface_depth_[i] > 0.0)) continue;
      // Only into a gap: nothing directly above within a column of half a spacing's radius.
      bool blocked = false;
      for (int k = nb_.begin(i); k < nb_.end(i) && !blocked; ++k) {
        if (P.kind[nb_.index[k]] == kWall) continue;
        const Vec<Dim> r = -nb_.rij[k];
        const double h = up.dot(r);
        blocked = h > 0.0 && h < 1.2 * P.spacing && (r - h * up).norm() < 0.6 * P.spacing;
      }
      if (blocked) continue;
      shift_[i] += std::min(surface_depth_[i], cap) * up;
      if (!shift_mode_[i]) shift_mode_[i] = 1;  // so that its velocity is Taylor-corrected
    }
  }
  // Taylor-correct velocities to the shifted positions (u_star_ reused as scratch), limited so
  // that no new extremum appears: each component stays within the range of the particle's own
  // and its fluid neighbours' values. On a truncated support (free surface, splash tip) the
  // gradient's own coefficient -sum_j G_ij does not vanish, so u_i + (grad u)_i . dr is
  // u_i (1 - dr . sum_j G_ij) + ...: whenever the shift has a component along -sum_j G_ij the
  // particle's velocity was amplified by a fixed factor in every step, and the shift itself
  // grows with |u|. Surface and toe particles ran away exponentially in the step count, which
  // is why a smaller dt failed earlier. The limiter is inactive in smooth interior flow.
  exchange(shift_);  // the separation of close pairs reads both particles' shifts
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    if (!shift_mode_[i]) {
      u_star_[i] = P.v[i];
      continue;
    }
    Vec<Dim> u = P.v[i] + gradient(nb_, op_, P.v, i) * shift_[i];
    Vec<Dim> lo = P.v[i], hi = P.v[i];
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P.kind[j] == kWall) continue;
      lo = lo.cwiseMin(P.v[j]);
      hi = hi.cwiseMax(P.v[j]);
    }
    u_star_[i] = u.cwiseMax(lo).cwiseMin(hi);
  }
  P.v.swap(u_star_);
  exchange(P.v);
}

template void IsphSolver<2>::shift(double);
template void IsphSolver<3>::shift(double);

}  // namespace isph
