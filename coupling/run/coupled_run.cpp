#include "run/coupled_run.hpp"

#include <omp.h>

#include <stdexcept>

#include "dem/dem_case_config.hpp"
#include "stopwatch.hpp"

namespace isphdem {

namespace {

using isph::Stopwatch;

}  // namespace

template <int Dim>
CoupledRun<Dim>::CoupledRun(FluidScene<Dim> scene, const RunSettings& settings, DemBackend& backend,
                            int substeps, std::vector<std::unique_ptr<CouplingStage<Dim>>> stages)
    : fluid_(std::move(scene), settings),
      backend_(backend),
      substeps_(substeps),
      dt_(settings.fixed_dt.value_or(0.0)),
      stages_(std::move(stages)) {
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
isph::StepStats CoupledRun<Dim>::advance() {
  auto& solver = fluid_.solver();
  isph::StepStats stats;
  {
    Stopwatch w(timings_.coupling);
    const DemState& state = backend_.state();
    for (auto& s : stages_) s->before_fluid_step(state, solver);
  }
  {
    Stopwatch w(timings_.fluid);
    stats = solver.step(dt_);
  }
  {
    Stopwatch w(timings_.coupling);
    const DemState& state = backend_.state();
    loads_ = DemLoads{};
    for (auto& s : stages_) s->after_fluid_step(state, solver, dt_, loads_);
  }
  Stopwatch w(timings_.dem);
  backend_.set_atom_loads(loads_.atom_tags, loads_.atom_force, loads_.atom_torque);
  backend_.set_body_loads(loads_.body_ids, loads_.body_force, loads_.body_torque);
  backend_.advance(substeps_);
  return stats;
}

template <int Dim>
void CoupledRun<Dim>::run_until(double t,
                                const std::function<void(const isph::StepStats&)>& after_step) {
  while (fluid_.solver().time() < t * (1.0 - 1e-9)) {
    const isph::StepStats s = advance();
    if (after_step) after_step(s);
  }
}

template class CoupledRun<2>;
template class CoupledRun<3>;

}  // namespace isphdem
