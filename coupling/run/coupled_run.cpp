#include "run/coupled_run.hpp"

#include <mpi.h>
#include <omp.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

#include "dem/dem_case_config.hpp"
#include "format_number.hpp"
#include "run/grain_overlap.hpp"
#include "stopwatch.hpp"

namespace isphdem {

namespace {

using isph::Stopwatch;

}  // namespace

template <int Dim>
CoupledRun<Dim>::CoupledRun(FluidScene<Dim> scene, const RunSettings& settings, DemBackend& backend,
                            int substeps, std::vector<std::unique_ptr<CouplingStage<Dim>>> stages,
                            DemExchange exchange)
    : fluid_(std::move(scene), settings),
      backend_(backend),
      substeps_(substeps),
      dt_(settings.fixed_dt.value_or(0.0)),
      stages_(std::move(stages)),
      exchange_(exchange),
      energy_(0.1 * fluid_.solver().particles().spacing / (dt_ > 0 ? dt_ : 1.0)) {
  timings_.staggered = exchange_ == DemExchange::staggered;
  if (timings_.staggered) {
    int level = MPI_THREAD_SINGLE;
    MPI_Query_thread(&level);
    if (level < MPI_THREAD_MULTIPLE)
      throw CaseError(
          "dem.exchange = \"staggered\" steps LIGGGHTS on a thread of its own beside the "
          "fluid, and both call MPI: this process's MPI was started without "
          "MPI_THREAD_MULTIPLE. Use dem.exchange = \"sequential\", or an MPI built with "
          "thread support (ompi_info | grep -i thread)");
  }
  // The DEM advances a whole number of its own steps per fluid step, so an automatic fluid dt
  // (changing every step) cannot be honoured.
  if (!settings.fixed_dt)
    throw CaseError("a coupled case needs a fixed fluid step: set time.dt = substeps x DEM dt = " +
                    std::to_string(substeps * backend.timestep()) + " s (not \"auto\")");
  try {
    check_fluid_dt(dt_, substeps_, backend.timestep());
  } catch (const std::runtime_error& e) {
    throw CaseError(e.what());
  }
  const DemState& state = backend_.state();
  for (auto& s : stages_) {
    try {
      s->initialize(state, fluid_.solver());
    } catch (const std::runtime_error& e) {
      throw CaseError(s->name() + " coupling: " + e.what());
    }
  }
}

template <int Dim>
isph::StepStats CoupledRun<Dim>::fluid_step(const DemState& state, DemLoads& loads) {
  auto& solver = fluid_.solver();
  isph::StepStats stats;
  {
    Stopwatch w(timings_.coupling);
    for (auto& s : stages_) s->move_particles(state, solver);
    solver.redistribute();  // decomposed: the stages map the particles the step will step
    for (auto& s : stages_) s->before_fluid_step(state, solver);
  }
  {
    Stopwatch w(timings_.fluid);
    stats = solver.step(dt_);
  }
  Stopwatch w(timings_.coupling);
  loads = DemLoads{};
  for (auto& s : stages_) s->after_fluid_step(state, solver, dt_, loads);
  return stats;
}

template <int Dim>
void CoupledRun<Dim>::hand_loads_to_dem(const DemLoads& loads) {
  backend_.set_atom_loads(loads.atom_tags, loads.atom_force, loads.atom_torque);
  backend_.set_body_loads(loads.body_ids, loads.body_force, loads.body_torque);
  backend_.advance(substeps_);
}

template <int Dim>
isph::StepStats CoupledRun<Dim>::advance() {
  if (exchange_ == DemExchange::staggered && have_loads_) return advance_staggered();
  const DemState& state = backend_.state();
  atoms_before_ = state.atoms;
  const isph::StepStats stats = fluid_step(state, loads_);
  have_loads_ = true;
  {
    Stopwatch w(timings_.dem);
    hand_loads_to_dem(loads_);
  }
  check_grains();
  return stats;
}

// The DEM steps from t to t + dt with the loads of the fluid step that ended at t, on a thread
// of its own, while the fluid steps from t to t + dt with the grains as they are at t: the two
// halves of a sequential step, each on a core. The fluid's thread writes nothing the DEM's
// reads (loads_ is replaced only after the join, the fluid sees a copy of the state), and
// LIGGGHTS is called from one thread at a time. While LIGGGHTS runs it holds the process's
// stdout on its screen file (LiggghtsStdoutToScreen): what the fluid's step printed on stdout
// then would land there; it prints its warnings on stderr.
template <int Dim>
isph::StepStats CoupledRun<Dim>::advance_staggered() {
  const DemState state = backend_.state();  // a copy: the DEM moves on while the fluid uses it
  atoms_before_ = state.atoms;
  std::exception_ptr dem_error;
  double dem_seconds = 0.0;
  std::thread dem([&] {
    try {
      Stopwatch w(dem_seconds);
      hand_loads_to_dem(loads_);
    } catch (...) {
      dem_error = std::current_exception();
    }
  });
  DemLoads next;
  isph::StepStats stats;
  try {
    stats = fluid_step(state, next);
  } catch (...) {
    dem.join();  // the DEM's error, if any, is the later one: the fluid's is said
    throw;
  }
  {
    Stopwatch w(timings_.dem_wait);
    dem.join();
  }
  timings_.dem += dem_seconds;
  if (dem_error) std::rethrow_exception(dem_error);
  loads_ = std::move(next);
  check_grains();
  return stats;
}

template <int Dim>
void CoupledRun<Dim>::check_grains() {
  const DemState& now = backend_.state();
  check_no_grain_lost(now);
  check_overlap(now);
  check_energy(now);
}

template <int Dim>
void CoupledRun<Dim>::check_overlap(const DemState& now) {
  const GrainOverlap o = deepest_overlap(now);
  max_overlap_ = o.relative;
  if (o.relative <= kMaxGrainOverlap) return;
  const double t1 = fluid_.solver().time(), t0 = t1 - dt_;
  throw isph::SimulationError(
      "grains " + std::to_string(o.tag_a) + " and " + std::to_string(o.tag_b) + " overlap by " +
          isph::format_number(100 * o.relative, 3) +
          "% of the smaller radius after the DEM steps " +
          "between t = " + isph::format_number(t0, 6) + " and " + isph::format_number(t1, 6) +
          " s (a contact that resolves its collision stays far below " +
          isph::format_number(100 * kMaxGrainOverlap, 3) +
          "%): the DEM time step is too long for the contact stiffness. Shorten the DEM "
          "timestep (a tenth of the contact time or less) and raise [dem] substeps with it, or "
          "look for a load that drives grains into each other",
      "grain_overlap");
}

template <int Dim>
void CoupledRun<Dim>::check_energy(const DemState& now) {
  const auto grown = energy_.observe(grain_mean_square_speed(now));
  if (!grown) return;
  const double t1 = fluid_.solver().time();
  const double dx = fluid_.solver().particles().spacing;
  throw isph::SimulationError(
      "the grains' kinetic energy grew " + isph::format_number(grown->now / grown->before, 3) +
          " times from one window of " + std::to_string(kEnergyGrowthWindow) +
          " fluid steps to the next, up to t = " + isph::format_number(t1, 6) +
          " s, and at least " + isph::format_number(kEnergyGrowthFactor, 3) + " times for the " +
          std::to_string(kEnergyGrowthWindow) + " steps before (largest mean grain speed " +
          isph::format_number(std::sqrt(grown->before), 3) + " -> " +
          isph::format_number(std::sqrt(grown->now), 3) +
          " m/s, against dx/dt = " + isph::format_number(dx / dt_, 3) +
          " m/s): the exchange between fluid and grains is unstable at this step. Shorten "
          "time.dt (and [dem] substeps with it, keeping the DEM step), and check that the grains' "
          "drag response time m/K and, for resolved bodies, their mass against the fluid they "
          "displace are resolved by it (docs/study.md, where each method fails)",
      "energy_growth");
}

template <int Dim>
void CoupledRun<Dim>::check_no_grain_lost(const DemState& now) const {
  if (now.atoms.size() >= atoms_before_.size()) return;  // grains may be inserted, not lost
  // Both lists are sorted by tag: the first tag of before that now lacks is a lost grain.
  std::size_t k = 0;
  const DemAtom* lost = nullptr;
  for (const DemAtom& a : atoms_before_) {
    while (k < now.atoms.size() && now.atoms[k].tag < a.tag) ++k;
    if (k == now.atoms.size() || now.atoms[k].tag != a.tag) {
      lost = &a;
      break;
    }
  }
  auto vec = [](const Vec3& v) { return isph::format_vector(v); };
  const double t1 = fluid_.solver().time(), t0 = t1 - dt_;
  const std::size_t n = atoms_before_.size() - now.atoms.size();
  std::string what = n == 1 ? "a grain" : std::to_string(n) + " grains";
  std::string where;
  if (lost) {
    what = n == 1 ? "grain " + std::to_string(lost->tag)
                  : what + " (among them grain " + std::to_string(lost->tag) + ")";
    where = " (last seen at " + vec(lost->x) + " m, moving at " + vec(lost->v) + " m/s)";
  }
  throw isph::SimulationError(
      what + " left the DEM simulation between t = " + isph::format_number(t0, 6) + " and " +
          isph::format_number(t1, 6) + " s" + where +
          ": LIGGGHTS drops a grain that crosses a fixed (f) boundary of its box without an error. "
          "Enlarge the box (region/create_box in the DEM script) or close it with walls, and check "
          "what drove the grain there (a fluid time step too large for the drag, a wrong initial "
          "velocity)",
      "grain_lost");
}

template <int Dim>
void CoupledRun<Dim>::run_until(double t,
                                const std::function<void(const isph::StepStats&)>& after_step) {
  while (fluid_.solver().time() < t * (1.0 - 1e-9)) {
    const isph::StepStats s = advance();
    if (after_step) after_step(s);
  }
}

namespace {

void put_vectors(StageState& s, const std::string& name, const std::vector<Vec3>& v) {
  auto& out = s[name];
  out.clear();
  for (const Vec3& x : v) out.insert(out.end(), x.begin(), x.end());
}

const std::vector<double>& entry(const StageState& s, const std::string& name) {
  const auto it = s.find(name);
  if (it == s.end())
    throw std::runtime_error("coupled run: the checkpoint holds no '" + name + "'");
  return it->second;
}

std::vector<Vec3> get_vectors(const StageState& s, const std::string& name, std::size_t n) {
  const std::vector<double>& v = entry(s, name);
  if (v.size() != 3 * n)
    throw std::runtime_error("coupled run: '" + name + "' does not fit its ids");
  std::vector<Vec3> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  return out;
}

}  // namespace

template <int Dim>
void CoupledRun<Dim>::save(StageState& s) const {
  s["atom_tags"].assign(loads_.atom_tags.begin(), loads_.atom_tags.end());
  put_vectors(s, "atom_force", loads_.atom_force);
  put_vectors(s, "atom_torque", loads_.atom_torque);
  s["body_ids"].assign(loads_.body_ids.begin(), loads_.body_ids.end());
  put_vectors(s, "body_force", loads_.body_force);
  put_vectors(s, "body_torque", loads_.body_torque);
  s["max_overlap"] = {max_overlap_};
  s["energy"] = energy_.state();
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    StageState own;
    stages_[k]->save(own);
    for (auto& [name, v] : own) s["stage" + std::to_string(k) + "_" + name] = std::move(v);
  }
}

template <int Dim>
void CoupledRun<Dim>::restore(const StageState& s) {
  DemLoads l;
  for (double t : entry(s, "atom_tags")) l.atom_tags.push_back(int(t));
  l.atom_force = get_vectors(s, "atom_force", l.atom_tags.size());
  l.atom_torque = get_vectors(s, "atom_torque", l.atom_tags.size());
  for (double b : entry(s, "body_ids")) l.body_ids.push_back(int(b));
  l.body_force = get_vectors(s, "body_force", l.body_ids.size());
  l.body_torque = get_vectors(s, "body_torque", l.body_ids.size());
  loads_ = std::move(l);
  have_loads_ = true;  // staggered: the next DEM substeps take these, as in the run saved
  max_overlap_ = entry(s, "max_overlap").at(0);
  energy_.restore(entry(s, "energy"));
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    const std::string prefix = "stage" + std::to_string(k) + "_";
    StageState own;
    for (const auto& [name, v] : s)
      if (name.compare(0, prefix.size(), prefix) == 0) own[name.substr(prefix.size())] = v;
    stages_[k]->restore(own);
  }
}

template class CoupledRun<2>;
template class CoupledRun<3>;

}  // namespace isphdem
