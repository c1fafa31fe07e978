#pragma once
// Assembly of the pressure Poisson equation. One row per particle:
//  - fluid-like particles (fluid, forcing zone, PMS solid): lap p_i = rhs_i with the corrected
//    Laplacian;
//  - free-surface particles: p_i = 0, or the hydrostatic rho0 |g| surface_depth[i] when given
//    (surface_depth in sph/free_surface.hpp);
//  - wall/dummy particles: p_w = sum_f W_wf (p_f + rho0 (g - a_w).(x_w - x_f)) / sum_f W_wf over
//    fluid neighbours f (Adami et al. 2012 extrapolation, solved implicitly with the fluid so
//    the wall condition and the interior equation are consistent in one system);
//  - wall particles without fluid neighbours: p_w = 0 (decoupled);
//  - with a per-particle coefficient c (porous media, sph/porous_medium.hpp) interior rows are
//    div(c grad p) = rhs, each Laplacian pair weight scaled by the harmonic mean of c_i and c_j;
//  - with no Dirichlet row at all (closed or periodic box), one fluid row is pinned to p = 0 to
//    remove the constant null space.
#include <cstdint>
#include <utility>
#include <vector>

#include "linear_solver.hpp"
#include "neighbors.hpp"
#include "operators.hpp"
#include "row_share.hpp"

namespace isph {

template <int Dim>
struct PressureSystem {
  SparseMatrix A;
  Eigen::VectorXd b;
  int pinned = -1;  // index of the pinned row, -1 when a Dirichlet row fixes the level
  // The pinned particle's id, -1 without a pin; decomposed, the same on every process while only
  // the owner's `pinned` names a row.
  int64_t pinned_id = -1;
  // The interior equation the pin replaced (scaled like the other rows): its coefficients by
  // column, diagonal included, and its right-hand side. spread_pinned_source() uses them.
  std::vector<std::pair<int, double>> pin_row;
  double pin_b = 0.0;
};

// The pinned row p_k = 0 absorbs whatever part of the source the singular equation cannot
// satisfy: the component along its left null vector y (y^T b), which is not the mean unless the
// Laplacian is symmetric. With the fitted Laplacian around PMS bodies it is large: in the closed
// internal-erosion tank the pinned corner became a point sink with jets of 4 v_in at 0.01 s,
// matched by volume created in the bed's pores. Given the solution p of the pinned system and q
// of the same system with a unit source in every fluid-like row but the pinned one (walls and
// the pin: 0), this returns p - lambda q, which satisfies every interior equation, the pinned
// one included, with the source lowered by the same lambda everywhere: the excess is spread
// over all particles as a uniform compression the density-invariance term then corrects, not
// put into one. Returns lambda (in units of the scaled right-hand side).
template <int Dim>
double spread_pinned_source(const PressureSystem<Dim>& system, const Eigen::VectorXd& q,
                            Eigen::VectorXd& p);
// lambda alone (p unchanged); needs the pinned row as assembled (pin_row).
template <int Dim>
double pinned_lambda(const PressureSystem<Dim>& system, const Eigen::VectorXd& q,
                     const Eigen::VectorXd& p);

// The right-hand side of that second solve: 1 in the interior rows, 0 in wall rows, the pin and
// the rows of isolated particles (p = 0).
template <int Dim>
Eigen::VectorXd uniform_source(const Particles<Dim>& particles, const Operators<Dim>& op,
                               const PressureSystem<Dim>& system);

// Without a Dirichlet row (closed or periodic boxes) the pressure equation is solvable only when
// its right-hand side has no net source; otherwise the pinned row absorbs the excess (density-
// invariance and divergence errors do not sum to zero) as a point source. A driven periodic
// column grew a vortex around the pinned particle within 0.3 s, and the circulation tank closed
// at the water line blew up from its pinned corner at 0.41 s (stable to 2 s with this). Removes
// the mean over fluid-like rows; does nothing when any particle is on the free surface.
// `decomposed`: the fluid decomposed over processes (sph/decomposition.hpp); the mean is then
// over every process's owned rows.
template <int Dim>
void remove_net_source(const Particles<Dim>& particles, std::vector<double>& rhs,
                       const RowShare* decomposed = nullptr);

// `decomposed`: as above; whether any Dirichlet row exists and which particle is pinned (the
// smallest id of all processes' owned candidates) are then decided over all processes.
template <int Dim>
void assemble_pressure(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                       const Operators<Dim>& op, const std::vector<double>& rhs,
                       const Vec<Dim>& gravity, double rho0, double h, PressureSystem<Dim>& out,
                       const std::vector<double>* coefficient = nullptr,
                       const std::vector<double>* surface_depth = nullptr,
                       const RowShare* decomposed = nullptr);

}  // namespace isph
