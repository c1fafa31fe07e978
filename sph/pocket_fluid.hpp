#pragma once
// Fluid caught in a pocket between PMS solids moves with them.
//
// A fluid particle whose kernel support is mostly solid sits in a gap narrower than the
// resolution: between touching grains, or in the concave parts of a clump. The projection does
// not control its velocity there. The solid rows' corrections are discarded when the bodies are
// placed rigidly, and the next step's divergence error in the cage can only be corrected by
// moving the one free particle. In the semi-resolved erosion tank such particles picked up
// 0.2-1.5 m/s (10-75 v_in) while hardly moving, and every run broke up from one
// (docs/internal_erosion.md). As in the fictitious-domain velocity correction of resolved
// CFD-DEM (Shirgaonkar et al. 2009; CFDEMcoupling's IB solver, which sets u = a u_s + (1 - a) u_f
// in a cell of solid fraction a), the particle's velocity is blended towards the solids':
//     v <- v_s + (1 - s) (v - v_s),   s = clamp((phi - onset) / kPocketRamp, 0, 1),
// with phi the kernel-weighted solid share of its support (walls left out) and v_s the
// kernel-weighted velocity of its solid neighbours. Unlike the cell-based correction, it leaves
// the first fluid row along a flat or convex body alone (phi about 0.35 there, below the onset),
// so drag and buoyancy of single bodies are unchanged. The momentum the particle loses goes to
// those solid neighbours (solid_force, by weight), so the exchange conserves momentum.
#include "neighbors.hpp"
#include "particles.hpp"
#include "row_share.hpp"

namespace isph {

constexpr double kPocketRamp = 0.2;  // solid share over which the blend goes from 0 to 1

// Kernel-weighted share of solid (PMS) particles in i's support, walls left out; 0 without
// solid neighbours.
template <int Dim>
double solid_share(const Particles<Dim>& particles, const Neighbors<Dim>& nb, int i);

// Applies the blend to every fluid particle (kind kFluid) with a solid share above `onset`, after
// the corrector; adds the reaction to the solid neighbours' solid_force (N, per unit depth in
// 2D, for a step dt with fluid density rho0). Returns the number of particles blended. onset >= 1
// turns it off. Sweeps every fluid row: call it only where the scene has solids (on some
// process, decomposed). With shared rows (sph/row_share.hpp, nb for this process's rows only) the
// blend acts on this process's rows, and the reactions of all processes are added to every row's
// solid_force in the one-process order (velocities: exchange them after); decomposed
// (sph/decomposition.hpp), to the owned solids' solid_force, wherever the fluid particle is.
template <int Dim>
int follow_enclosing_solids(Particles<Dim>& particles, const Neighbors<Dim>& nb, double onset,
                            double rho0, double dt, const RowShare* share = nullptr);

}  // namespace isph
