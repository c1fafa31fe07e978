// The coupled driver: one DemBackend, one IsphSolver and a list of CouplingStages, advanced
// together one fluid step at a time in the sequence of coupling_stage.hpp (DESIGN.md decision
// 2). The fluid step is fixed and must equal `substeps` DEM steps. Stages are independent of
// each other, so a resolved (PMS) stage is added next to the unresolved one by appending it.
#ifndef ISPHDEM_COUPLED_RUN_HPP
#define ISPHDEM_COUPLED_RUN_HPP

#include <memory>
#include <vector>

#include "coupling_stage.hpp"
#include "dem/dem_backend.hpp"
#include "dem/dem_case_config.hpp"
#include "run/energy_growth.hpp"
#include "run/fluid_run.hpp"

namespace isphdem {

// Wall seconds spent per part of the coupled step. Staggered (DemExchange), `dem` is the DEM
// thread's own time, spent beside coupling and fluid; `dem_wait` is what the fluid's thread
// waited for it at the end of its step, and the run's wall time is coupling + fluid + dem_wait.
struct CoupledTimings {
  double dem = 0, coupling = 0, fluid = 0, dem_wait = 0;
  bool staggered = false;
  double total() const { return staggered ? coupling + fluid + dem_wait : dem + coupling + fluid; }
};

template <int Dim>
class CoupledRun {
 public:
  // The backend must be initialized. Checks settings.fixed_dt == substeps x DEM dt (throws
  // CaseError naming both and the matching values) and calls every stage's initialize().
  // Staggered needs MPI_THREAD_MULTIPLE (CaseError otherwise) and, on several ranks, a backend
  // on a communicator of its own: the DEM's collectives run beside the fluid's.
  CoupledRun(FluidScene<Dim> scene, const RunSettings& settings, DemBackend& backend, int substeps,
             std::vector<std::unique_ptr<CouplingStage<Dim>>> stages,
             DemExchange exchange = DemExchange::sequential);

  // One fluid step of dt with the exchange before and after, then `substeps` DEM steps
  // (staggered: the DEM's substeps beside the fluid step, with the last step's loads; the first
  // step after start, with no loads yet, is sequential). Throws
  // isph::SimulationError when a grain has gone from the DEM in those substeps: LIGGGHTS drops a
  // grain that crosses a fixed boundary without a word (thermo_modify lost defaults to ignore).
  isph::StepStats advance();
  // Steps until time t is reached (the fixed dt; the last step may pass t by less than dt).
  void run_until(double t, const std::function<void(const isph::StepStats&)>& after_step = {});

  double dt() const { return dt_; }
  int substeps() const { return substeps_; }
  // FluidRun::decompose: each rank keeps its own part of the fluid, PMS bodies' particles too.
  bool decompose() { return fluid_.decompose(); }
  isph::IsphSolver<Dim>& solver() { return fluid_.solver(); }
  const isph::IsphSolver<Dim>& solver() const { return fluid_.solver(); }
  DemBackend& dem() { return backend_; }
  // The loads of the last fluid step (the hydrodynamic loads of the output): sequential, the DEM
  // has taken them; staggered, its next substeps take them.
  const DemLoads& loads() const { return loads_; }
  const std::vector<std::unique_ptr<CouplingStage<Dim>>>& stages() const { return stages_; }
  const CoupledTimings& timings() const { return timings_; }
  // The deepest overlap of two grains after the last step, a fraction of the smaller radius.
  double max_overlap() const { return max_overlap_; }
  // Between two steps (a checkpoint's part, docs/output.md): the loads handed to the DEM in the
  // last step (what the output reports for it), the deepest overlap, the energy monitor's
  // windows, and every stage's own state ("stage<k>_<name>"). restore() puts back what save()
  // gave, into a run built for the same case; the fluid and the DEM are restored apart.
  void save(StageState& state) const;
  void restore(const StageState& state);

 private:
  FluidRun<Dim> fluid_;
  DemBackend& backend_;
  int substeps_;
  double dt_;
  std::vector<std::unique_ptr<CouplingStage<Dim>>> stages_;
  DemExchange exchange_;
  bool have_loads_ = false;  // loads_ hold a fluid step's loads (staggered hands them on)
  // The fluid step from `state` (stages before, step, stages after into `loads`).
  isph::StepStats fluid_step(const DemState& state, DemLoads& loads);
  void hand_loads_to_dem(const DemLoads& loads);
  isph::StepStats advance_staggered();
  // After the DEM substeps, the three checks below on the grains as they are now.
  void check_grains();
  void check_no_grain_lost(const DemState& now) const;
  // Throws isph::SimulationError (cause "grain_overlap") past kMaxGrainOverlap.
  void check_overlap(const DemState& now);
  // Throws isph::SimulationError (cause "energy_growth") when the grains' kinetic energy grows
  // faster than the step resolves (energy_growth.hpp).
  void check_energy(const DemState& now);

  DemLoads loads_;
  CoupledTimings timings_;
  std::vector<DemAtom> atoms_before_;  // the grains at the start of the step, by tag
  double max_overlap_ = 0.0;
  EnergyGrowthMonitor energy_;
};

}  // namespace isphdem

#endif
