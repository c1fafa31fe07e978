#pragma once
// study.csv: one row per point with the varied keys, how the point ended, its cost (wall time,
// steps, particle-steps/s, PPE iterations) and every error metric any point reported.
#include <filesystem>
#include <vector>

#include "study/study_file.hpp"
#include "study/study_runner.hpp"

namespace isphdem {

// With the study's reference point, every point's metrics get that point's values as expected
// and their errors against them; when the reference point did not run to its end, NaN, and a line
// to stderr says why.
void compare_with_reference_point(const Study& study, std::vector<PointOutcome>& outcomes);

// Written atomically; the metric columns are <name>, <name>_expected and <name>_error, in the
// order the points first report them.
void write_study_table(const std::filesystem::path& file, const Study& study,
                       const std::vector<PointOutcome>& outcomes);

}  // namespace isphdem
