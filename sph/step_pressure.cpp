// Stage 4 of a step: the stabilised PPE, lap p = rho0/dt div u* + alpha_s (rho0 - rho)/dt^2,
// its right-hand side, assembly (pressure_equation.hpp) and solve.
#include <algorithm>
#include <cmath>

#include "format_number.hpp"
#include "isph_solver.hpp"
#include "pocket_fluid.hpp"

namespace isph {

namespace {

// q of spread_pinned_source carries the pinned row's excess to the other rows: p -= lambda q, so
// q's residual enters every row's equation times lambda. It is solved to the pressure's own
// tolerance, so that the spread pressure meets the tolerance asked for. With q at 1e-3 (until
// 2026-12-04) the semi-resolved closed erosion tank blew up with amg at t = 0.33 s (0.29 s at
// tolerance 1e-10) while Eigen's BiCGSTAB ran on; with q at the pressure's tolerance amg ran it
// to 1 s (0.4 s at 1e-10). A q tied to lambda (|lambda r| within the pressure's own budget) blew
// up again at 1e-10 (0.30 s): that trajectory is sensitive, and only the tight q carried it
// (docs/fluid.md). The price, q being solved every 10th step and warm-started: 8-9% more PPE
// iterations in closed and periodic boxes (Taylor-Green at 6400 particles, jacobi 96.9 against
// 89.1 per step; the closed erosion tank, ilu0, 35.3 against 32.3), 1% of that tank's wall time.
constexpr int kUnitResponseEvery = 10;

// A full-support particle whose number density is 10% under n0, with no PMS particle in its
// support, is taken to sit at a void's rim. Pore fluid among PMS particles keeps alpha_s: the
// density-correction speed alpha_s error dx/dt is 4 v_in at 0.5 cm/s with 0.02, and with it there
// too the semi-resolved 0.5 cm/s run's peak pore speed over 1-2 s read 28.4 v_in, against 24.2
// without and 19.7 before the term (docs/internal_erosion.md). The 10% was not tuned.
constexpr double kVoidDensityError = 0.1;

}  // namespace

template <int Dim>
void IsphSolver<Dim>::compute_pressure_rhs(double dt) {
  const int n = static_cast<int>(particles_.size());
  auto& P = particles_;
  const double rho0 = config_.density;
  rhs_.assign(n, 0.0);
  const bool remesh_band = remeshes() && config_.surface_remesh_alpha_s > 0.0;
  const double band_depth = config_.surface_remesh_rows + 4;
  const Vec<Dim> up = remesh_band ? Vec<Dim>(-config_.gravity.normalized()) : Vec<Dim>::Zero();
  const bool solids = remesh_band && has_solids();
  // alpha_s / dt^2 in the PPE relaxes a density error at the rate alpha_s / dt: a relaxation time
  // keeps that rate whatever the step.
  const double alpha_s = config_.density_relaxation_time > 0.0
                             ? dt / config_.density_relaxation_time
                             : config_.alpha_s;
#pragma omp parallel for schedule(static)
  for (int i = first_; i < last_; ++i) {
    if (P.kind[i] == kWall) continue;
    // A forcing zone's rows take the source too, though no pressure moves their particles: it
    // moves the fluid around the zone, and that is what keeps the zone's spacing. The pumped flux
    // is the zone's particles per unit area times v_in; without the source their spacing drifted
    // under the pressure drop the pump works against, by an amount that grew with the step (the
    // reduced erosion layer at 2 cm/s passed 0.88 of the pumped flux at 5e-4 s, 0.98 at 1e-4 s).
    const double density_error = full_support_[i] ? 1.0 - number_density_[i] / n0_ : 0.0;
    // Under a remeshed surface: the band whose fluid has to follow the rows held flat, and any void
    // deeper down. Surface marks are confined to the remeshed rows there, so a void a body leaves
    // deep in the water gets no p = 0 rim; only this stronger density term refills it.
    const bool in_band = up.dot(P.x[i]) > surface_top_ - band_depth * P.spacing;
    const bool void_rim =
        density_error > kVoidDensityError && (!solids || solid_share(P, nb_, i) == 0.0);
    const double alpha =
        remesh_band && (in_band || void_rim) ? config_.surface_remesh_alpha_s : alpha_s;
    rhs_[i] =
        rho0 / dt * divergence(nb_, op_, u_star_, i) + alpha * rho0 * density_error / (dt * dt);
  }
  if (!decomposition_) exchange(rhs_);  // the net source is a sum over every row
  remove_net_source(P, rhs_, decomposed_share());
}

template <int Dim>
void IsphSolver<Dim>::assemble_pressure_system() {
  assemble_pressure(particles_, nb_, op_, rhs_, config_.gravity, config_.density, kernel_.h(),
                    system_, porous_.active() ? &porous_.pressure_coefficient() : nullptr,
                    surface_depth_.empty() ? nullptr : &surface_depth_, decomposed_share());
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
  const bool q_ready = decomposition_ ? have_q_ : unit_response_.size() == n;
  const bool same_pin =
      system_.pinned_id >= 0 && q_ready && system_.pinned_id == unit_response_pin_;
  if (config_.spread_pin && same_pin) pressure_ += unit_response_lambda_ * unit_response_;
  // Physical pressure scale (hydrostatic head over the box plus dynamic pressure) per row.
  const double extent = domain_.length().maxCoeff();
  const double vmax = max_speed();
  const double rows = decomposition_ ? double(decomposition_->numbering()->total) : double(n);
  const double p_scale = rho0 * (config_.gravity.norm() * extent + vmax * vmax) * std::sqrt(rows);
  const SolveStats s = linear_solver_->solve(system_.A, system_.b, pressure_, p_scale);
  // Decomposed, the solver returned the owned rows only; the pin's lambda and the corrector read
  // the halo's too.
  if (decomposition_) share_->exchange_rows(pressure_.data(), sizeof(double), n);
  stats.ppe_iterations = s.iterations;
  stats.ppe_residual = s.residual;
  timings_.stage[kStageSolveSetup] += s.setup_seconds;
  unit_response_lambda_ = 0.0;
  if (config_.spread_pin && system_.pinned_id >= 0 && std::isfinite(s.residual)) {
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
      timings_.stage[kStageSolveSetup] += u.setup_seconds;
      fresh = std::isfinite(u.residual) && u.residual <= 1e3 * config_.pressure_solver.tolerance;
      unit_response_pin_ = system_.pinned_id;
      if (!fresh) unit_response_.resize(0);
      have_q_ = fresh;
      // pinned_lambda reads q at the pin's neighbours, some of which may be in the halo.
      if (fresh && decomposition_) share_->exchange_rows(unit_response_.data(), sizeof(double), n);
    }
    if (fresh) {
      // Only the process whose rows hold the pin assembled its interior equation.
      const bool own_pin = system_.pinned >= first_ && system_.pinned < last_;
      double lambda = own_pin ? pinned_lambda(system_, unit_response_, pressure_) : 0.0;
      if (blocked_) lambda = share_->sum(lambda);
      pressure_ -= lambda * unit_response_;
      unit_response_lambda_ = lambda;
    }
  }
  if (s.broke_down || !std::isfinite(s.residual) ||
      s.residual > 1e3 * config_.pressure_solver.tolerance)
    throw SimulationError("pressure solver failed at step " + std::to_string(steps_ + 1) +
                              ", t = " + format_number(time_, 4) + " s (relative residual " +
                              format_number(s.residual, 4) + " after " +
                              std::to_string(s.iterations) + " iterations" +
                              (s.reason.empty() ? "" : ", " + s.reason) +
                              "): reduce time.dt or check the geometry for isolated particles",
                          "pressure_solver");
  Eigen::Map<Eigen::VectorXd>(P.p.data(), n) = pressure_;
}

template void IsphSolver<2>::compute_pressure_rhs(double);
template void IsphSolver<2>::assemble_pressure_system();
template void IsphSolver<2>::solve_pressure(StepStats&);
template void IsphSolver<3>::compute_pressure_rhs(double);
template void IsphSolver<3>::assemble_pressure_system();
template void IsphSolver<3>::solve_pressure(StepStats&);

}  // namespace isph
