#pragma once
// Whether a particle's pressure row can project its own divergence away, or amplifies it.
//
// The approximate projection solves L p = (rho/dt) D u* with the Laplacian L, then corrects
// u = u* - (dt/rho) G p with the gradient G; D G is not L. For one particle i, the divergence left
// after the step is the divergence before times 1 - (DG)_ii / L_ii, where
//   L_ii  = -sum_j b_ij,
//   (DG)_ii = -(dt/rho)^-1 d(D u_i)/d p_i = sum_j a_ij . a_ji + |sum_j a_ij|^2
// (a_ij, b_ij the operator weights). On a full support sum_j a_ij = 0 and the ratio is positive
// (0.10-0.15 on a 2D lattice: the wide D G stencil against the compact Laplacian), so every step
// damps the divergence. On a one-sided support that the surface tests read as interior (a top row
// squeezed along the surface, a kink in a disturbed surface) |sum_j a_ij|^2 dominates, the ratio
// turns negative and the particle's divergence - and its pressure - grows by |1 - ratio| every
// step: -378, -679, -1212, -2090 Pa in four steps under a 30 Pa head in a disturbed tank at
// dx = 2 mm (docs/fluid.md, "A disturbed free surface at small dt"). Such a row is a surface row
// in all but name and takes p = 0.
#include <cstdint>
#include <vector>

#include "neighbors.hpp"
#include "operators.hpp"
#include "particles.hpp"

namespace isph {

// The stability limit itself: a row whose ratio is not above 0 does not damp its divergence.
// Lattice rows read 0.10-0.15 in 2D and 0.06-0.08 in 3D; a top-row particle read as interior reads
// -0.20 (-0.08 squeezed to 0.67 dx): tests/sph/test_projection_stability.cpp.
constexpr double kMinProjectionRatio = 0.0;

// (DG)_ii / L_ii for particle i, with walls held and a_ji = -a_ij (see the .cpp). Neighbours
// whose velocity the pressure does not correct (walls, solid particles, the forcing zone) give no
// a_ji term.
template <int Dim>
double projection_self_ratio(const Particles<Dim>& P, const Neighbors<Dim>& nb,
                             const Operators<Dim>& op, int i);

// Marks as free surface every fluid particle in [first, last) that is not surface yet, has a
// surface neighbour (the unstable rows sit next to the surface), and whose ratio lies outside
// [min_ratio, 2 - min_ratio]. Returns how many it marked.
template <int Dim>
int mark_unstable_projection_rows(Particles<Dim>& P, const Neighbors<Dim>& nb,
                                  const Operators<Dim>& op, int first, int last, double min_ratio);

}  // namespace isph
