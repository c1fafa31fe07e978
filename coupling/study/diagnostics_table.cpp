#include "study/diagnostics_table.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace isphdem {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  std::string f;
  while (std::getline(s, f, ',')) fields.push_back(f);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

DiagnosticsTable read_diagnostics(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::string line;
  if (!std::getline(in, line) || line.empty())
    throw std::runtime_error(path.string() + " has no header row");
  DiagnosticsTable t;
  t.names = split(line);
  std::vector<std::vector<double>> values(t.names.size());
  while (std::getline(in, line)) {
    const auto fields = split(line);
    if (fields.size() != t.names.size()) continue;  // a row cut off by a kill
    std::vector<double> row(fields.size());
    bool complete = true;
    for (std::size_t k = 0; k < fields.size() && complete; ++k) {
      char* end = nullptr;
      row[k] = std::strtod(fields[k].c_str(), &end);
      complete = end != fields[k].c_str() && *end == '\0';
    }
    if (!complete) continue;
    for (std::size_t k = 0; k < row.size(); ++k) values[k].push_back(row[k]);
  }
  for (std::size_t k = 0; k < t.names.size(); ++k) t.columns[t.names[k]] = std::move(values[k]);
  return t;
}

}  // namespace isphdem
