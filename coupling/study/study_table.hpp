#pragma once
// study.csv: one row per point with the varied keys, how the point ended, its cost (wall time,
// steps, particle-steps/s, PPE iterations) and every error metric any point reported.
#include <filesystem>
#include <vector>

#include "study/study_file.hpp"
#include "study/study_runner.hpp"

namespace isphdem {

// Written atomically; the metric columns are <name>, <name>_expected and <name>_error, in the
// order the points first report them.
void write_study_table(const std::filesystem::path& file, const Study& study,
                       const std::vector<PointOutcome>& outcomes);

}  // namespace isphdem
