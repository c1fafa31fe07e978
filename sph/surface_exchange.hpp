#pragma once
// Particle exchange between the free-surface row and the row under it, for surfaces that a
// steady flow stretches or squeezes. In the upwelling of the circulation tank the top row is a
// single layer of p = 0 particles under the Lagrangian strain of a stagnation flow: it is
// stretched over the upwelling and squeezed where the flow turns down, and no particle joins or
// leaves it (docs/fluid.md). Tangential shifting cannot undo a strain whose speed vanishes at
// the stagnation point, and a second-row particle exposed by a gap that takes p = 0 there, two
// thirds of a spacing below the row, is kicked up. Here the exchange is made geometrically, as a
// remeshing of the top row, one particle moved per defect, so the count and the volume are kept:
//   gap:  two neighbouring surface particles more than `gap` spacings apart along the surface:
//         the nearest fluid particle below their midpoint (within `reach`) is moved to it and
//         takes the pair's mean velocity, if nothing else lies within `clearance` of it;
//   void: nothing within `clearance` of the point one spacing under a surface particle whose
//         nearest surface neighbour is closer than `squeeze` spacings: that particle is moved
//         down into the void (the squeezed row gives one up to the void under it).
// Positions are the current ones; the neighbour lists are those of this step (every candidate
// lies within 2 spacings of the particle whose list is read, inside the 2.6-spacing support).
#include <vector>

#include "domain.hpp"
#include "neighbors.hpp"
#include "particles.hpp"

namespace isph {

struct SurfaceExchangeParams {
  double gap = 1.5;  // surface pair farther apart than this (spacings) is a gap
  // A surface particle this close to another may fill a void below; below gap / 2, or a
  // particle just moved into a gap would be sent back into the void its donor left.
  double squeeze = 0.55;
  double clearance = 0.7;  // a point with no particle this close (spacings) is empty
  double reach = 1.3;      // farthest donor from a gap's midpoint (spacings)
};

struct SurfaceExchangeCount {
  int gaps_filled = 0;
  int voids_filled = 0;
};

template <int Dim>
SurfaceExchangeCount exchange_surface_particles(Particles<Dim>& particles, const Neighbors<Dim>& nb,
                                                const Domain<Dim>& domain, const Vec<Dim>& up,
                                                const SurfaceExchangeParams& params);

}  // namespace isph
