#pragma once
// diagnostics.csv read back as columns of numbers, for the error metrics a run computes at its
// end ([reference] in a case file) and for tests.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace isphdem {

struct DiagnosticsTable {
  std::vector<std::string> names;                      // header order
  std::map<std::string, std::vector<double>> columns;  // one value per complete row

  bool has(const std::string& column) const { return columns.count(column) != 0; }
  std::size_t rows() const { return columns.empty() ? 0 : columns.begin()->second.size(); }
};

// Reads `path` (header row, then numbers; nan and inf as written by DiagnosticsWriter). A last
// line with fewer fields than the header (a run killed while writing it) is dropped. Throws
// std::runtime_error naming the file when it cannot be read or has no header.
DiagnosticsTable read_diagnostics(const std::filesystem::path& path);

}  // namespace isphdem
