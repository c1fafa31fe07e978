#include "io/diagnostics_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>
#include <system_error>

namespace isphdem {

namespace fs = std::filesystem;

namespace {

std::string header_line(const std::vector<std::string>& columns) {
  std::string line;
  for (const auto& c : columns) line += (line.empty() ? "" : ",") + c;
  return line + "\n";
}

std::string format_value(double v) {
  // printf's spelling of non-finite values varies with the C library; pin it to what numpy,
  // pandas and Python's float() all parse.
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  // Shortest text that reads back to the same double (0.1 stays "0.1").
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// For append: the existing file's text up to its last complete line.
std::string complete_lines(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto end = text.rfind('\n');
  return end == std::string::npos ? std::string() : text.substr(0, end + 1);
}

// The lines of `text` (header first) whose value in column `column` is at most `step`.
std::string rows_through(const std::string& text, std::size_t column, long step) {
  std::string kept;
  std::size_t at = 0;
  for (bool header = true; at < text.size(); header = false) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at + 1);
    at = end + 1;
    std::size_t field = 0;
    for (std::size_t k = 0; k < column && field != std::string::npos; ++k)
      field = line.find(',', field) == std::string::npos ? std::string::npos
                                                         : line.find(',', field) + 1;
    if (header || (field != std::string::npos && std::stod(line.substr(field)) <= double(step)))
      kept += line;
  }
  return kept;
}

}  // namespace

DiagnosticsWriter::DiagnosticsWriter(fs::path path, std::vector<std::string> columns, bool append,
                                     long through_step)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("diagnostics: no columns");
  std::set<std::string> seen;
  for (const auto& c : columns_) {
    if (c.empty() || c.find_first_of(",\"\r\n") != std::string::npos)
      throw std::invalid_argument("diagnostics: bad column name '" + c + "'");
    if (!seen.insert(c).second)
      throw std::invalid_argument("diagnostics: column '" + c + "' appears twice");
  }
  const std::string header = header_line(columns_);

  std::string existing;
  std::error_code ec;
  if (append && fs::exists(path_, ec)) {
    existing = complete_lines(path_);
    if (!existing.empty() && existing.compare(0, header.size(), header) != 0)
      throw std::runtime_error("diagnostics: " + path_.string() +
                               " has a different header; cannot append");
    const auto step = std::find(columns_.begin(), columns_.end(), "step");
    if (!existing.empty() && through_step >= 0 && step != columns_.end())
      existing = rows_through(existing, std::size_t(step - columns_.begin()), through_step);
  }
  // Rewriting the kept lines (rather than opening for append) is what drops a partial last line.
  file_ = std::fopen(path_.c_str(), "w");
  if (!file_)
    throw std::runtime_error("diagnostics: cannot create " + path_.string() + ": " +
                             std::strerror(errno));
  const std::string start = existing.empty() ? header : existing;
  if (std::fputs(start.c_str(), file_) < 0 || std::fflush(file_) != 0) {
    const int err = errno;
    std::fclose(file_);
    file_ = nullptr;
    throw std::runtime_error("diagnostics: cannot write " + path_.string() + ": " +
                             std::strerror(err));
  }
}

DiagnosticsWriter::~DiagnosticsWriter() {
  if (file_) std::fclose(file_);
}

void DiagnosticsWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument("diagnostics: row has " + std::to_string(values.size()) +
                                " values for " + std::to_string(columns_.size()) + " columns");
  // A SnapshotWriter constructed later with fresh = true deletes diagnostics.csv; writing on into
  // the unlinked file would lose every row without a trace.
  std::error_code ec;
  if (!fs::exists(path_, ec))
    throw std::runtime_error("diagnostics: " + path_.string() +
                             " was removed while open (construct the SnapshotWriter first)");
  std::string line;
  for (double v : values) line += (line.empty() ? "" : ",") + format_value(v);
  line += "\n";
  if (std::fputs(line.c_str(), file_) < 0 || std::fflush(file_) != 0)
    throw std::runtime_error("diagnostics: cannot write " + path_.string() + ": " +
                             std::strerror(errno));
}

}  // namespace isphdem
