#pragma once
// `isphdem run` on a fluid-only case (no [dem]): the scene, the loop to time.end with its output,
// checkpoints and --resume (docs/output.md), and the closing summary.
#include "case/case_file.hpp"
#include "case/verb_arguments.hpp"
#include "run/run_report.hpp"

namespace isphdem {

// The command line of `isphdem run`: the verbs' common one and --resume.
struct RunArguments : VerbArguments {
  bool resume = false;
};

// Returns the exit status: 0 finished, 1 stopped by a simulation error, 128 + the signal when
// SIGINT or SIGTERM interrupted it (after a checkpoint).
template <int Dim>
int run_fluid_case(const CaseFile& c, const RunArguments& args, RunReport& report);

}  // namespace isphdem
