#pragma once
// Advances a fluid-only scene in time: chooses each step (auto from the stability limits, or the
// fixed time.dt after checking it against them) and reports each step to an observer. Used by
// `isphdem run` and directly by the validation tests, so both run the same code path.
#include <functional>

#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"

namespace isphdem {

template <int Dim>
class FluidRun {
 public:
  FluidRun(FluidScene<Dim> scene, const RunSettings& settings);

  double next_dt() const;
  isph::StepStats advance();
  // Steps until time t: exactly onto t with an automatic dt (steps evened out), or with the fixed
  // dt until t is reached or passed by less than one step.
  void run_until(double t, const std::function<void(const isph::StepStats&)>& after_step = {});

  isph::IsphSolver<Dim>& solver() { return solver_; }
  const isph::IsphSolver<Dim>& solver() const { return solver_; }
  const RunSettings& settings() const { return settings_; }

 private:
  RunSettings settings_;
  isph::IsphSolver<Dim> solver_;
};

}  // namespace isphdem
