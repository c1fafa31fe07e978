#pragma once
// OUT/result.json: how a run ended and what it measured, one small file written atomically at
// the end of every `isphdem run` (also one that stopped), and read back by `isphdem study`.
// A run that is killed leaves none, so "no result.json" means "not finished".
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/reference_metrics.hpp"

namespace isphdem {

struct RunResult {
  // "finished": reached time.end; "stopped": a simulation error (CFL, NaN, solver failure, a
  // grain leaving the domain) ended it early, output so far valid; "error": bad input;
  // "interrupted": SIGINT/SIGTERM, a checkpoint written (`isphdem run ... --resume` goes on).
  std::string status;
  std::string message;                 // the error, for "stopped" and "error"
  std::string cause;                   // "stopped": isph::SimulationError::cause(), e.g. "cfl"
  std::vector<std::string> overrides;  // the --set values of the run, in order
  std::string case_file;               // the case file, absolute
  std::string case_fingerprint;        // of its text (case_fingerprint()): an edit shows
  double time = 0.0;                   // simulated time reached [s]
  long steps = 0;                      // fluid steps (DEM chunks for a DEM-only case)
  long particles = 0;                  // fluid + wall particles
  double wall_seconds = 0.0;
  double particle_steps_per_second = 0.0;
  double ppe_iterations_per_step = 0.0;
  int ranks = 1;             // MPI ranks of the run
  bool rows_shared = false;  // each rank computed its block of the fluid's rows (docs/parallel.md)
  bool decomposed = false;   // each rank held only its own part of the fluid (docs/parallel.md)
  // Wall seconds by part of the step, on rank 0: the fluid's stages (isph::StepStage names), and
  // for a coupled run "coupling", "dem" (sequential) or "dem_wait" and "dem_beside" (staggered),
  // and "output" for what the step loop spent outside the steps (snapshots, diagnostics, start).
  std::vector<std::pair<std::string, double>> stage_seconds;
  std::vector<MetricResult> metrics;
};

std::string run_result_file_name();  // "result.json"

// DIR/result.json removed, if there is one (a run starting, a study point restarting).
void remove_run_result(const std::filesystem::path& dir);

// A fingerprint of a file's bytes (FNV-1a, 64 bit, hex); empty when it cannot be read. The
// study compares it to tell a point run from an edited base case.
std::string case_fingerprint(const std::filesystem::path& file);

// Throws std::runtime_error naming the file when it cannot be written (the old file stays).
void write_run_result(const std::filesystem::path& file, const RunResult& result);

// Nothing when the file is missing or is not a result.json (an interrupted copy, a field of the
// wrong type).
std::optional<RunResult> read_run_result(const std::filesystem::path& file);

}  // namespace isphdem
