#pragma once
// Stabilised ISPH (Asai et al. 2012) on the unified equations. One step (step(), isph_solver.cpp):
//   neighbours, pair geometry, operator weights (once, reused below)  step_neighbors.cpp
//   free-surface marking, full-support flags                          step_free_surface.cpp
//   predictor  u* = u + dt (nu lap u + g)                             step_predictor.cpp
//   pressure   lap p = rho0/dt div u* + alpha_s (rho0 - rho_i)/dt^2   step_pressure.cpp
//   corrector  u = u* - dt/rho0 grad p, advection x += dt u            step_correction.cpp
//   particle shifting                                                 step_shifting.cpp
// In porous regions (eps < 1 or K > 0 on some particle) the predictor, the PPE coefficient and
// the corrector take the Darcy-Brinkman form of porous_medium.hpp.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "decomposition.hpp"
#include "domain.hpp"
#include "free_surface.hpp"
#include "kernel.hpp"
#include "linear_solver.hpp"
#include "neighbors.hpp"
#include "operators.hpp"
#include "particles.hpp"
#include "porous_medium.hpp"
#include "pressure_equation.hpp"
#include "row_share.hpp"
#include "shifting.hpp"
#include "step_carry.hpp"
#include "stopwatch.hpp"
#include "time_step.hpp"

namespace isph {

enum class WallSlip { NoSlip, FreeSlip };

// A region whose fluid particles are driven at a prescribed velocity (kind kForcing while
// inside), like the seed's upward inflow under the soil layer. They take part in the pressure
// equation like fluid, so the flow around them stays divergence-free, but the pressure does not
// change their velocity: the zone acts as an ideal pump.
template <int Dim>
struct ForcingZone {
  Vec<Dim> lo = Vec<Dim>::Zero(), hi = Vec<Dim>::Zero();
  Vec<Dim> velocity = Vec<Dim>::Zero();
  // Start-up time [s]: the velocity eases in as (1 - cos(pi t / ramp)) / 2. Switching the pump
  // on in one step gives the whole loop an impulse that rings the tank's sloshing modes, and
  // the contact lines then move along the walls for the rest of the run.
  double ramp = 0.0;
  Vec<Dim> velocity_at(double t) const {
    if (!(ramp > 0.0) || t >= ramp) return velocity;
    return 0.5 * (1.0 - std::cos(M_PI * t / ramp)) * velocity;
  }
  bool contains(const Vec<Dim>& x) const {
    return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
  }
};

template <int Dim>
struct IsphConfig {
  double smoothing_ratio = 1.3;  // h / dx
  KernelType kernel = KernelType::WendlandC2;
  double density = 1000.0;              // rho0 [kg/m^3]
  double viscosity = 1e-6;              // kinematic nu [m^2/s]
  Vec<Dim> gravity = Vec<Dim>::Zero();  // body acceleration [m/s^2], gravity plus any driving force
  // Density-invariance relaxation of the stabilised PPE. Its stiffness grows as 1/dt^2: 0.01 left
  // Poiseuille rows jittering by 0.2 dx at the viscous dt; 0.001 keeps the L2 error at 0.2%.
  double alpha_s = 0.001;
  bool free_surface = true;
  // Closed or periodic boxes: spread what the pinned pressure row would absorb over all rows
  // (spread_pinned_source, sph/pressure_equation.hpp); costs a second, looser solve every 10th
  // step.
  bool spread_pin = true;
  SurfaceCriteria surface;
  // With gravity: a free-surface particle below the line of its surface neighbours (a second-row
  // particle exposed by a gap in a stretched top row) gets the hydrostatic pressure of its depth
  // (surface_depth) instead of p = 0, and is shifted up onto that line (at most the shifting cap
  // per step) when nothing lies directly above it; particles not on the surface then shift
  // freely. p = 0 half a spacing below the row kicked such particles up at 20-40 mm/s in the
  // circulation tank, whose flow is 5 mm/s. Off by default: it moves the tank's break-up from
  // 1.33 s to 1.87 s, not to the 10 s (docs/fluid.md, "Known limitations").
  bool surface_refill = false;
  // Remeshing of the top rows of a nearly flat free surface (sph/surface_remesh.hpp): this many
  // rows, every surface_remesh_every steps; 0 turns it off. Needs gravity; not decomposed.
  int surface_remesh_rows = 0;
  int surface_remesh_every = 50;
  // alpha_s in the band from the remeshed top row down to rows + 4 spacings under it, where the
  // fluid has to follow the rows held flat, and at any void deeper down (number density 10% under
  // n0, no PMS particle in the support), which no p = 0 rim closes under the remesh; 0: alpha_s
  // there too.
  double surface_remesh_alpha_s = 0.0;
  // Smagorinsky eddy viscosity nu_T = (C_s dx)^2 sqrt(2 S:S), added to nu in the viscous term.
  bool smagorinsky = false;
  double smagorinsky_constant = 0.1;
  WallSlip wall = WallSlip::NoSlip;
  // No-slip ghost velocities of walls and PMS solids for the viscous term
  // (IsphSolver::compute_wall_ghosts): false extrapolates the fluid's velocity linearly through
  // the surface, true fits u = v_w + a s + b s^2 along the normal (s the height above the
  // surface), which is exact for the parabolic profile of a narrow gap.
  bool quadratic_wall_ghosts = false;
  // Closest a fluid particle may come to a wall surface, in spacings (the first fluid layer sits
  // at 0.5).
  double min_wall_distance = 0.25;
  // Fluid particles whose support is more than this share PMS solid follow the solids
  // (sph/pocket_fluid.hpp); 1 turns it off.
  double pocket_solid_fraction = 0.5;
  // PMS rows in the projection (sph/rigid_solids.hpp). true: u* = v + dt c grad p^n / rho, so
  // that the body moves rigidly through the projection while the pressure is steady and only
  // its change per step moves it (the pressure-increment form, as for the forcing zone). false:
  // the fluid predictor's u* = v + dt (nu lap u + g), with which the projection let the body's
  // rows move as fluid by dt (g - grad p / rho) a step: the body leaked like a porous block of
  // resistance 1/dt (a square array of cylinders carried 5.6% more flow at the viscous step
  // than at 1/16 of it; docs/resolved.md, "Time step").
  bool pms_pressure_increment = true;
  // Density-invariance relaxation time [s]: when positive, alpha_s = dt / tau in the PPE, so
  // that a density error relaxes at the rate 1/tau whatever the step (alpha_s / dt^2 in the PPE
  // is a rate of alpha_s / dt). 0: alpha_s as given. docs/fluid.md, "Time step".
  double density_relaxation_time = 0.0;
  std::vector<ForcingZone<Dim>> forcing;
  ShiftingParams shifting;
  TimeStepParams time_step;
  LinearSolverConfig pressure_solver;
};

// Stops a run with a message naming the cause and the fix. `cause` is the same in one word, for
// result.json and the stability map of a study: "nan", "cfl", "pressure_solver", "porosity",
// "fluid_left_domain", "grain_lost", "grain_overlap", "energy_growth" or "other".
class SimulationError : public std::runtime_error {
 public:
  explicit SimulationError(const std::string& what, std::string cause = "other")
      : std::runtime_error(what), cause_(std::move(cause)) {}
  const std::string& cause() const { return cause_; }

 private:
  std::string cause_;
};

// The stages of a step, in the order they run: the finer split of StepTimings (bench/fluid).
enum StepStage : int {
  kStageNeighbors,   // sort by cell, neighbour lists with r_ij, W, grad W
  kStageSurface,     // free-surface detection
  kStageOperators,   // corrected operator weights
  kStagePredictor,   // wall ghosts, eddy viscosity, predictor, wall u*, full-support marks
  kStageRhs,         // the PPE's right-hand side
  kStageAssembly,    // the PPE's matrix
  kStageSolveSetup,  // the preconditioner's setup (ILU factors, AMG hierarchy)
  kStageSolveIterations,
  kStageCorrection,  // pressure gradient, PMS loads, pocket blend
  kStageShifting,
  kStageAdvection,  // close pairs, positions
  kStageOther,      // surface remesh, forcing-zone kinds, the halo, state checks
  kStageCount
};
const char* step_stage_name(int stage);  // "neighbours", "free_surface", ...

struct StepTimings {
  double stage[kStageCount] = {};  // seconds by StepStage
  // Exchanging rows between processes (sph/row_share.hpp), inside the stages' times.
  double exchange = 0;
  // The coarse parts of the `time per part` line (bench/fluid/run_taylor_green.sh reads it);
  // kStageOther is in none of them.
  double neighbors() const { return stage[kStageNeighbors]; }
  double operators() const { return stage[kStageSurface] + stage[kStageOperators]; }
  double assembly() const { return stage[kStageAssembly]; }
  double solve_setup() const { return stage[kStageSolveSetup]; }
  double solve() const { return stage[kStageSolveSetup] + stage[kStageSolveIterations]; }
  double rest() const {
    return stage[kStagePredictor] + stage[kStageRhs] + stage[kStageCorrection] +
           stage[kStageShifting] + stage[kStageAdvection];
  }
  double total() const { return neighbors() + operators() + assembly() + solve() + rest(); }
};

struct StepStats {
  double dt = 0.0;
  int ppe_iterations = 0;
  double ppe_residual = 0.0;
  double max_speed = 0.0;
  std::size_t surface_particles = 0;
  // Fluid volume (2D: area) from the number density, sum V0 n0/n_i over fluid with full support
  // plus V0 for the rest: it shows compression or loss of volume that particle counts cannot.
  double fluid_volume = 0.0;
  double max_eddy_viscosity = 0.0;
};

template <int Dim>
class IsphSolver {
 public:
  IsphSolver(const IsphConfig<Dim>& config, const Domain<Dim>& domain, Particles<Dim> particles);

  // Limits for the current state (max speed from the present velocities).
  TimeStepLimits limits() const;
  // Advances by dt. Throws SimulationError on NaN, escape or a step far beyond the CFL limit.
  StepStats step(double dt);

  Particles<Dim>& particles() { return particles_; }
  const Particles<Dim>& particles() const { return particles_; }
  // The sum of the last step's shifts over its fluid rows: this process's own rows when the fluid
  // is decomposed, all rows otherwise. Shifts move particles besides their velocity, so the
  // particles carry sum(V v) + V shift_sum / dt, not sum(V v) (the mean-flow drive's "particles"
  // flux, coupling/unresolved/mean_flow_drive.hpp).
  const Vec<Dim>& last_shift_sum() const { return shift_sum_; }
  const Domain<Dim>& domain() const { return domain_; }
  const IsphConfig<Dim>& config() const { return config_; }
  const Kernel<Dim>& kernel() const { return kernel_; }
  const Neighbors<Dim>& neighbors() const { return nb_; }
  const Operators<Dim>& operators() const { return op_; }
  double time() const { return time_; }
  long steps() const { return steps_; }
  double max_speed() const;
  const StepTimings& timings() const { return timings_; }
  const PorousMedium<Dim>& porous() const { return porous_; }
  // Between steps: what the next step reads besides the particles (a checkpoint's part), and
  // putting it back with the particles saved with it. resume() expects the solver built from the
  // same case (and decomposed alike, each process given the particles it held); the particles
  // replace this process's, in their saved order.
  StepCarry<Dim> carry() const;
  void resume(Particles<Dim> particles, const StepCarry<Dim>& carry);
  // Body acceleration for the coming steps (a flow-rate drive adjusts it between steps).
  void set_gravity(const Vec<Dim>& g) { config_.gravity = g; }
  // Shares the rows of every step between the processes of `share` (sph/row_share.hpp). Takes
  // effect in the steps where the pressure solver is distributed over the same processes; with
  // another solver every process computes every row, as before.
  void share_rows(std::shared_ptr<const RowShare> share) { share_ = std::move(share); }
  // Decomposes the fluid over the processes of `d` (sph/decomposition.hpp): from now on this
  // process steps only the particles it owns, and particles() holds them alone between steps.
  // Every process must have been given every particle, or (split) its share of a scene built
  // with Particles::keep_parts = d's parts; collective. Needs the distributed
  // pressure solver (solver.preconditioner = "amg"). PMS solids travel between the processes
  // as fluid particles do; their bodies' loads are then each process's share (rigid_solid_loads
  // over its own particles, summed over decomposition()).
  void decompose(std::shared_ptr<Decomposition<Dim>> d, bool split = false);
  // The constructor's check of a scene: every particle starts inside the domain box (throws
  // SimulationError naming the first that does not). For a process's share of a split scene,
  // callable before the processes construct their solvers, so that all can stop together.
  static void check_inside(const Particles<Dim>& particles, const Domain<Dim>& domain);
  bool decomposed() const { return decomposition_ != nullptr; }
  // Decomposed: sends the particles that left this process's region to their owners. step()
  // does it at its start unless called since the last step: a coupled driver calls it before its
  // stages read the particles, so that they map the set the step steps. Collective; nothing to
  // do when not decomposed.
  void redistribute();
  // The processes to reduce over when the fluid is decomposed (sums and maxima of what each
  // process computed from its own particles), else null.
  const RowShare* decomposition() const { return decomposed_share(); }
  // grad p of the last step at the given rows (storage order), on every process: with shared
  // rows only the process that computed a row holds its neighbour list (neighbors()).
  // Decomposed: at this process's own rows, kept from the step (its halo is gone after it).
  std::vector<Vec<Dim>> pressure_gradient_at(const std::vector<int>& rows) const;
  // Whether the last step was computed in shared blocks of rows, and between how many processes
  // they may be shared (1 without share_rows).
  bool rows_shared() const { return blocked_; }
  int row_parts() const { return share_->parts(); }
  // This process's block of the present rows (all of them on one process): the part of every
  // per-particle output it writes, so that the processes' parts in order are the storage order.
  std::pair<std::size_t, std::size_t> own_block() const {
    const int n = static_cast<int>(particles_.size());
    return {static_cast<std::size_t>(share_->first(n)), static_cast<std::size_t>(share_->last(n))};
  }

 private:
  // The stages of step(), in order, each in the file named.
  void find_neighbors();       // step_neighbors.cpp
  void detect_free_surface();  // step_free_surface.cpp
  void confine_surface_to_remeshed_rows();
  void compute_operator_weights();  // step_neighbors.cpp
  void compute_wall_ghosts();       // step_predictor.cpp
  void fit_ghost_profiles();        // step_predictor.cpp
  bool ghost_profile(int i, Vec<Dim>& slope, Vec<Dim>& curvature) const;
  void compute_eddy_viscosity();
  void predict(double dt);
  void set_wall_u_star(double dt);
  void mark_full_support();              // step_free_surface.cpp
  void compute_pressure_rhs(double dt);  // step_pressure.cpp
  void assemble_pressure_system();
  void solve_pressure(StepStats& stats);
  void correct(double dt);                   // step_correction.cpp
  void shift(double dt);                     // step_shifting.cpp
  void advect(double dt, StepStats& stats);  // step_correction.cpp
  void update_forcing_kinds();
  void remesh_surface();  // isph_solver.cpp
  void keep_off_walls(int i);
  const ForcingZone<Dim>* zone_of(const Vec<Dim>& x) const;
  // Where the fastest particle is and what its support holds (for the CFL stop message).
  std::string describe_fastest() const;
  void check_state(const char* where) const;
  void check_cfl(double dt, const StepStats& stats) const;
  // After a stage whose rows another row's stage reads: every process gets every row.
  template <class T>
  void exchange(std::vector<T>& rows) {
    if (!blocked_) return;
    Stopwatch w(timings_.exchange);
    share_->exchange(rows);
  }
  const RowShare* block_share() const { return blocked_ ? share_.get() : nullptr; }
  // Passes over all rows that must reduce over the processes instead (decomposed fluid).
  const RowShare* decomposed_share() const { return decomposition_ ? share_.get() : nullptr; }
  // Whether the scene has PMS solids, on every process alike.
  bool has_solids() const { return decomposition_ ? solids_ : particles_.count(kSolid) > 0; }

  IsphConfig<Dim> config_;
  Domain<Dim> domain_;
  Particles<Dim> particles_;
  Kernel<Dim> kernel_;
  NeighborSearch<Dim> search_;
  std::unique_ptr<LinearSolver> linear_solver_;
  std::unique_ptr<LinearSolver> unit_solver_;  // for spread_pinned_source's q (its own setup)
  std::shared_ptr<const RowShare> share_ = std::make_shared<RowShare>();
  std::shared_ptr<Decomposition<Dim>> decomposition_;  // set: the same object as share_
  bool redistributed_ = false;                         // since the last step
  // Decomposed: whether any process holds PMS solids (decided before the split, so that every
  // process takes the solids' collective passes).
  bool solids_ = false;
  // Decomposed: whether q is valid, the same on every process (a process owning no particle
  // holds an empty q all the same).
  bool have_q_ = false;
  bool blocked_ = false;      // this step's rows are shared (share_rows)
  int first_ = 0, last_ = 0;  // the rows this process computes in this step
  double n0_ = 0.0;
  double time_ = 0.0;
  long steps_ = 0;
  StepTimings timings_;

  // Per-step work arrays, kept to avoid reallocation.
  Neighbors<Dim> nb_;
  Operators<Dim> op_;
  PressureSystem<Dim> system_;
  PorousMedium<Dim> porous_;
  std::vector<double> number_density_, divergence_r_, rhs_, eddy_viscosity_;
  std::vector<double> surface_depth_;  // empty unless surface_refill acts
  std::vector<Vec<Dim>> grad_p_;       // decomposed: the owned rows' grad p of the last step
  double max_eddy_viscosity_ = 0.0;
  std::vector<Vec<Dim>> u_star_, wall_ghost_, shift_;
  Vec<Dim> shift_sum_ = Vec<Dim>::Zero();  // last_shift_sum()
  // Quadratic ghosts: per wall or solid row the fitted slope and curvature of the fluid's velocity
  // along its normal, and whether its own fluid neighbours determined them (1) or not (0).
  std::vector<Vec<Dim>> ghost_slope_, ghost_curvature_;
  std::vector<double> ghost_fitted_;
  std::vector<Vec<Dim>> pms_u_star_;       // PMS rows: the plain predictor's u*, for their force
  std::vector<Vec<Dim>> surface_columns_;  // the lattice surface_remesh_rows remeshes onto
  bool remeshes() const { return config_.surface_remesh_rows > 0; }
  double surface_top_ = 0.0;  // height of the remeshed top row along -gravity
  std::vector<uint8_t> operator_mode_, full_support_, shift_mode_, dry_wall_;
  Eigen::VectorXd pressure_;
  Eigen::VectorXd unit_response_;      // q of spread_pinned_source, reused for a few steps
  int64_t unit_response_pin_ = -1;     // id of the particle pinned when q was solved
  double unit_response_lambda_ = 0.0;  // the last step's lambda: p was spread by -lambda q
};

}  // namespace isph
