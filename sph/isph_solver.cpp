// The step as a list of stages, construction, and the checks that stop a run (the stages
// themselves are in step_*.cpp).
#include "isph_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "format_number.hpp"
#include "pocket_fluid.hpp"
#include "stopwatch.hpp"
#include "surface_remesh.hpp"

namespace isph {

template <int Dim>
IsphSolver<Dim>::IsphSolver(const IsphConfig<Dim>& config, const Domain<Dim>& domain,
                            Particles<Dim> particles)
    : config_(config),
      domain_(domain),
      particles_(std::move(particles)),
      kernel_(config.kernel, config.smoothing_ratio * particles_.spacing),
      search_(domain, kernel_.support()),
      linear_solver_(make_linear_solver(config.pressure_solver)),
      unit_solver_(make_linear_solver(config.pressure_solver)) {
  if (!(particles_.spacing > 0.0))
    throw SimulationError("particle spacing must be positive (particles.spacing)");
  // A process's share of a split scene (Particles::keep_parts) may be empty; the scene is not.
  if (particles_.size() == 0 && particles_.next_id == 0)
    throw SimulationError("the case creates no particles");
  if (!(config.density > 0.0)) throw SimulationError("fluid.density must be positive");
  if (config.viscosity < 0.0) throw SimulationError("fluid.viscosity must not be negative");
  check_inside(particles_, domain_);
  for (auto& x : particles_.x) domain_.wrap(x);
  n0_ = reference_number_density(kernel_, particles_.spacing);
  if (config.surface_remesh_rows > 0) {
    if (!(config.gravity.squaredNorm() > 0.0) || !config.free_surface)
      throw SimulationError(
          "solver.surface_remesh_rows needs a free surface under gravity (fluid.gravity)");
    if (config.surface_remesh_every < 1)
      throw SimulationError("solver.surface_remesh_every must be at least 1 step");
    const Vec<Dim> up = -config.gravity.normalized();
    surface_columns_ = surface_columns(particles_, up);
    surface_top_ = highest_fluid(particles_, up);
  }
}

template <int Dim>
void IsphSolver<Dim>::remesh_surface() {
  const Vec<Dim> up = -config_.gravity.normalized();
  surface_top_ = decomposition_
                     ? remesh_surface_rows_shared(particles_, kernel_, up, surface_columns_,
                                                  config_.surface_remesh_rows, *decomposition_)
                     : remesh_surface_rows(particles_, kernel_, up, surface_columns_,
                                           config_.surface_remesh_rows);
}

template <int Dim>
void IsphSolver<Dim>::check_inside(const Particles<Dim>& particles, const Domain<Dim>& domain) {
  // Periodic axes too: a block sticking out of a periodic box would wrap onto other particles.
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (((particles.x[i] - domain.lo).array() < 0.0).any() ||
        ((particles.x[i] - domain.hi).array() > 0.0).any())
      throw SimulationError("particle " + std::to_string(particles.id[i]) + " at " +
                            format_vector(particles.x[i]) +
                            " starts outside the domain box: enlarge domain.min/domain.max");
}

template <int Dim>
void IsphSolver<Dim>::decompose(std::shared_ptr<Decomposition<Dim>> d, bool split) {
  // A split scene's share holds only part of the surface: its lattice and top from all of them.
  if (remeshes() && split) {
    const Vec<Dim> up = -config_.gravity.normalized();
    surface_columns_ = surface_columns_shared(particles_, up, *d);
    surface_top_ = d->max(highest_fluid(particles_, up));
  }
  try {
    linear_solver_->number_globally(nullptr);
    unit_solver_->number_globally(nullptr);
  } catch (const std::invalid_argument& e) {
    throw SimulationError(std::string("decomposed fluid: ") + e.what());
  }
  // Over all processes: a split scene's share may hold none of the solids.
  solids_ = d->max(particles_.count(kSolid) > 0 ? 1.0 : 0.0) > 0.0;
  // Every process holds every particle: each keeps every parts-th, then all go to their owners
  // (split: each holds its share already, the same particles).
  if (!split) {
    std::vector<int> mine;
    for (int i = d->part(); i < static_cast<int>(particles_.size()); i += d->parts())
      mine.push_back(i);
    particles_.permute(mine);
    particles_.for_each_array([&](auto& a) {
      a.resize(mine.size());
      a.shrink_to_fit();  // the whole scene's memory goes back
    });
  }
  d->migrate(particles_, nullptr);
  decomposition_ = d;
  share_ = std::move(d);
  unit_response_.resize(0);
  have_q_ = false;
}

template <int Dim>
void IsphSolver<Dim>::redistribute() {
  if (!decomposition_) return;
  // q travels with the particles, as it follows them through the sort, so that it is reused as
  // on one process.
  std::vector<double> q;
  const bool carry = have_q_;
  if (carry) q.assign(unit_response_.data(), unit_response_.data() + unit_response_.size());
  decomposition_->migrate(particles_, carry ? &q : nullptr);
  if (carry) unit_response_ = Eigen::Map<const Eigen::VectorXd>(q.data(), q.size());
  redistributed_ = true;
}

template <int Dim>
StepCarry<Dim> IsphSolver<Dim>::carry() const {
  StepCarry<Dim> c;
  c.time = time_;
  c.steps = steps_;
  c.max_eddy_viscosity = max_eddy_viscosity_;
  c.surface_top = surface_top_;
  c.gravity = config_.gravity;
  c.unit_response.assign(unit_response_.data(), unit_response_.data() + unit_response_.size());
  c.unit_response_pin = unit_response_pin_;
  c.unit_response_lambda = unit_response_lambda_;
  c.have_q = have_q_;
  return c;
}

template <int Dim>
void IsphSolver<Dim>::resume(Particles<Dim> particles, const StepCarry<Dim>& c) {
  if (particles.spacing != particles_.spacing)
    throw SimulationError("resume: the saved particles have spacing " +
                          format_number(particles.spacing, 6) + " m, the case " +
                          format_number(particles_.spacing, 6) +
                          " m: resume with the case and --set options of the run");
  particles_ = std::move(particles);
  time_ = c.time;
  steps_ = c.steps;
  max_eddy_viscosity_ = c.max_eddy_viscosity;
  surface_top_ = c.surface_top;
  config_.gravity = c.gravity;
  unit_response_ = Eigen::Map<const Eigen::VectorXd>(c.unit_response.data(),
                                                     Eigen::Index(c.unit_response.size()));
  unit_response_pin_ = c.unit_response_pin;
  unit_response_lambda_ = c.unit_response_lambda;
  have_q_ = c.have_q;
  redistributed_ = false;
}

template <int Dim>
double IsphSolver<Dim>::max_speed() const {
  double m = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i)
    if (particles_.kind[i] != kWall) m = std::max(m, particles_.v[i].norm());
  return decomposition_ ? share_->max(m) : m;
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
StepStats IsphSolver<Dim>::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw SimulationError("time step must be positive");
  double* const stage = timings_.stage;
  {
    Stopwatch w(stage[kStageOther]);
    blocked_ = decomposition_ || (share_->parts() > 1 && linear_solver_->distributed_rows() &&
                                  unit_solver_->distributed_rows());
    if (!redistributed_) redistribute();
    redistributed_ = false;
    update_forcing_kinds();
    if (remeshes() && steps_ > 0 && steps_ % config_.surface_remesh_every == 0) remesh_surface();
  }
  {
    Stopwatch w(stage[kStageNeighbors]);
    find_neighbors();  // the pair geometry and weights every stage below reuses
  }
  {
    Stopwatch w(stage[kStageSurface]);
    detect_free_surface();
  }
  {
    Stopwatch w(stage[kStageOperators]);
    compute_operator_weights();
  }
  StepStats stats;
  stats.dt = dt;
  {
    Stopwatch w(stage[kStagePredictor]);
    compute_wall_ghosts();
    compute_eddy_viscosity();
    predict(dt);
    set_wall_u_star(dt);
    mark_full_support();
  }
  {
    Stopwatch w(stage[kStageRhs]);
    compute_pressure_rhs(dt);
  }
  {
    Stopwatch w(stage[kStageAssembly]);
    assemble_pressure_system();
  }
  {
    // solve_pressure adds the preconditioner's setup to its stage; the rest is iterations.
    const double setup = stage[kStageSolveSetup];
    const double t0 = omp_get_wtime();
    solve_pressure(stats);
    stage[kStageSolveIterations] += omp_get_wtime() - t0 - (stage[kStageSolveSetup] - setup);
  }
  {
    Stopwatch w(stage[kStageCorrection]);
    correct(dt);
    if (has_solids() && follow_enclosing_solids(particles_, nb_, config_.pocket_solid_fraction,
                                                config_.density, dt, block_share()) > 0)
      exchange(particles_.v);  // the blended rows (the count is over all processes)
  }
  {
    Stopwatch w(stage[kStageShifting]);
    shift(dt);
  }
  {
    Stopwatch w(stage[kStageAdvection]);
    advect(dt, stats);
  }
  Stopwatch w(stage[kStageOther]);
  if (decomposition_) {
    grad_p_.resize(last_);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < last_; ++i) grad_p_[i] = gradient(nb_, op_, particles_.p, i);
    decomposition_->drop_halo(particles_);
    if (have_q_) unit_response_.conservativeResize(static_cast<Eigen::Index>(particles_.size()));
  }
  time_ += dt;
  ++steps_;
  check_state("after the step");
  check_cfl(dt, stats);
  return stats;
}

const char* step_stage_name(int stage) {
  static const char* const names[kStageCount] = {
      "neighbours",  "free_surface",     "operators",  "predictor", "pressure_rhs", "assembly",
      "solve_setup", "solve_iterations", "correction", "shifting",  "advection",    "other"};
  return stage >= 0 && stage < kStageCount ? names[stage] : "";
}

template <int Dim>
void IsphSolver<Dim>::check_cfl(double dt, const StepStats& stats) const {
  if (dt * stats.max_speed > particles_.spacing)
    throw SimulationError(
        "time step far beyond the CFL limit at t = " + format_number(time_, 4) +
            " s: dt = " + format_number(dt, 4) + " s moved particles " +
            format_number(dt * stats.max_speed / particles_.spacing, 4) +
            " spacings in one step (max |u| = " + format_number(stats.max_speed, 4) +
            " m/s); use a dt below " + format_number(limits().min(), 4) +
            " s (time.dt = \"auto\" in a fluid-only case; a coupled case needs time.dt and [dem] "
            "substeps changed together) or find what accelerates the flow this much; " +
            describe_fastest(),
        "cfl");
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
  static const char* const names[] = {"fluid", "wall", "solid (PMS)", "forcing-zone"};
  const std::string fastest = fast < 0 ? std::string("no moving particle")
                                       : std::string("the fastest is ") + names[P.kind[fast]] +
                                             " particle " + std::to_string(P.id[fast]) + " at " +
                                             format_vector(P.x[fast]) + " m (" +
                                             format_number(P.v[fast].norm(), 4) + " m/s)";
  if (decomposition_) {
    // Each process knows its own fastest: the fastest of all is named (collective).
    const double mine = fast < 0 ? -1.0 : P.v[fast].norm();
    const double best = share_->max(mine);  // on every process, before the test below
    const std::string named =
        share_->first_text(fast >= 0 && mine == best ? fastest : std::string());
    return named.empty() ? fastest : named;
  }
  if (fast < 0) return fastest;
  if (fast < first_ || fast >= last_) return fastest;  // its neighbours were listed elsewhere
  // The neighbour list is the step's own (built before the particles moved): what the fastest
  // particle's equations saw. A fluid particle whose support is mostly solid sits in a pocket
  // between bodies (the semi-resolved erosion runs broke up from one).
  int count[4] = {0, 0, 0, 0};
  for (int k = nb_.begin(fast); k < nb_.end(fast); ++k) ++count[P.kind[nb_.index[k]]];
  return fastest + " with " + std::to_string(count[kFluid] + count[kForcing]) + " fluid, " +
         std::to_string(count[kSolid]) + " solid and " + std::to_string(count[kWall]) +
         " wall neighbours";
}

template <int Dim>
void IsphSolver<Dim>::check_state(const char* where) const {
  const auto& P = particles_;
  std::string failure, cause;
  for (std::size_t i = 0; i < P.size() && failure.empty(); ++i) {
    if (!P.x[i].allFinite() || !P.v[i].allFinite() || !std::isfinite(P.p[i])) {
      failure = "non-finite value (NaN/inf) in particle " + std::to_string(P.id[i]) + " " + where +
                " at t = " + format_number(time_, 4) +
                " s: the run became unstable; reduce time.dt (or use \"auto\")";
      cause = "nan";
    } else if (P.kind[i] != kWall && !domain_.contains(P.x[i])) {
      failure = "fluid particle " + std::to_string(P.id[i]) + " left the domain at " +
                format_vector(P.x[i]) + ", t = " + format_number(time_, 4) +
                " s: close the container with walls or enlarge domain.min/max";
      cause = "fluid_left_domain";
    }
  }
  // Decomposed, the particle is on one process only: every process stops with its message (the
  // lowest such process's), so that none waits for the others in the next step.
  if (decomposition_) {
    const std::string first = share_->first_text(failure.empty() ? "" : cause + '\n' + failure);
    if (first.empty()) return;
    cause = first.substr(0, first.find('\n'));
    failure = first.substr(first.find('\n') + 1);
  }
  if (!failure.empty()) throw SimulationError(failure, cause);
}

template class IsphSolver<2>;
template class IsphSolver<3>;

}  // namespace isph
