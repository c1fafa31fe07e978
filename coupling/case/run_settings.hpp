#pragma once
// The [time] and [output] tables: how long to run, how the time step is chosen, how often to write.
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "time_step.hpp"

namespace isphdem {

struct RunSettings {
  double t_end = 0.0;
  std::optional<double> fixed_dt;  // time.dt as a number; empty for "auto"
  double max_dt = 1e300;
  isph::TimeStepParams limits;
  double output_interval = 0.0;  // simulated seconds between snapshots
  long diagnostics_every = 10;   // steps between diagnostics rows
  // output.checkpoint_interval: simulated seconds between checkpoints (docs/output.md); 0 writes
  // none but an interrupted run's. Default: t_end / 4.
  double checkpoint_interval = 0.0;
  // A coupled run: its fixed step is [dem] substeps x the DEM step and cannot be "auto", which
  // the advice for a time step beyond the stable limit must say.
  bool coupled = false;
  // parallel.decompose: under mpirun, each rank holds and steps only its own part of the fluid
  // (docs/parallel.md), PMS bodies' particles included. Unset: yes where the pressure solve is
  // distributed (amg); else every rank holds the whole fluid and computes its block of rows.
  std::optional<bool> decompose;
};

std::vector<std::string> run_settings_keys();
RunSettings parse_run_settings(const CaseFile& c);

}  // namespace isphdem
