#pragma once
// What the fluid-only and the coupled `isphdem run` share: the loop to t_end with each output
// time a landing point, and the pressure solve's cost in the closing summary.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "case/run_settings.hpp"
#include "io/progress_line.hpp"
#include "isph_solver.hpp"
#include "run/checkpoints.hpp"

namespace isphdem {

// Advances `run` (FluidRun or CoupledRun) to settings.t_end with each output time as a landing
// point, so snapshots fall on t = k * interval. A SimulationError stops the run: the progress
// line is closed, `report` says where it stopped (the snapshots already written are complete),
// `why` gets the error, `cause` its one-word cause, and false comes back. `end_tolerance` is the
// relative slack on t_end. `k` is the output time stepped towards (k * interval): 1 for a new
// run, where a checkpoint left it for a resumed one; at return, the next one. After `after_step`
// of every step, checkpoint_between_steps writes a checkpoint through `save(k)` when one is due
// and throws Interrupted on a signal (passed through); a finished run also checkpoints its end,
// so that a later time.end can go on from it.
template <class Run, class StepCallback, class WriteSnapshot>
bool run_to_end(Run& run, const RunSettings& settings, double end_tolerance,
                const StepCallback& after_step, const WriteSnapshot& snapshot,
                ProgressLine& progress, bool report, const std::filesystem::path& out,
                std::string& why, std::string& cause, long& k, const Checkpoints& checkpoints,
                const std::function<std::filesystem::path(long)>& save) {
  const auto& solver = run.solver();
  auto each_step = [&](const isph::StepStats& st) {
    after_step(st);
    checkpoint_between_steps(solver.time(), solver.steps(), checkpoints, k, save);
  };
  try {
    for (; solver.time() < settings.t_end * (1.0 - end_tolerance); ++k) {
      run.run_until(std::min(k * settings.output_interval, settings.t_end), each_step);
      snapshot();
    }
  } catch (const isph::SimulationError& e) {
    progress.finish();
    why = e.what();
    cause = e.cause();
    if (report)
      std::fprintf(stderr,
                   "isphdem run: stopped at t = %g s, step %ld: %s\n"
                   "  output written so far in %s is complete and valid.\n",
                   solver.time(), solver.steps(), e.what(), out.string().c_str());
    return false;
  }
  progress.finish();
  if (settings.checkpoint_interval > 0 && checkpoints.last_written() != solver.steps()) save(k);
  return true;
}

// The pressure solve per step, setup (AMG hierarchy, factorisation) apart from the iterations:
// the two numbers a user changing solver.preconditioner or solver.petsc.setup_reuse compares.
template <int Dim>
void print_ppe_cost(const isph::IsphSolver<Dim>& solver, long steps);

// The fluid's seconds by stage (isph::StepStage names, in step order) for result.json, and the
// same per step (over the `steps` this process took) on one line of the done report
// (bench/fluid/run_profile.sh reads the former).
std::vector<std::pair<std::string, double>> fluid_stage_seconds(const isph::StepTimings& t);
void print_fluid_stages(const isph::StepTimings& t, long steps);

}  // namespace isphdem
