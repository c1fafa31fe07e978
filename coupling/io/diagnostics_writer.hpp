// DIR/diagnostics.csv: one row per diagnostics step (time, step, wall seconds, PPE iterations,
// max |v|, case-specific columns), readable while the run goes on and after it stops at any
// point: the header is written on construction and every row is flushed as it is written.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace isphdem {

class DiagnosticsWriter {
 public:
  // Truncates `path` and writes the header row (std::invalid_argument for an empty, duplicate or
  // comma/quote/newline-containing column name; std::runtime_error if the file cannot be written).
  // append: continue an existing file instead, which must have exactly this header (a partial
  //   last line left by a crash is dropped); a missing or empty file is started afresh.
  // through_step (with append, a run resumed from its checkpoint at that step): rows whose
  //   "step" column is larger are dropped, so that the continuation writes each step once.
  DiagnosticsWriter(std::filesystem::path path, std::vector<std::string> columns,
                    bool append = false, long through_step = -1);
  ~DiagnosticsWriter();
  DiagnosticsWriter(const DiagnosticsWriter&) = delete;
  DiagnosticsWriter& operator=(const DiagnosticsWriter&) = delete;

  // One value per column, in header order (std::invalid_argument otherwise). Each value is
  // printed as the shortest text that reads back to the same double; NaN and infinities as nan,
  // inf, -inf.
  void row(const std::vector<double>& values);

  const std::vector<std::string>& columns() const { return columns_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::FILE* file_ = nullptr;
};

}  // namespace isphdem
