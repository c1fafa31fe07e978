#pragma once
// Free-surface detection by the kernel number density: a particle whose number density falls
// below `threshold` times that of a full support is on the surface and gets p = 0.
#include <vector>

#include "neighbors.hpp"

namespace isph {

// sum_j W_ij including the particle itself, over all kinds (walls count as support).
template <int Dim>
void number_density(const Neighbors<Dim>& nb, std::vector<double>& n);

// Number density of an interior particle of a perfect lattice of spacing dx.
template <int Dim>
double reference_number_density(const Kernel<Dim>& kernel, double dx);

// Sets particles.surface for non-wall particles; walls never carry the surface flag.
template <int Dim>
void mark_free_surface(Particles<Dim>& particles, const std::vector<double>& n, double n0,
                       double threshold);

}  // namespace isph
