#include "run/fluid_run.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "block_row_share.hpp"
#include "rcb_decomposition.hpp"

namespace isphdem {

namespace {
template <int Dim>
isph::IsphConfig<Dim> with_limits(isph::IsphConfig<Dim> c, const RunSettings& s) {
  c.time_step = s.limits;
  return c;
}
}  // namespace

namespace {
int world_size() {
  int mpi = 0, ranks = 1;
  MPI_Initialized(&mpi);
  if (mpi) MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  return ranks;
}
}  // namespace

template <int Dim>
FluidRun<Dim>::FluidRun(FluidScene<Dim> scene, const RunSettings& settings)
    : settings_(settings),
      solver_(with_limits(scene.config, settings), scene.domain, std::move(scene.particles)) {
  // Under mpirun every rank holds the whole fluid; each computes its block of rows of every
  // stage (sph/row_share.hpp) where the pressure solver is distributed too (amg).
  const int ranks = world_size();
  if (ranks > 1) solver_.share_rows(std::make_shared<isph::BlockRowShare>(MPI_COMM_WORLD));
  if (scene.split) {
    if (!decomposes(settings_, solver_.config().pressure_solver.preconditioner, ranks))
      throw std::logic_error("FluidRun: a split scene for a run that is not decomposed");
    decompose_now(true);
  }
  if (settings_.fixed_dt) {
    const auto l = solver_.limits();  // over all ranks when decomposed
    if (*settings_.fixed_dt > l.min()) {
      std::ostringstream m;
      m << "time.dt = " << *settings_.fixed_dt << " s is beyond the stable limit " << l.min()
        << " s (" << l.limiting() << " limit; CFL " << l.cfl << ", viscous " << l.viscous
        << ", force " << l.force << " s): set time.dt below " << l.min()
        << (settings_.coupled ? " and [dem] substeps with it (time.dt = substeps x the DEM step)"
                              : " or use \"auto\"");
      throw CaseError(m.str());
    }
  }
}

template <int Dim>
bool FluidRun<Dim>::decomposes(const RunSettings& settings, const std::string& preconditioner,
                               int ranks) {
  return ranks > 1 && preconditioner == "amg" && settings.decompose.value_or(true);
}

template <int Dim>
bool FluidRun<Dim>::decompose() {
  if (solver_.decomposed()) return true;  // a split scene, decomposed at construction
  const int ranks = world_size();
  const bool distributed = solver_.config().pressure_solver.preconditioner == "amg";
  if (ranks == 1 || !settings_.decompose.value_or(distributed)) return false;
  if (!distributed)
    throw CaseError(
        "parallel.decompose = true needs the pressure solved over the ranks: set "
        "solver.preconditioner = \"amg\" (or parallel.decompose = false)");
  decompose_now(false);
  return true;
}

template <int Dim>
void FluidRun<Dim>::decompose_now(bool split) {
  try {
    solver_.decompose(
        std::make_shared<isph::RcbDecomposition<Dim>>(MPI_COMM_WORLD, solver_.domain()), split);
  } catch (const isph::SimulationError& e) {
    throw CaseError(e.what());
  }
}

template <int Dim>
double FluidRun<Dim>::kinetic_energy() const {
  const auto& P = solver_.particles();
  double ke = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] != isph::kWall)
      ke += 0.5 * solver_.config().density * P.volume * P.v[i].squaredNorm();
  const isph::RowShare* ranks = solver_.decomposition();
  return ranks ? ranks->sum(ke) : ke;
}

template <int Dim>
double FluidRun<Dim>::next_dt() const {
  if (settings_.fixed_dt) return *settings_.fixed_dt;
  return std::min(solver_.limits().min(), settings_.max_dt);
}

template <int Dim>
isph::StepStats FluidRun<Dim>::advance() {
  return solver_.step(next_dt());
}

template <int Dim>
void FluidRun<Dim>::run_until(double t,
                              const std::function<void(const isph::StepStats&)>& after_step) {
  // A relative tolerance keeps round-off from adding one tiny extra step.
  while (solver_.time() < t * (1.0 - 1e-12)) {
    double dt = next_dt();
    if (!settings_.fixed_dt) {
      // Land exactly on t with equal steps rather than one short last step: the stabilised PPE's
      // density term scales as 1/dt^2, so a sliver of a step would kick the pressure.
      const double rest = t - solver_.time();
      dt = rest / std::ceil(rest / dt - 1e-9);
    }
    const isph::StepStats s = solver_.step(dt);
    if (after_step) after_step(s);
  }
}

template class FluidRun<2>;
template class FluidRun<3>;

}  // namespace isphdem
