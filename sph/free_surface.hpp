#pragma once
// Free-surface detection. A particle is on the surface (and gets p = 0) when its kernel number
// density falls below a fraction of a full support's, or when the divergence of position,
// div r = -sum_j V_j r_ij . grad W_ij, which is Dim inside the fluid, falls below a threshold
// (Lee et al. 2008: 1.5 in 2D, 2.4 in 3D), or either.
#include <string>
#include <vector>

#include "neighbors.hpp"

namespace isph {

// sum_j W_ij including the particle itself, over all kinds (walls count as support).
template <int Dim>
void number_density(const Neighbors<Dim>& nb, std::vector<double>& n);

// Number density of an interior particle of a perfect lattice of spacing dx.
template <int Dim>
double reference_number_density(const Kernel<Dim>& kernel, double dx);

enum class SurfaceDetection { NumberDensity, Divergence, Either };

struct SurfaceCriteria {
  SurfaceDetection method = SurfaceDetection::NumberDensity;
  double density_ratio = 0.9;  // n_i / n0 below this: surface
  double divergence = 0.0;     // div r below this: surface (0: 1.5 in 2D, 2.4 in 3D)
};

SurfaceDetection surface_detection_from_name(const std::string& name);

template <int Dim>
void position_divergence(const Neighbors<Dim>& nb, double volume, std::vector<double>& div);

// Sets particles.surface for non-wall particles; walls never carry the surface flag. `div` is
// only read when the criteria use it.
template <int Dim>
void mark_free_surface(Particles<Dim>& particles, const std::vector<double>& n, double n0,
                       const std::vector<double>& div, const SurfaceCriteria& criteria);

}  // namespace isph
