#pragma once
// A layer of ghost particles above the free surface (after Nair & Tomar 2014). Without it every
// particle within a kernel of the surface has a truncated support: its number-density deficit is
// geometry, so the density-invariance term cannot act there, shifting is tangential only, and a
// top row stretched by an upwelling is refilled by nothing (docs/fluid.md, the circulation tank).
// The ghosts complete the support for one step: they continue each surface particle's column
// upwards, carry its velocity (zero normal gradient, the stress-free surface), and take as a
// Dirichlet value the pressure that puts p = 0 on the surface line half a spacing above the top
// row. The top row then becomes an ordinary pressure row.
#include <cstddef>
#include <vector>

#include "domain.hpp"
#include "neighbors.hpp"
#include "operators.hpp"

namespace isph {

template <int Dim>
struct SurfaceGhosts {
  std::size_t real = 0;            // particles before the ghosts were appended
  std::vector<int> parent;         // per ghost: the surface particle it continues
  std::vector<Vec<Dim>> x;         // per ghost: position
  std::vector<double> pressure;    // per ghost: Dirichlet value [Pa]
  std::vector<Vec<Dim>> dv;        // per ghost: its velocity minus its parent's
  std::vector<uint8_t> has_ghost;  // per real particle: 1 where a column was placed above it
  std::vector<Vec<Dim>> normal;    // per real particle: the column's direction (zero: none)
};

// Places columns of `layers` ghosts at x_i + k dx n_i (k = 1..layers) above every free-surface
// fluid particle i, with n_i the unit vector along -sum_j grad W_ij (out of the water, tilted
// away from walls beside it). A spot within `clearance` of another particle (a wall rising above
// the water, an overhang) gets no ghost, and neither does one outside a closed box side. The
// Dirichlet value is rho0 g.(x_g - x_line) with x_line = x_i + dx/2 n_i: the hydrostatic
// pressure continued past the water line, so that p = 0 lies on it.
template <int Dim>
void place_surface_ghosts(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                          const Domain<Dim>& domain, int layers, double clearance,
                          const Vec<Dim>& gravity, double rho0, SurfaceGhosts<Dim>& out);

// Appends the ghosts as particles of kind kGhost (Dirichlet rows, surface = 1) after the real
// ones, with their parents' velocity and porosity; parents with a column lose the surface mark.
template <int Dim>
void append_surface_ghosts(const SurfaceGhosts<Dim>& ghosts, Particles<Dim>& particles);

// Drops the ghosts again (they sit after `real`) and every pair that points at one, so that the
// neighbour list and operator weights stay valid for the real particles between steps.
template <int Dim>
void remove_surface_ghosts(std::size_t real, Particles<Dim>& particles, Neighbors<Dim>& nb,
                           Operators<Dim>& op);

}  // namespace isph
