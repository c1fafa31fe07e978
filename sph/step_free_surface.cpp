// Stage 2 of a step: number density, free-surface, dry-wall and dry-solid marks, and which
// particles have full kernel support (free_surface.hpp holds the criteria).
#include <algorithm>

#include "isph_solver.hpp"
#include "rigid_solids.hpp"

namespace isph {

template <int Dim>
void IsphSolver<Dim>::detect_free_surface() {
  number_density(nb_, number_density_);
  if (config_.surface.method != SurfaceDetection::NumberDensity)
    position_divergence(nb_, particles_.volume, divergence_r_);
  if (config_.free_surface) {
    mark_free_surface(particles_, number_density_, n0_, divergence_r_, config_.surface);
    mark_sparse_as_surface(
        particles_, nb_, 3 * Dim,
        static_cast<int>(0.6 * reference_neighbor_count(kernel_, particles_.spacing)));
    if (config_.surface.scan) {
      // Before the first solve every pressure is zero and a roof would read as dry.
      if (steps_ > 0)
        mark_dry_walls(particles_, nb_, config_.gravity, config_.density, dry_wall_);
      else
        dry_wall_.assign(particles_.size(), 0);
      const bool gravity = config_.gravity.squaredNorm() > 0.0;
      const Vec<Dim> up = gravity ? Vec<Dim>(-config_.gravity.normalized()) : Vec<Dim>::Zero();
      exchange(dry_wall_);  // the scan ignores dry neighbours
      mark_open_side_as_surface(particles_, nb_, &dry_wall_, gravity ? &up : nullptr);
    }
    if (remeshes()) confine_surface_to_remeshed_rows();
  } else
    std::fill(particles_.surface.begin(), particles_.surface.end(), 0);
  if (config_.free_surface && has_solids())
    mark_dry_solids(particles_, nb_, config_.gravity, block_share());
  exchange(particles_.surface);
  surface_depth_.clear();
  if (config_.free_surface && config_.surface_refill && config_.gravity.squaredNorm() > 0.0)
    surface_depth(particles_, nb_, Vec<Dim>(-config_.gravity.normalized()), surface_depth_);
}

// Under a surface remesh the free surface is, by construction, the remeshed top row (it moves by
// micrometres between remeshes). Fluid deeper down with a thin support is not open to the air: in
// the semi-resolved erosion run, fluid in the pores between moving PMS particles read as surface
// (up to 30 particles at 15 mm depth), took p = 0, and jets of 0.4 m/s (76 v_in) ran through the
// layer from its first 0.05 s. The second row stays eligible so that a gap in the top row is
// still closed by a surface mark beneath it.
template <int Dim>
void IsphSolver<Dim>::confine_surface_to_remeshed_rows() {
  auto& P = particles_;
  const Vec<Dim> up = -config_.gravity.normalized();
  const double lowest = surface_top_ - 1.5 * P.spacing;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.surface[i] && up.dot(P.x[i]) < lowest) P.surface[i] = 0;
}

template <int Dim>
void IsphSolver<Dim>::mark_full_support() {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  // Particles whose whole support lies inside the fluid. Near the free surface the kernel is
  // truncated: the number-density deficit there is geometry, not compression, so neither the
  // density-invariance term nor shifting may act on it.
  full_support_.assign(n, 0);
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    if (P.kind[i] == kWall || P.surface[i]) continue;
    bool near_surface = false;
    for (int k = nb_.begin(i); k < nb_.end(i) && !near_surface; ++k)
      near_surface = P.surface[nb_.index[k]];
    full_support_[i] = !near_surface;
  }
}

template void IsphSolver<2>::detect_free_surface();
template void IsphSolver<2>::mark_full_support();
template void IsphSolver<2>::confine_surface_to_remeshed_rows();
template void IsphSolver<3>::detect_free_surface();
template void IsphSolver<3>::mark_full_support();
template void IsphSolver<3>::confine_surface_to_remeshed_rows();

}  // namespace isph
