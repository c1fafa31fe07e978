// Stage 3 of a step: wall and PMS ghost velocities, the eddy viscosity, and the predictor
// u* = u + dt (nu lap u + g) in its plain or Darcy-Brinkman form.
#include <algorithm>
#include <cmath>

#include "format_number.hpp"
#include "isph_solver.hpp"
#include "rigid_solids.hpp"

namespace isph {

template <int Dim>
void IsphSolver<Dim>::compute_wall_ghosts() {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  // Velocities seen by fluid particles at wall neighbours. Adami et al. (2012) mirror the
  // Shepard-averaged fluid velocity through the wall velocity, which assumes that average sits
  // at the mirror point; for the deeper wall layers it sits much closer to the wall, and the
  // wall slips (0.6% of the peak in Poiseuille flow). Where the wall geometry is known, the
  // fluid velocity is extrapolated linearly instead: with d_w the particle's distance to the
  // wall surface and d' that of the fluid-neighbour centroid, u_g = v_w - (d_w/d')(u~ - v_w).
  //
  // PMS solids get the same no-slip extrapolation through their body's surface, half a spacing
  // beyond the outermost particles (sph/rigid_solids.hpp), from the fluid neighbours only. With
  // the solids' own rigid velocity the fluid slipped over that half spacing, and the Stokes drag
  // of a sphere was that of one half a spacing smaller (-26% at d = 5 dx).
  wall_ghost_.resize(n);
  const bool quadratic = config_.quadratic_wall_ghosts;
  if (quadratic) fit_ghost_profiles();
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    const bool solid = P.kind[i] == kSolid && P.surface[i] != kDrySolid;
    if (P.kind[i] != kWall && !solid) {
      wall_ghost_[i] = P.v[i];
      continue;
    }
    double ws = 0.0;
    Vec<Dim> vs = Vec<Dim>::Zero(), offset = Vec<Dim>::Zero();
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P.kind[j] == kWall || (solid && P.kind[j] == kSolid)) continue;
      ws += nb_.w[k];
      vs += nb_.w[k] * P.v[j];
      offset -= nb_.w[k] * nb_.rij[k];  // x_j - x_i
    }
    if (ws <= 0.0) {
      wall_ghost_[i] = P.v[i];
      continue;
    }
    vs /= ws;
    offset /= ws;
    double ratio = 1.0;
    const Vec<Dim>& nrm = P.normal[i];
    if (nrm.squaredNorm() > 0.0) {
      // The wall surface lies at x_w + d_w n, so the centroid is offset.n - d_w inside the fluid.
      const double dc = std::max(offset.dot(nrm) - P.wall_distance[i], 0.25 * P.spacing);
      ratio = P.wall_distance[i] / dc;
    }
    const Vec<Dim> rel = vs - P.v[i];
    Vec<Dim> slope, curvature;
    if (quadratic && (solid || config_.wall == WallSlip::NoSlip) &&
        ghost_profile(i, slope, curvature)) {
      // A fit to a few disordered neighbours can extrapolate wildly; the parabola may differ
      // from the linear extrapolation by at most twice the latter's own departure from v
      // (a narrow channel's deepest ghost seen by the fluid needs 1.3 times it).
      const double d = P.wall_distance[i];
      const Vec<Dim> linear = -ratio * rel;
      Vec<Dim> extra = -d * slope + d * d * curvature - linear;
      const double cap = 2.0 * linear.norm();
      if (extra.norm() > cap) extra *= cap / extra.norm();
      wall_ghost_[i] = P.v[i] + linear + extra;
    } else if (solid || config_.wall == WallSlip::NoSlip) {
      wall_ghost_[i] = P.v[i] - ratio * rel;
    } else {  // free slip: tangential velocity copied, normal velocity mirrored
      const Vec<Dim> rn = nrm.squaredNorm() > 0.0 ? Vec<Dim>(rel.dot(nrm) * nrm) : Vec<Dim>::Zero();
      wall_ghost_[i] = P.v[i] + (rel - rn) - ratio * rn;
    }
  }
  exchange(wall_ghost_);
}

// The fluid's velocity relative to the wall along the normal, u - v_w = a s + b s^2 at the height
// s above the surface, fitted (kernel-weighted least squares) to a wall or solid row's own fluid
// neighbours. In a gap a few spacings wide the flow is a parabola across it, and a ghost
// extrapolated linearly through the surface from the fluid's centroid misses its curvature: the
// fluid slipped, and a plane channel 3 spacings wide carried 27% more than Poiseuille's flow.
// Linear terms along the surface and |t|^2 are fitted with it and dropped. The fit needs
// neighbours at two heights at least; rows deeper in the wall have fluid at one
// height only, and take the profile of the fitted rows around them (ghost_profile).
template <int Dim>
void IsphSolver<Dim>::fit_ghost_profiles() {
  const int n = static_cast<int>(particles_.size());
  const auto& P = particles_;
  ghost_slope_.assign(n, Vec<Dim>::Zero());
  ghost_curvature_.assign(n, Vec<Dim>::Zero());
  ghost_fitted_.assign(n, 0.0);
  constexpr int M = Dim + 2;  // s, s^2, the tangential offsets, |t|^2
  using Basis = Eigen::Matrix<double, M, 1>;
  const double inv_dx = 1.0 / P.spacing;
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    const bool solid = P.kind[i] == kSolid && P.surface[i] != kDrySolid;
    const bool wall = P.kind[i] == kWall && config_.wall == WallSlip::NoSlip;
    const Vec<Dim>& nrm = P.normal[i];
    if ((!solid && !wall) || nrm.squaredNorm() == 0.0) continue;
    // Tangent directions, so that the velocity's change along the surface and the surface's own
    // curvature (a neighbour to the side of a convex body sits higher above the surface than its
    // offset along this row's normal says, by about |t|^2 / 2R) are not read as curvature of the
    // profile across it.
    Mat<Dim> frame = Mat<Dim>::Identity();
    frame.col(0) = nrm;
    if constexpr (Dim == 2) {
      frame.col(1) = Vec<Dim>(-nrm[1], nrm[0]);
    } else {
      int least = 0;
      nrm.cwiseAbs().minCoeff(&least);
      const Vec<Dim> t1 = nrm.cross(Vec<Dim>::Unit(least)).normalized();
      frame.col(1) = t1;
      frame.col(2) = nrm.cross(t1);
    }
    Eigen::Matrix<double, M, M> A = Eigen::Matrix<double, M, M>::Zero();
    Eigen::Matrix<double, M, Dim> R = Eigen::Matrix<double, M, Dim>::Zero();
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P.kind[j] == kWall || P.kind[j] == kSolid) continue;
      const Vec<Dim> r = -inv_dx * (frame.transpose() * nb_.rij[k]);  // x_j - x_i, in dx
      const double s = r[0] - inv_dx * P.wall_distance[i];
      if (s <= 0.0) continue;
      Basis phi;
      phi[0] = s;
      phi[1] = s * s;
      double t2 = 0.0;
      for (int a = 1; a < Dim; ++a) {
        phi[1 + a] = r[a];
        t2 += r[a] * r[a];
      }
      phi[M - 1] = t2;
      const double w = nb_.w[k];
      A.noalias() += w * phi * phi.transpose();
      R.noalias() += w * phi * (P.v[j] - P.v[i]).transpose();
    }
    // The profile across alone: sum w s^2, sum w s^3, sum w s^4. Neighbours at one height only
    // (rows deeper in the wall) give no curvature.
    const Eigen::Matrix2d across = A.template topLeftCorner<2, 2>();
    if (!(across(0, 0) > 0.0) || across.determinant() <= 0.1 * across(0, 0) * across(1, 1))
      continue;
    Eigen::Matrix<double, M, Dim> c;
    Eigen::FullPivLU<Eigen::Matrix<double, M, M>> lu(A);
    if (lu.isInvertible() && lu.rcond() > 1e-8) {
      c = lu.solve(R);
    } else {  // too few neighbours to the sides: the profile across alone
      c.setZero();
      c.template topRows<2>() = across.inverse() * R.template topRows<2>();
    }
    ghost_slope_[i] = inv_dx * c.row(0).transpose();
    ghost_curvature_[i] = inv_dx * inv_dx * c.row(1).transpose();
    ghost_fitted_[i] = 1.0;
  }
  exchange(ghost_slope_);
  exchange(ghost_curvature_);
  exchange(ghost_fitted_);
}

// Row i's fitted profile, or the kernel-weighted mean of those of the fitted rows around it of
// the same wall or body facing the same way (rows deeper in the wall, whose fluid neighbours sit
// at one height); false if there are none. (Averaging every row's profile with its neighbours'
// did not quieten the force on a bed of spheres, and it mixes normals on a curved body.)
template <int Dim>
bool IsphSolver<Dim>::ghost_profile(int i, Vec<Dim>& slope, Vec<Dim>& curvature) const {
  if (ghost_fitted_[i] > 0.0) {
    slope = ghost_slope_[i];
    curvature = ghost_curvature_[i];
    return true;
  }
  const auto& P = particles_;
  double ws = 0.0;
  slope.setZero();
  curvature.setZero();
  for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
    const int j = nb_.index[k];
    if (ghost_fitted_[j] <= 0.0 || P.kind[j] != P.kind[i] || P.body[j] != P.body[i] ||
        P.normal[j].dot(P.normal[i]) < 0.5)
      continue;
    ws += nb_.w[k];
    slope += nb_.w[k] * ghost_slope_[j];
    curvature += nb_.w[k] * ghost_curvature_[j];
  }
  if (ws <= 0.0) return false;
  slope /= ws;
  curvature /= ws;
  return true;
}

template <int Dim>
void IsphSolver<Dim>::compute_eddy_viscosity() {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  eddy_viscosity_.assign(n, 0.0);
  if (config_.smagorinsky) {
    const double cs_dx = config_.smagorinsky_constant * P.spacing;
#pragma omp parallel for schedule(static)
    for (int i = first_; i < last_; ++i) {
      if (P.kind[i] != kFluid) continue;
      const Mat<Dim> g = gradient(nb_, op_, P.v, i);
      const Mat<Dim> S = 0.5 * (g + g.transpose());
      eddy_viscosity_[i] = cs_dx * cs_dx * std::sqrt(2.0 * S.squaredNorm());
    }
    exchange(eddy_viscosity_);
    max_eddy_viscosity_ =
        n > 0 ? *std::max_element(eddy_viscosity_.begin(), eddy_viscosity_.end()) : 0.0;
    if (decomposition_) max_eddy_viscosity_ = share_->max(max_eddy_viscosity_);
  }
}

template <int Dim>
void IsphSolver<Dim>::predict(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  const double nu = config_.viscosity;
  try {
    porous_.prepare(P, nb_, dt, block_share());
  } catch (const std::invalid_argument& e) {
    throw SimulationError(
        std::string("porous terms at t = ") + format_number(time_, 4) + " s: " + e.what(),
        "porosity");
  }
  u_star_.resize(n);
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    // The zone's rows see the pressure like fluid rows, and the projection makes the field
    // divergence-free assuming the corrector acts on them too. Like walls they therefore carry
    // the body acceleration: otherwise the hydrostatic gradient alone reads as a correction of
    // +dt g, the fluid above a rising zone was projected to v_in + dt g (5.25-5.5 mm/s over a
    // 5 mm/s pump at dt = 1e-4 s) while the zone's particles moved at v_in.
    //
    // The projection also takes the zone's velocity after the step to be u* - dt c grad p / rho,
    // while the pump holds it at v_in: so u* carries the whole pressure gradient of the last
    // step, not only its hydrostatic part g. With g alone the fluid was projected as if the zone
    // moved at v_in - dt c grad p_dyn / rho: the pressure that drives the flow through the
    // layer cut the pumped flux by a share that grew with the step (window flux above the
    // erosion layer 0.4-0.5 v_in at dt = 2e-3 s, about v_in at 1e-4 s).
    if (P.kind[i] == kForcing) {
      const Vec<Dim> a =
          steps_ > 0 ? Vec<Dim>(gradient(nb_, op_, P.p, i) / config_.density) : config_.gravity;
      u_star_[i] =
          zone_of(P.x[i])->velocity_at(time_ + dt) + dt * porous_.pressure_coefficient(i) * a;
      continue;
    }
    // Walls take the body acceleration too: their pressure rows impose dp/dn = rho (g - a_w).n,
    // so after the corrector the normal velocity at the wall is v_w.n again. Leaving u*_w = v_w
    // would count gravity twice in div u* next to the wall.
    if (P.kind[i] == kWall) {
      u_star_[i] = P.v[i] + dt * porous_.pressure_coefficient(i) * config_.gravity;
      continue;
    }
    if (porous_.active()) {
      u_star_[i] = porous_.predict(P, i, dt, nu, eddy_viscosity_[i],
                                   laplacian(nb_, op_, wall_ghost_, i), config_.gravity);
      continue;
    }
    // (Wall tangential velocities are replaced below, once the fluid u* is known.)
    // The eddy viscosity enters as nu_eff lap u (its gradient term is dropped).
    u_star_[i] = P.v[i] + dt * ((nu + eddy_viscosity_[i]) * laplacian(nb_, op_, wall_ghost_, i) +
                                config_.gravity);
  }
  if (config_.pms_pressure_increment && has_solids()) {
    // A PMS body is rigid and moved by the DEM, not by this projection: its rows predict the
    // velocity they keep under last step's pressure, so that only the pressure's change per step
    // moves them (rigid while the flow is steady). With the fluid's u* the projection moved the
    // body's rows by dt (g + nu lap u - grad p / rho), a leak through the body of the order of
    // dt times the pressure gradient, which the next step's reset to the rigid velocity undid.
    // Their force (pms_force) keeps the fluid predictor's u*: its nu lap u is the viscous load.
    // The first step takes the hydrostatic gradient, rho g.
    pms_u_star_ = u_star_;
#pragma omp parallel for schedule(static)
    for (int i = first_; i < last_; ++i) {
      if (P.kind[i] != kSolid || P.surface[i] == kDrySolid) continue;
      const Vec<Dim> a =
          steps_ > 0 ? Vec<Dim>(gradient(nb_, op_, P.p, i) / config_.density) : config_.gravity;
      u_star_[i] = P.v[i] + dt * porous_.pressure_coefficient(i) * a;
    }
  }
  exchange(u_star_);  // the walls' u* below and the divergence read the fluid's
}

template <int Dim>
void IsphSolver<Dim>::set_wall_u_star(double dt) {
  auto& P = particles_;
  // In div u* only the wall-normal velocity is a boundary condition. A no-slip wall's zero
  // tangential velocity next to fluid sliding along it reads as a divergence wherever the wall
  // extends beyond the fluid (the toe of a surge, corners), and the pressure answered with a
  // pocket of suction that pulled the toe into the floor. Walls with known normals therefore
  // carry the fluid's tangential u* (Shepard average) and their own normal u*.
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    if (P.kind[i] != kWall || P.normal[i].squaredNorm() == 0.0) continue;
    double ws = 0.0;
    Vec<Dim> us = Vec<Dim>::Zero();
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P.kind[j] == kWall) continue;
      ws += nb_.w[k];
      us += nb_.w[k] * u_star_[j];
    }
    if (ws <= 0.0) continue;
    us /= ws;
    const Vec<Dim>& nrm = P.normal[i];
    const Vec<Dim> own = P.v[i] + dt * porous_.pressure_coefficient(i) * config_.gravity;
    u_star_[i] = us - us.dot(nrm) * nrm + own.dot(nrm) * nrm;
  }
  exchange(u_star_);
}

template void IsphSolver<2>::compute_wall_ghosts();
template void IsphSolver<2>::fit_ghost_profiles();
template bool IsphSolver<2>::ghost_profile(int, Vec<2>&, Vec<2>&) const;
template void IsphSolver<2>::compute_eddy_viscosity();
template void IsphSolver<2>::predict(double);
template void IsphSolver<2>::set_wall_u_star(double);
template void IsphSolver<3>::compute_wall_ghosts();
template void IsphSolver<3>::fit_ghost_profiles();
template bool IsphSolver<3>::ghost_profile(int, Vec<3>&, Vec<3>&) const;
template void IsphSolver<3>::compute_eddy_viscosity();
template void IsphSolver<3>::predict(double);
template void IsphSolver<3>::set_wall_u_star(double);

}  // namespace isph
