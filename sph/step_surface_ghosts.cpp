// The ghost layer's place in a step (sph/surface_ghosts.hpp): appended after the free surface is
// marked, given its parents' u*, and dropped again before the step ends.
#include <cmath>
#include <cstdlib>

#include "isph_solver.hpp"
#include "stopwatch.hpp"

namespace isph {

namespace {

// Closest a ghost may come to another particle, in spacings: a wall rising above the water or a
// particle of a staggered top row already fills that spot.
constexpr double kGhostClearance = 0.75;

}  // namespace

template <int Dim>
void IsphSolver<Dim>::add_surface_ghosts() {
  auto& P = particles_;
  ghosts_.real = P.size();
  ghosts_.parent.clear();
  ghosts_.x.clear();
  ghosts_.pressure.clear();
  if (!config_.free_surface || !config_.surface_ghosts) return;
  // Layers up to the support radius: the top row's kernel reaches 2.6 dx above it.
  const int layers = static_cast<int>(std::floor(kernel_.support() / P.spacing + 1e-9));
  place_surface_ghosts(P, nb_, domain_, layers, kGhostClearance * P.spacing, config_.gravity,
                       config_.density, ghosts_);
  if (ghosts_.x.empty()) return;
  if (std::getenv("GHOST_EXTRAPOLATE")) {
    compute_operator_weights();
    for (std::size_t g = 0; g < ghosts_.x.size(); ++g) {
      const int i = ghosts_.parent[g];
      ghosts_.dv[g] = gradient(nb_, op_, P.v, i) * domain_.min_image(ghosts_.x[g] - P.x[i]);
    }
  }
  append_surface_ghosts(ghosts_, P);
  {
    // Not re-sorted: the real particles keep their indices, and the ghosts sit after them.
    Stopwatch w(timings_.neighbors);
    search_.build(P, kernel_, nb_);
  }
  number_density(nb_, number_density_);
  if (!surface_depth_.empty()) surface_depth_.resize(P.size(), 0.0);
}

template <int Dim>
void IsphSolver<Dim>::set_ghost_u_star() {
  for (std::size_t g = 0; g < ghosts_.x.size(); ++g)
    u_star_[ghosts_.real + g] = u_star_[ghosts_.parent[g]] + ghosts_.dv[g];
}

template <int Dim>
void IsphSolver<Dim>::remove_surface_ghosts() {
  if (particles_.size() == ghosts_.real) return;
  isph::remove_surface_ghosts(ghosts_.real, particles_, nb_, op_);
  if (!surface_depth_.empty()) surface_depth_.resize(ghosts_.real);
}

template void IsphSolver<2>::add_surface_ghosts();
template void IsphSolver<2>::set_ghost_u_star();
template void IsphSolver<2>::remove_surface_ghosts();
template void IsphSolver<3>::add_surface_ghosts();
template void IsphSolver<3>::set_ghost_u_star();
template void IsphSolver<3>::remove_surface_ghosts();

}  // namespace isph
