#pragma once
// A study file: a base case and the case keys to vary, as a grid (every combination) and/or a
// list of points. Everything is checked when it is loaded, before any point runs: a misspelt key
// or a value of the wrong type stops the study naming the key (see study_file_help()).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace isphdem {

struct StudyPoint {
  std::string name;  // its directory under --out
  // The varied keys with this point's value as a user reads it ("0.02", "resolved").
  std::vector<std::pair<std::string, std::string>> values;
  std::vector<std::string> overrides;  // key=value for `isphdem run --set`: [set] first
};

struct Study {
  std::filesystem::path file;
  std::filesystem::path base;       // the case every point starts from (absolute)
  std::vector<std::string> varied;  // every key some point sets, in order
  std::vector<StudyPoint> points;
  std::string plot_metric;             // [plot] metric: empty = the first metric
  std::string plot_series;             // [plot] series: one line per value of this key
  std::string plot_label;              // [plot] label: the key whose value labels each point
  std::vector<std::string> stability;  // [plot] stability = [x, y]: stability.png over two keys
  std::string convergence;  // [plot] convergence: convergence.png, the metrics against this key
  // reference = "point": every metric is measured against this point's value (a fine-resolution
  // run where no analytic answer exists) instead of the case's expected value.
  std::string reference_point;
};

// The format, for `isphdem study --help` (docs/study.md has the same with examples).
const char* study_file_help();

// Loads and checks `file`; `extra` are --set values given to the study, applied to every point
// after [set]. Every point's case is loaded against `known_keys` as `isphdem run` would.
// CaseError names the key, the point and the fix.
Study load_study(const std::filesystem::path& file, const std::vector<std::string>& extra,
                 const std::vector<std::string>& known_keys);

}  // namespace isphdem
