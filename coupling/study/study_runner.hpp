#pragma once
// Runs the points of a study, each as its own `isphdem run` process in OUT/<point>/ (its log in
// log.txt, the resolved case in case_used.toml, its result in result.json), N side by side. A
// point already finished with the same overrides is not run again, so a killed study resumes
// where it was; a point that blows up or fails is recorded, never fatal to the study.
#include <filesystem>
#include <string>
#include <vector>

#include "study/run_result.hpp"
#include "study/study_file.hpp"

namespace isphdem {

struct PointOutcome {
  // finished / stopped / error (as the run reported it in result.json); failed (exit status
  // without a result.json: a crash) or killed (by a signal).
  std::string status;
  std::string message;
  bool earlier = false;  // finished in an earlier invocation: not run again
  RunResult result;
};

struct StudyRunOptions {
  std::filesystem::path out;
  std::filesystem::path isphdem;  // the executable each point runs
  int jobs = 1;
  bool quiet = false;  // no line per point
};

std::vector<PointOutcome> run_study(const Study& study, const StudyRunOptions& options);

}  // namespace isphdem
