#pragma once
// One run of an internal-erosion case at a given model, inflow and fluid step, through
// `isphdem run` as a user runs it, for the time-step tests of issue 46: the DEM step held at
// 1e-6 s (dem.substeps = dt / 1e-6) and a diagnostics row every 0.01 s whatever the step.
#include <cmath>
#include <string>

#include "../cli/cli_support.hpp"

namespace isphdem::erosion_test {

struct StepRun {
  cli::Result result;      // the command's exit code and output
  double end_time = 0.0;   // the last diagnostics row's time
  double pore_jet = 0.0;   // max_pore_speed_ratio, mean over the rows from t = 0.1 s on
  double pore_p95 = 0.0;   // pore_speed_p95_ratio, the same mean
  double pore_mean = 0.0;  // mean_pore_speed_ratio, the same mean
  int rows = 0;            // how many rows those means took
};

// `case_args`: the case file and its own overrides (cli::reduced_case(), cli::seed_case());
// `model`: coupling.model; `velocity`: inflow.velocity [m/s]; `extra`: more overrides. Writes
// into cli::scratch(name).
inline StepRun run_at_step(const std::string& case_args, const std::string& name,
                           const std::string& model, const std::string& velocity,
                           const std::string& dt, const std::string& end,
                           const std::string& extra = "") {
  const double step = std::stod(dt);
  const auto out = cli::scratch(name);
  StepRun s;
  s.result = cli::run(
      case_args + " --out " + out.string() + " --quiet --set inflow.velocity=" + velocity +
      " --set 'coupling.model=\"" + model + "\"' --set time.end=" + end + " --set time.dt=" + dt +
      " --set dem.substeps=" + std::to_string(std::lround(step / 1e-6)) +
      " --set output.diagnostics_every=" + std::to_string(std::lround(0.01 / step)) + extra);
  if (s.result.exit_code != 0) return s;
  for (const auto& row : cli::read_csv(out / "diagnostics.csv")) {
    s.end_time = std::stod(row.at("time"));
    if (s.end_time >= 0.1 - 1e-9) {
      s.pore_jet += std::stod(row.at("max_pore_speed_ratio"));
      s.pore_p95 += std::stod(row.at("pore_speed_p95_ratio"));
      s.pore_mean += std::stod(row.at("mean_pore_speed_ratio"));
      ++s.rows;
    }
  }
  if (s.rows > 0) {
    s.pore_jet /= s.rows;
    s.pore_p95 /= s.rows;
    s.pore_mean /= s.rows;
  }
  return s;
}

// Semi-resolved at v_in = 0.5 cm/s, the seed's case.
inline StepRun run_semi_resolved_at_step(const std::string& case_args, const std::string& name,
                                         const std::string& dt, const std::string& end,
                                         const std::string& extra = "") {
  return run_at_step(case_args, name, "semi-resolved", "0.005", dt, end, extra);
}

}  // namespace isphdem::erosion_test
