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
  bool scan = false;           // also mark_open_side_as_surface (below)
  bool unstable_rows = true;   // also mark_unstable_projection_rows (projection_stability.hpp)
};

SurfaceDetection surface_detection_from_name(const std::string& name);

template <int Dim>
void position_divergence(const Neighbors<Dim>& nb, double volume, std::vector<double>& div);

// Sets particles.surface for non-wall particles; walls never carry the surface flag. `div` is
// only read when the criteria use it.
template <int Dim>
void mark_free_surface(Particles<Dim>& particles, const std::vector<double>& n, double n0,
                       const std::vector<double>& div, const SurfaceCriteria& criteria);

// Walls count as support in the number density, and a close pair adds a large kernel value, so
// a sheet one or two particles thick running along a floor (the toe of a dam-break surge), or a
// clustered splash, reads as nearly full and was not flagged: its rows then carried pressures of
// 1e4-1e5 Pa where the head is a few pascals. A particle is therefore marked as surface too when
// it has fewer than `min_fluid` non-wall neighbours or fewer than `min_all` neighbours of any
// kind. A particle in a two-wall corner of a full tank has 7 fluid neighbours in 2D and a full
// count with its walls, so neither test touches it.
template <int Dim>
void mark_sparse_as_surface(Particles<Dim>& particles, const Neighbors<Dim>& nb, int min_fluid,
                            int min_all);

// A top row squeezed together by converging flow reads as full by number density and by div r,
// and a particle of it that takes more pressure than the row below dives (the circulation tank
// broke up that way). Scan test, a simple form of Marrone et al. (2010): with n a unit direction
// out of the water, a particle is on the surface when no neighbour j lies within one spacing of
// x_i + dx n and within 60 degrees of n as seen from x_i. The cone leaves out the neighbours
// beside i in a squeezed row (Marrone's 45-degree umbrella of height h = 1.3 dx was tried and
// also marked the lower row of a staggered top layer, two p = 0 rows 0.66 dx apart, which lifted
// it). n is `up` (against gravity) when given: next to a wall, and in a top layer whose rows are
// staggered by diverging surface flow, -sum_j grad W_ij tilts by 30 degrees and more, and a row
// was then marked or missed by that tilt alone. Without `up`, n is along -sum_j grad W_ij
// (towards the emptier side). Walls flagged in `dry` (mark_dry_walls) take no part: a wall rising
// above the water covers the contact-line particle, which, read as interior with a one-sided
// support, was pulled down into the corner in the circulation tank.
template <int Dim>
void mark_open_side_as_surface(Particles<Dim>& particles, const Neighbors<Dim>& nb,
                               const std::vector<uint8_t>* dry = nullptr,
                               const Vec<Dim>* up = nullptr);

// Wall particles in the air. The Adami extrapolation p_w = <p_f + rho g.(x_w - x_f)> over the
// fluid neighbours (with the last solved fluid pressures) continues the hydrostatic field up past
// the water line, so it is negative for a wall above the water; a wall is flagged dry when that
// value is negative and it sits above its fluid neighbours' centroid by more than dx/4 along -g.
// The bottom of a submerged wall (the inner walls' lower ends) extrapolates a positive pressure.
// Only the surface scan uses the flag: the pressure rows keep the extrapolation, whose negative
// values are what balances the top row's hydrostatics next to the wall (p = 0 sits on the top
// particle row, half a spacing below the water line).
template <int Dim>
void mark_dry_walls(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                    const Vec<Dim>& gravity, double rho0, std::vector<uint8_t>& dry);

// How far each free-surface particle sits below the surface its surface neighbours outline: the
// kernel-weighted mean of up.(x_j - x_i) over free-surface fluid neighbours j, clamped at zero
// (0 for every other particle). On a straight surface row, level or sloping, it is zero; a
// particle of the second row exposed by a gap in a stretched top row (the upwelling of the
// circulation tank) reads its depth under the row, 0.4-0.7 dx.
template <int Dim>
void surface_depth(const Particles<Dim>& particles, const Neighbors<Dim>& nb, const Vec<Dim>& up,
                   std::vector<double>& depth);

// Neighbours of an interior particle of a perfect lattice of spacing dx (20 in 2D at h = 1.3 dx).
template <int Dim>
int reference_neighbor_count(const Kernel<Dim>& kernel, double dx);

}  // namespace isph
