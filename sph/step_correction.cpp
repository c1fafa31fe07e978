// Stage 5 of a step: the corrector u = u* - dt/rho0 grad p (the pump's and PMS solids' rows
// apart), then advection with the wall constraint.
#include <algorithm>

#include "isph_solver.hpp"
#include "rigid_solids.hpp"

namespace isph {

namespace {

// Closest approach of two fluid particles, in spacings (see separate_close_pairs). 0.5 held the
// dam-break toe, but not a disturbed surface at small steps: next to the surface nothing else
// keeps particles apart (no density term, tangential shifting), pairs closed to 0.5-0.7 dx there
// (39 pairs under 0.7 dx after 0.3 s at dt = 5e-5 s, 12 at 5e-4 s), and their pressure rows
// carried alternating pressures of +-500 Pa under a 30 Pa head that threw water out of the tank
// (docs/fluid.md, "A disturbed free surface at small dt"). 0.6 still failed, 0.7 and 0.8 held.
constexpr double kMinPairDistance = 0.8;

}  // namespace

template <int Dim>
void IsphSolver<Dim>::correct(double dt) {
  auto& P = particles_;
  const double rho0 = config_.density;
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    if (P.kind[i] == kWall) continue;
    if (P.kind[i] == kForcing) {  // the pump: the zone velocity whatever the pressure
      P.v[i] = zone_of(P.x[i])->velocity_at(time_ + dt);
      continue;
    }
    if (P.kind[i] == kSolid) {  // PMS: the fluid's momentum change goes to the body
      const Vec<Dim>& u_star = config_.pms_pressure_increment ? pms_u_star_[i] : u_star_[i];
      P.solid_force[i] = pms_force(P, nb_, op_, i, rho0, dt, u_star, config_.gravity);
      continue;
    }
    P.v[i] = u_star_[i] - dt * porous_.pressure_coefficient(i) / rho0 * gradient(nb_, op_, P.p, i);
  }
  exchange(P.v);
  // With shared rows the pocket blend adds to every row's; decomposed, to the owned rows' only,
  // and the loads are summed over those.
  if (!decomposition_ && has_solids()) exchange(P.solid_force);
}

template <int Dim>
std::vector<Vec<Dim>> IsphSolver<Dim>::pressure_gradient_at(const std::vector<int>& rows) const {
  std::vector<Vec<Dim>> g(rows.size(), Vec<Dim>::Zero());
  if (decomposition_) {  // the step's neighbour lists reached into a halo dropped since
    for (std::size_t r = 0; r < rows.size(); ++r) g[r] = grad_p_.at(rows[r]);
    return g;
  }
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r] >= first_ && rows[r] < last_) g[r] = gradient(nb_, op_, particles_.p, rows[r]);
  // One process contributes each row, the others zero: the sum is exact.
  if (blocked_ && !g.empty()) share_->sum_in_place(g[0].data(), Dim * g.size());
  return g;
}

template <int Dim>
void IsphSolver<Dim>::advect(double dt, StepStats& stats) {
  auto& P = particles_;
  if (config_.free_surface)
    separate_close_pairs(P, nb_, domain_, dt, kMinPairDistance * P.spacing, shift_, block_share());
  double vmax = 0.0, surface = 0.0, volume = 0.0;
  shift_sum_.setZero();
  for (int i = first_; i < last_; ++i) {
    if (P.kind[i] == kWall || P.kind[i] == kSolid) continue;  // solids: placed by their body
    P.x[i] += dt * P.v[i] + shift_[i];
    if (P.kind[i] == kFluid) shift_sum_ += shift_[i];
    keep_off_walls(i);
    domain_.wrap(P.x[i]);
    vmax = std::max(vmax, P.v[i].norm());
    surface += P.surface[i];
    volume += P.volume * (full_support_[i] ? n0_ / number_density_[i] : 1.0);
  }
  if (!decomposition_) {  // the decomposed step drops its halo next
    exchange(P.x);
    exchange(P.v);
  }
  if (blocked_ && !decomposition_) share_->sum_in_place(shift_sum_.data(), Dim);
  if (blocked_) {
    vmax = share_->max(vmax);
    surface = share_->sum(surface);
    volume = share_->sum(volume);
  }
  stats.surface_particles = static_cast<std::size_t>(surface);
  stats.fluid_volume = volume;
  stats.max_speed = vmax;
  stats.max_eddy_viscosity = max_eddy_viscosity_;
}

template <int Dim>
void IsphSolver<Dim>::keep_off_walls(int i) {
  // Nothing in the pressure equation reacts to a position error, so a particle driven fast along
  // a wall (the toe of a dam break) can creep into it and then blow up among the wall
  // particles. Walls with known geometry therefore act as a kinematic constraint: a fluid
  // particle closer than `min_wall_distance` to the wall surface of a neighbouring wall particle
  // is put back at that distance and loses its velocity into the wall.
  auto& P = particles_;
  const double min_dist = config_.min_wall_distance * P.spacing;
  for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
    const int w = nb_.index[k];
    if (P.kind[w] != kWall || P.normal[w].squaredNorm() == 0.0) continue;
    const Vec<Dim>& nrm = P.normal[w];
    // Only walls whose surface patch is beside the particle (not a neighbouring face at a corner).
    const Vec<Dim> d = domain_.min_image(P.x[i] - P.x[w]);
    const Vec<Dim> tangential = d - d.dot(nrm) * nrm;
    if (tangential.norm() > 0.5 * P.spacing) continue;
    const double gap = d.dot(nrm) - P.wall_distance[w];
    if (gap >= min_dist) continue;
    P.x[i] += (min_dist - gap) * nrm;
    const double vn = P.v[i].dot(nrm) - P.v[w].dot(nrm);
    if (vn < 0.0) P.v[i] -= vn * nrm;
  }
}

template std::vector<Vec<2>> IsphSolver<2>::pressure_gradient_at(const std::vector<int>&) const;
template std::vector<Vec<3>> IsphSolver<3>::pressure_gradient_at(const std::vector<int>&) const;
template void IsphSolver<2>::correct(double);
template void IsphSolver<2>::advect(double, StepStats&);
template void IsphSolver<2>::keep_off_walls(int);
template void IsphSolver<3>::correct(double);
template void IsphSolver<3>::advect(double, StepStats&);
template void IsphSolver<3>::keep_off_walls(int);

}  // namespace isph
