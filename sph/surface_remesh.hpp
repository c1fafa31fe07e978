#pragma once
// Remeshing of the top rows of a nearly flat free surface. Over an upwelling the surface flow is
// a stagnation-point flow whose Lagrangian strain stretches the top particle rows without end
// and squeezes them where the flow dives at the walls; no particle joins or leaves the top row,
// and the layer breaks up within a second (docs/fluid.md, "Known limitations"). Remeshed SPH
// (Chaniotis, Poulikakos & Koumoutsakos 2002) resets the particles to a lattice every few steps
// and interpolates the fields onto it, so that the strain never accumulates. Here only the top
// `rows` x (number of columns) fluid particles are remeshed, onto the columns of the surface's
// initial lattice, at the same mean height (count, volume and the zone's potential energy stay);
// the surface is flat at every remesh, which holds where its deflection is far below dx (Froude
// number U^2 / g H << dx / H).
#include <vector>

#include "kernel.hpp"
#include "particles.hpp"
#include "row_share.hpp"

namespace isph {

// The largest height along `up` of a fluid particle (-infinity without fluid).
template <int Dim>
double highest_fluid(const Particles<Dim>& particles, const Vec<Dim>& up);

// The tangential positions (along the surface, height along `up` taken out) of the fluid
// particles within half a spacing of the highest one: the columns of the surface's lattice.
template <int Dim>
std::vector<Vec<Dim>> surface_columns(const Particles<Dim>& particles, const Vec<Dim>& up);

// Moves the rows x columns highest fluid particles onto the lattice of `columns` with rows one
// spacing apart under a top row, at their present mean height, and sets their velocity, pressure
// and porosity to the Shepard interpolation of the fluid's values before the move. Returns the
// height of the new top row along `up`.
template <int Dim>
double remesh_surface_rows(Particles<Dim>& particles, const Kernel<Dim>& kernel, const Vec<Dim>& up,
                           const std::vector<Vec<Dim>>& columns, int rows);

// The same over processes that each hold a part of the fluid (collective): the fluid near the
// top, deep enough for the rows and the fluid they interpolate from, is gathered from every
// process in the order of the particles' ids, every process remeshes it alike, and each takes
// the new values of its own particles. The result is one process's up to the order of the
// interpolation's sums. `columns` are the whole surface's (surface_columns_shared).
template <int Dim>
double remesh_surface_rows_shared(Particles<Dim>& particles, const Kernel<Dim>& kernel,
                                  const Vec<Dim>& up, const std::vector<Vec<Dim>>& columns,
                                  int rows, const RowShare& share);

// surface_columns and highest_fluid over all processes' particles (collective).
template <int Dim>
std::vector<Vec<Dim>> surface_columns_shared(const Particles<Dim>& particles, const Vec<Dim>& up,
                                             const RowShare& share);

}  // namespace isph
