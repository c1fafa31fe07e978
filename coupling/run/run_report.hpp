#pragma once
// What one `isphdem run` leaves in OUT/result.json: how it ended, what it cost, and the
// [reference] metrics of its case evaluated from its own diagnostics.csv.
#include <filesystem>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "study/reference_metrics.hpp"
#include "study/run_result.hpp"

namespace isphdem {

class RunReport {
 public:
  // Parses [reference] (CaseError for a bad formula, before anything runs). run_main has removed
  // the result.json of an earlier run in `out` already.
  RunReport(const CaseFile& c, std::vector<std::string> overrides, std::filesystem::path out);

  // CaseError before the first step when a metric reads a column this run does not write.
  void check_columns(const std::vector<std::string>& columns) const;
  void cost(double time, long steps, long particles, double wall_seconds, long ppe_iterations);
  // Seconds by part of the step (RunResult::stage_seconds) in this process (a resumed run's
  // share), whose wall time `wall` is; "output" is added as `wall` less their sum. `beside`:
  // seconds spent on another thread at the same time (the staggered DEM), listed but not part
  // of the wall time.
  void stages(double wall, std::vector<std::pair<std::string, double>> parts,
              const std::vector<std::pair<std::string, double>>& beside = {});
  // The ranks the run's fluid was on, and whether its rows were shared between them.
  void parallel(int ranks, bool rows_shared, bool decomposed);
  void stopped(const std::string& why, const std::string& cause);
  void error(const std::string& why);
  // SIGINT/SIGTERM ended the run between two steps, after a checkpoint: status "interrupted",
  // the message says how to resume.
  void interrupted(const std::string& message);

  // Evaluates the metrics (finished or stopped runs), prints them when `talk`, and writes
  // result.json when the output directory exists. A metric that cannot be evaluated is reported
  // on stderr and left out; the result is still written.
  void finish(bool talk);

 private:
  std::vector<ReferenceMetric> metrics_;
  std::filesystem::path out_;
  RunResult result_;
};

}  // namespace isphdem
