#include "isph_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "format_number.hpp"
#include "free_surface.hpp"
#include "pocket_fluid.hpp"
#include "rigid_solids.hpp"
#include "stopwatch.hpp"

namespace isph {

namespace {

// q of spread_pinned_source only has to carry the pinned row's excess (lambda n, n rows) to the
// other rows, each of which then takes lambda. A relative residual tol in q leaves at most
// lambda tol sqrt(n) in any one row: at 1e-3 less than the share every row takes for n up to
// 1e6. Tighter buys nothing: between solves q is stale by more than that anyway. Solved every
// 10th step, warm-started: about 35 BiCGSTAB iterations per solve in the fluidization tank
// (100 at 1e-4, against about 35 for the pressure itself in its quiet phase).
constexpr double kUnitResponseTolerance = 1e-3;
constexpr int kUnitResponseEvery = 10;

LinearSolverConfig unit_solver_config(LinearSolverConfig c) {
  c.tolerance = std::max(c.tolerance, kUnitResponseTolerance);
  return c;
}

std::string fmt(double v) { return format_number(v, 4); }

template <int Dim>
std::string fmt(const Vec<Dim>& v) {
  std::ostringstream s;
  s.precision(6);
  s << "(";
  for (int a = 0; a < Dim; ++a) s << (a ? ", " : "") << v[a];
  s << ")";
  return s.str();
}

// Closest approach of two fluid particles, in spacings (see separate_close_pairs).
constexpr double kMinPairDistance = 0.5;

}  // namespace

template <int Dim>
IsphSolver<Dim>::IsphSolver(const IsphConfig<Dim>& config, const Domain<Dim>& domain,
                            Particles<Dim> particles)
    : config_(config),
      domain_(domain),
      particles_(std::move(particles)),
      kernel_(config.kernel, config.smoothing_ratio * particles_.spacing),
      search_(domain, kernel_.support()),
      linear_solver_(make_linear_solver(config.pressure_solver)),
      unit_solver_(make_linear_solver(unit_solver_config(config.pressure_solver))) {
  if (!(particles_.spacing > 0.0))
    throw SimulationError("particle spacing must be positive (particles.spacing)");
  if (particles_.size() == 0) throw SimulationError("the case creates no particles");
  if (!(config.density > 0.0)) throw SimulationError("fluid.density must be positive");
  if (config.viscosity < 0.0) throw SimulationError("fluid.viscosity must not be negative");
  // Periodic axes too: a block sticking out of a periodic box would wrap onto other particles.
  for (std::size_t i = 0; i < particles_.size(); ++i)
    if (((particles_.x[i] - domain_.lo).array() < 0.0).any() ||
        ((particles_.x[i] - domain_.hi).array() > 0.0).any())
      throw SimulationError("particle " + std::to_string(particles_.id[i]) + " at " +
                            fmt<Dim>(particles_.x[i]) +
                            " starts outside the domain box: enlarge domain.min/domain.max");
  for (auto& x : particles_.x) domain_.wrap(x);
  n0_ = reference_number_density(kernel_, particles_.spacing);
}

template <int Dim>
double IsphSolver<Dim>::max_speed() const {
  double m = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i)
    if (particles_.kind[i] != kWall) m = std::max(m, particles_.v[i].norm());
  return m;
}

template <int Dim>
TimeStepLimits IsphSolver<Dim>::limits() const {
  return time_step_limits(config_.time_step, particles_.spacing, max_speed(),
                          config_.viscosity + max_eddy_viscosity_, config_.gravity.norm());
}

template <int Dim>
const ForcingZone<Dim>* IsphSolver<Dim>::zone_of(const Vec<Dim>& x) const {
  for (const auto& z : config_.forcing)
    if (z.contains(x)) return &z;
  return nullptr;
}

template <int Dim>
void IsphSolver<Dim>::update_forcing_kinds() {
  if (config_.forcing.empty()) return;
  auto& P = particles_;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != kFluid && P.kind[i] != kForcing) continue;
    P.kind[i] = zone_of(P.x[i]) ? kForcing : kFluid;
  }
}

template <int Dim>
void IsphSolver<Dim>::update_geometry() {
  {
    Stopwatch w(timings_.neighbors);
    const std::vector<int> perm = search_.sort(particles_);
    if (unit_response_.size() == static_cast<Eigen::Index>(perm.size())) {
      Eigen::VectorXd q(unit_response_.size());
      for (std::size_t k = 0; k < perm.size(); ++k) q[k] = unit_response_[perm[k]];
      unit_response_.swap(q);
    }
    search_.build(particles_, kernel_, nb_);
  }
  Stopwatch w(timings_.operators);
  const int n = static_cast<int>(particles_.size());
  number_density(nb_, number_density_);
  if (config_.surface.method != SurfaceDetection::NumberDensity)
    position_divergence(nb_, particles_.volume, divergence_r_);
  if (config_.free_surface) {
    mark_free_surface(particles_, number_density_, n0_, divergence_r_, config_.surface);
    mark_sparse_as_surface(
        particles_, nb_, 3 * Dim,
        static_cast<int>(0.6 * reference_neighbor_count(kernel_, particles_.spacing)));
    if (config_.surface.scan) {
      // Before the first solve every pressure is zero and a roof would read as dry.
      if (steps_ > 0)
        mark_dry_walls(particles_, nb_, config_.gravity, config_.density, dry_wall_);
      else
        dry_wall_.assign(particles_.size(), 0);
      const bool gravity = config_.gravity.squaredNorm() > 0.0;
      const Vec<Dim> up = gravity ? Vec<Dim>(-config_.gravity.normalized()) : Vec<Dim>::Zero();
      mark_open_side_as_surface(particles_, nb_, &dry_wall_, gravity ? &up : nullptr);
    }
  } else
    std::fill(particles_.surface.begin(), particles_.surface.end(), 0);
  if (config_.free_surface) mark_dry_solids(particles_, nb_, config_.gravity);
  surface_depth_.clear();
  if (config_.free_surface && config_.surface_refill && config_.gravity.squaredNorm() > 0.0)
    surface_depth(particles_, nb_, Vec<Dim>(-config_.gravity.normalized()), surface_depth_);
  // Walls need no operators; free-surface particles get the robust first-order forms (a
  // one-sided quadratic fit extrapolates). Their neighbours keep the quadratic fit: the Brookshaw
  // Laplacian is not exact for a linear (hydrostatic) field on a truncated support, and still
  // water drifted and blew up after 6000 steps with it.
  operator_mode_.resize(n);
  for (int i = 0; i < n; ++i)
    operator_mode_[i] = particles_.kind[i] == kWall ? 0 : (particles_.surface[i] ? 1 : 2);
  compute_operators(nb_, kernel_.h(), particles_.volume, operator_mode_, op_);
}

template <int Dim>
StepStats IsphSolver<Dim>::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw SimulationError("time step must be positive");
  update_forcing_kinds();
  update_geometry();
  StepStats stats;
  stats.dt = dt;
  {
    Stopwatch w(timings_.rest);
    compute_wall_ghosts();
    compute_eddy_viscosity();
    predict(dt);
    set_wall_u_star(dt);
    mark_full_support();
    compute_pressure_rhs(dt);
  }
  {
    Stopwatch w(timings_.assembly);
    assemble_pressure(particles_, nb_, op_, rhs_, config_.gravity, config_.density, kernel_.h(),
                      system_, porous_.active() ? &porous_.pressure_coefficient() : nullptr,
                      surface_depth_.empty() ? nullptr : &surface_depth_);
  }
  {
    Stopwatch w(timings_.solve);
    solve_pressure(stats);
  }
  {
    Stopwatch w(timings_.rest);
    correct(dt);
    follow_enclosing_solids(particles_, nb_, config_.pocket_solid_fraction, config_.density, dt);
    shift(dt);
    advect(dt, stats);
  }
  time_ += dt;
  ++steps_;
  check_state("after the step");
  if (dt * stats.max_speed > particles_.spacing)
    throw SimulationError(
        "time step far beyond the CFL limit at t = " + fmt(time_) + " s: dt = " + fmt(dt) +
        " s moved particles " + fmt(dt * stats.max_speed / particles_.spacing) +
        " spacings in one step (max |u| = " + fmt(stats.max_speed) + " m/s); use a dt below " +
        fmt(limits().min()) +
        " s (time.dt = \"auto\" in a fluid-only case; a coupled case needs time.dt and [dem] "
        "substeps changed together) or find what accelerates the flow this much; " +
        describe_fastest());
  return stats;
}

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
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
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
    if (solid || config_.wall == WallSlip::NoSlip) {
      wall_ghost_[i] = P.v[i] - ratio * rel;
    } else {  // free slip: tangential velocity copied, normal velocity mirrored
      const Vec<Dim> rn = nrm.squaredNorm() > 0.0 ? Vec<Dim>(rel.dot(nrm) * nrm) : Vec<Dim>::Zero();
      wall_ghost_[i] = P.v[i] + (rel - rn) - ratio * rn;
    }
  }
}

template <int Dim>
void IsphSolver<Dim>::compute_eddy_viscosity() {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  eddy_viscosity_.assign(n, 0.0);
  if (config_.smagorinsky) {
    const double cs_dx = config_.smagorinsky_constant * P.spacing;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) {
      if (P.kind[i] != kFluid) continue;
      const Mat<Dim> g = gradient(nb_, op_, P.v, i);
      const Mat<Dim> S = 0.5 * (g + g.transpose());
      eddy_viscosity_[i] = cs_dx * cs_dx * std::sqrt(2.0 * S.squaredNorm());
    }
    max_eddy_viscosity_ = *std::max_element(eddy_viscosity_.begin(), eddy_viscosity_.end());
  }
}

template <int Dim>
void IsphSolver<Dim>::predict(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  const double nu = config_.viscosity;
  try {
    porous_.prepare(P, nb_, dt);
  } catch (const std::invalid_argument& e) {
    throw SimulationError(std::string("porous terms at t = ") + fmt(time_) + " s: " + e.what());
  }
  u_star_.resize(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    // The zone's rows see the pressure like fluid rows, and the projection makes the field
    // divergence-free assuming the corrector acts on them too. Like walls they therefore carry
    // the body acceleration: otherwise the hydrostatic gradient alone reads as a correction of
    // +dt g, the fluid above a rising zone was projected to v_in + dt g (5.25-5.5 mm/s over a
    // 5 mm/s pump at dt = 1e-4 s) while the zone's particles moved at v_in.
    if (P.kind[i] == kForcing) {
      u_star_[i] = zone_of(P.x[i])->velocity_at(time_ + dt) +
                   dt * porous_.pressure_coefficient(i) * config_.gravity;
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
}

template <int Dim>
void IsphSolver<Dim>::set_wall_u_star(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  // In div u* only the wall-normal velocity is a boundary condition. A no-slip wall's zero
  // tangential velocity next to fluid sliding along it reads as a divergence wherever the wall
  // extends beyond the fluid (the toe of a surge, corners), and the pressure answered with a
  // pocket of suction that pulled the toe into the floor. Walls with known normals therefore
  // carry the fluid's tangential u* (Shepard average) and their own normal u*.
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
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
}

template <int Dim>
void IsphSolver<Dim>::mark_full_support() {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  // Particles whose whole support lies inside the fluid. Near the free surface the kernel is
  // truncated: the number-density deficit there is geometry, not compression, so neither the
  // density-invariance term nor shifting may act on it.
  full_support_.assign(n, 0);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] == kWall || P.surface[i]) continue;
    bool near_surface = false;
    for (int k = nb_.begin(i); k < nb_.end(i) && !near_surface; ++k)
      near_surface = P.surface[nb_.index[k]];
    full_support_[i] = !near_surface;
  }
}

template <int Dim>
void IsphSolver<Dim>::compute_pressure_rhs(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  const double rho0 = config_.density;
  rhs_.assign(n, 0.0);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] == kWall) continue;
    const double density_error = full_support_[i] ? 1.0 - number_density_[i] / n0_ : 0.0;
    rhs_[i] = rho0 / dt * divergence(nb_, op_, u_star_, i) +
              config_.alpha_s * rho0 * density_error / (dt * dt);
  }
  remove_net_source(P, rhs_);
}

template <int Dim>
void IsphSolver<Dim>::solve_pressure(StepStats& stats) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  const double rho0 = config_.density;
  pressure_ = Eigen::Map<const Eigen::VectorXd>(P.p.data(), n);
  // Warm start from the pinned system's own last solution, not the spread one: the two differ by
  // lambda q, a smooth field over the whole domain that BiCGSTAB would otherwise have to remove
  // again every step (fluidization tank: 83 -> 140 iterations per step).
  const bool same_pin = system_.pinned >= 0 && unit_response_.size() == n &&
                        P.id[system_.pinned] == unit_response_pin_;
  if (config_.spread_pin && same_pin) pressure_ += unit_response_lambda_ * unit_response_;
  // Physical pressure scale (hydrostatic head over the box plus dynamic pressure) per row.
  const double extent = domain_.length().maxCoeff();
  const double vmax = max_speed();
  const double p_scale =
      rho0 * (config_.gravity.norm() * extent + vmax * vmax) * std::sqrt(double(n));
  const SolveStats s = linear_solver_->solve(system_.A, system_.b, pressure_, p_scale);
  stats.ppe_iterations = s.iterations;
  stats.ppe_residual = s.residual;
  unit_response_lambda_ = 0.0;
  if (config_.spread_pin && system_.pinned >= 0 && std::isfinite(s.residual)) {
    // q follows the particle arrangement slowly: solved again every few steps, in between the
    // last one is used (the pinned row still holds exactly; the others take lambda times the
    // change of A q since then, a small part of an excess that is itself small).
    // Only while the same particle is pinned: q is 0 there and carries its excess.
    bool fresh = same_pin && steps_ % kUnitResponseEvery != 0;
    if (!fresh) {
      const Eigen::VectorXd e = uniform_source(P, op_, system_);
      if (unit_response_.size() != n) unit_response_ = Eigen::VectorXd::Zero(n);
      const SolveStats u = unit_solver_->solve(system_.A, e, unit_response_);
      stats.ppe_iterations += u.iterations;
      fresh = std::isfinite(u.residual) && u.residual <= 1e3 * kUnitResponseTolerance;
      unit_response_pin_ = P.id[system_.pinned];
      if (!fresh) unit_response_.resize(0);
    }
    unit_response_lambda_ = fresh ? spread_pinned_source(system_, unit_response_, pressure_) : 0.0;
  }
  if (!std::isfinite(s.residual) || s.residual > 1e3 * config_.pressure_solver.tolerance)
    throw SimulationError("pressure solver failed at t = " + fmt(time_) + " s (relative residual " +
                          fmt(s.residual) + " after " + std::to_string(s.iterations) +
                          " iterations): reduce time.dt or check the geometry for isolated "
                          "particles");
  Eigen::Map<Eigen::VectorXd>(P.p.data(), n) = pressure_;
}

template <int Dim>
void IsphSolver<Dim>::correct(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  const double rho0 = config_.density;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] == kWall) continue;
    if (P.kind[i] == kForcing) {  // the pump: the zone velocity whatever the pressure
      P.v[i] = zone_of(P.x[i])->velocity_at(time_ + dt);
      continue;
    }
    if (P.kind[i] == kSolid) {  // PMS: the fluid's momentum change goes to the body
      P.solid_force[i] = pms_force(P, nb_, op_, i, rho0, dt, u_star_[i], config_.gravity);
      continue;
    }
    P.v[i] = u_star_[i] - dt * porous_.pressure_coefficient(i) / rho0 * gradient(nb_, op_, P.p, i);
  }
}

template <int Dim>
void IsphSolver<Dim>::shift(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  // Fluid with full support shifts freely; at and next to the free surface only tangentially.
  shift_mode_.resize(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    // With surface_refill every particle that is not on the surface shifts freely: voids under
    // the top row (return flow beside the walls) are otherwise closed by nothing.
    const bool free_shift = full_support_[i] || (!surface_depth_.empty() && !P.surface[i]);
    shift_mode_[i] = P.kind[i] != kFluid ? 0 : (free_shift ? 2 : 1);
    // Shifting repairs disorder inside the fluid. A splash tip or a toe particle whose support
    // is mostly wall has no meaningful concentration gradient: its shift came out at the cap,
    // against the flow, and the Taylor correction turned that into a velocity kick every step.
    if (shift_mode_[i] == 1) {
      int nf = 0;
      for (int k = nb_.begin(i); k < nb_.end(i); ++k) nf += P.kind[nb_.index[k]] != kWall;
      if (nf < 3 * Dim) shift_mode_[i] = 0;
    }
  }
  compute_shifts(P, nb_, kernel_, config_.shifting, dt, shift_mode_, shift_);
  if (!surface_depth_.empty()) {
    // Lift exposed second-row particles onto the surface line (surface_refill).
    const Vec<Dim> up = -config_.gravity.normalized();
    const double cap = config_.shifting.max_fraction * P.spacing;
    for (int i = 0; i < n; ++i) {
      if (P.kind[i] != kFluid || !(surface_depth_[i] > 0.0)) continue;
      // Only into a gap: nothing directly above within a column of half a spacing's radius.
      bool blocked = false;
      for (int k = nb_.begin(i); k < nb_.end(i) && !blocked; ++k) {
        if (P.kind[nb_.index[k]] == kWall) continue;
        const Vec<Dim> r = -nb_.rij[k];
        const double h = up.dot(r);
        blocked = h > 0.0 && h < 1.2 * P.spacing && (r - h * up).norm() < 0.6 * P.spacing;
      }
      if (blocked) continue;
      shift_[i] += std::min(surface_depth_[i], cap) * up;
      if (!shift_mode_[i]) shift_mode_[i] = 1;  // so that its velocity is Taylor-corrected
    }
  }
  // Taylor-correct velocities to the shifted positions (u_star_ reused as scratch), limited so
  // that no new extremum appears: each component stays within the range of the particle's own
  // and its fluid neighbours' values. On a truncated support (free surface, splash tip) the
  // gradient's own coefficient -sum_j G_ij does not vanish, so u_i + (grad u)_i . dr is
  // u_i (1 - dr . sum_j G_ij) + ...: whenever the shift has a component along -sum_j G_ij the
  // particle's velocity was amplified by a fixed factor in every step, and the shift itself
  // grows with |u|. Surface and toe particles ran away exponentially in the step count, which
  // is why a smaller dt failed earlier. The limiter is inactive in smooth interior flow.
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (!shift_mode_[i]) {
      u_star_[i] = P.v[i];
      continue;
    }
    Vec<Dim> u = P.v[i] + gradient(nb_, op_, P.v, i) * shift_[i];
    Vec<Dim> lo = P.v[i], hi = P.v[i];
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P.kind[j] == kWall) continue;
      lo = lo.cwiseMin(P.v[j]);
      hi = hi.cwiseMax(P.v[j]);
    }
    u_star_[i] = u.cwiseMax(lo).cwiseMin(hi);
  }
  P.v.swap(u_star_);
}

template <int Dim>
void IsphSolver<Dim>::advect(double dt, StepStats& stats) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  if (config_.free_surface)
    separate_close_pairs(P, nb_, domain_, dt, kMinPairDistance * P.spacing, shift_);
  double vmax = 0.0;
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] == kWall || P.kind[i] == kSolid) continue;  // solids: placed by their body
    P.x[i] += dt * P.v[i] + shift_[i];
    keep_off_walls(i);
    domain_.wrap(P.x[i]);
    vmax = std::max(vmax, P.v[i].norm());
    stats.surface_particles += P.surface[i];
    stats.fluid_volume += P.volume * (full_support_[i] ? n0_ / number_density_[i] : 1.0);
  }
  stats.max_speed = vmax;
  stats.max_eddy_viscosity = max_eddy_viscosity_;
}

template <int Dim>
void IsphSolver<Dim>::keep_off_walls(int i) {
  // Nothing in the pressure equation reacts to a position error, so a particle driven fast along
  // a wall (the toe of a dam break) can creep into it and then blow up among the wall
  // particles. Walls with known geometry therefore act as a kinematic constraint: a fluid
  // particle closer than `min_wall_distance` to the wall surface of a neighbouring wall particle
  // is put back at that distance and loses its velocity into the wall.
  auto& P = particles_;
  const double min_dist = config_.min_wall_distance * P.spacing;
  for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
    const int w = nb_.index[k];
    if (P.kind[w] != kWall || P.normal[w].squaredNorm() == 0.0) continue;
    const Vec<Dim>& nrm = P.normal[w];
    // Only walls whose surface patch is beside the particle (not a neighbouring face at a corner).
    const Vec<Dim> d = domain_.min_image(P.x[i] - P.x[w]);
    const Vec<Dim> tangential = d - d.dot(nrm) * nrm;
    if (tangential.norm() > 0.5 * P.spacing) continue;
    const double gap = d.dot(nrm) - P.wall_distance[w];
    if (gap >= min_dist) continue;
    P.x[i] += (min_dist - gap) * nrm;
    const double vn = P.v[i].dot(nrm) - P.v[w].dot(nrm);
    if (vn < 0.0) P.v[i] -= vn * nrm;
  }
}

template <int Dim>
std::string IsphSolver<Dim>::describe_fastest() const {
  const auto& P = particles_;
  // The particles advect() takes max |u| over (solids are placed by their bodies), so that the
  // particle named is the one whose speed the message quotes.
  int fast = -1;
  for (int i = 0; i < static_cast<int>(P.size()); ++i)
    if (P.kind[i] != kWall && P.kind[i] != kSolid && (fast < 0 || P.v[i].norm() > P.v[fast].norm()))
      fast = i;
  if (fast < 0) return "no moving particle";
  // The neighbour list is the step's own (built before the particles moved): what the fastest
  // particle's equations saw. A fluid particle whose support is mostly solid sits in a pocket
  // between bodies (the semi-resolved erosion runs broke up from one).
  static const char* const names[] = {"fluid", "wall", "solid (PMS)", "forcing-zone"};
  int count[4] = {0, 0, 0, 0};
  for (int k = nb_.begin(fast); k < nb_.end(fast); ++k) ++count[P.kind[nb_.index[k]]];
  return std::string("the fastest is ") + names[P.kind[fast]] + " particle " +
         std::to_string(P.id[fast]) + " at " + fmt<Dim>(P.x[fast]) + " m (" +
         fmt(P.v[fast].norm()) + " m/s) with " + std::to_string(count[kFluid] + count[kForcing]) +
         " fluid, " + std::to_string(count[kSolid]) + " solid and " + std::to_string(count[kWall]) +
         " wall neighbours";
}

template <int Dim>
void IsphSolver<Dim>::check_state(const char* where) const {
  const auto& P = particles_;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.x[i].allFinite() || !P.v[i].allFinite() || !std::isfinite(P.p[i]))
      throw SimulationError("non-finite value (NaN/inf) in particle " + std::to_string(P.id[i]) +
                            " " + where + " at t = " + fmt(time_) +
                            " s: the run became unstable; reduce time.dt (or use \"auto\")");
    if (P.kind[i] != kWall && !domain_.contains(P.x[i]))
      throw SimulationError("fluid particle " + std::to_string(P.id[i]) + " left the domain at " +
                            fmt<Dim>(P.x[i]) + ", t = " + fmt(time_) +
                            " s: close the container with walls or enlarge domain.min/max");
  }
}

template class IsphSolver<2>;
template class IsphSolver<3>;

}  // namespace isph
