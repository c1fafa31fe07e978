#pragma once
// Advances a fluid-only scene in time: chooses each step (auto from the stability limits, or the
// fixed time.dt after checking it against them) and reports each step to an observer. Used by
// `isphdem run` and directly by the validation tests, so both run the same code path.
#include <functional>
#include <string>

#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"

namespace isphdem {

template <int Dim>
class FluidRun {
 public:
  // A split scene (each rank its share, FluidScene::split) is decomposed here, first; the
  // construction is then collective.
  FluidRun(FluidScene<Dim> scene, const RunSettings& settings);

  // Whether decompose() will decompose a run with these settings and pressure preconditioner on
  // `ranks` ranks: the case's scene can then be built split (build_fluid_scene's parts).
  static bool decomposes(const RunSettings& settings, const std::string& preconditioner, int ranks);

  double next_dt() const;
  isph::StepStats advance();
  // Steps until time t: exactly onto t with an automatic dt (steps evened out), or with the fixed
  // dt until t is reached or passed by less than one step.
  void run_until(double t, const std::function<void(const isph::StepStats&)>& after_step = {});

  // Under mpirun, where settings.decompose asks for it (unset: where the pressure solve is
  // distributed, solver.preconditioner = "amg"; a coupled run calls it after its stages added
  // their PMS solids, which are decomposed with the fluid): from now on each rank holds and
  // steps only its part of the fluid (docs/parallel.md). Call before the first step, with the
  // same fluid on every rank (check_replicas) or a split scene; collective. Returns whether the
  // fluid is decomposed.
  bool decompose();
  // Sum of rho V |v|^2 / 2 over the fluid, over all ranks when decomposed (collective then).
  double kinetic_energy() const;

  isph::IsphSolver<Dim>& solver() { return solver_; }
  const isph::IsphSolver<Dim>& solver() const { return solver_; }
  const RunSettings& settings() const { return settings_; }

 private:
  void decompose_now(bool split);

  RunSettings settings_;
  isph::IsphSolver<Dim> solver_;
};

}  // namespace isphdem
