#include "run/run_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "study/diagnostics_table.hpp"

namespace isphdem {

namespace fs = std::filesystem;

RunReport::RunReport(const CaseFile& c, std::vector<std::string> overrides, fs::path out)
    : metrics_(parse_reference(c)), out_(std::move(out)) {
  result_.status = "finished";
  result_.overrides = std::move(overrides);
  result_.case_file = c.path().string();
  result_.case_fingerprint = case_fingerprint(c.path());
}

void RunReport::check_columns(const std::vector<std::string>& columns) const {
  check_reference_columns(metrics_, columns);
}

void RunReport::cost(double time, long steps, long particles, double wall, long ppe) {
  result_.time = time;
  result_.steps = steps;
  result_.particles = particles;
  result_.wall_seconds = wall;
  result_.particle_steps_per_second = wall > 0 ? double(particles) * double(steps) / wall : NAN;
  result_.ppe_iterations_per_step = steps > 0 ? double(ppe) / double(steps) : 0.0;
}

void RunReport::stages(double wall, std::vector<std::pair<std::string, double>> parts,
                       const std::vector<std::pair<std::string, double>>& beside) {
  double sum = 0.0;
  for (const auto& s : parts) sum += s.second;
  parts.emplace_back("output", std::max(0.0, wall - sum));
  parts.insert(parts.end(), beside.begin(), beside.end());
  result_.stage_seconds = std::move(parts);
}

void RunReport::parallel(int ranks, bool rows_shared, bool decomposed) {
  result_.ranks = ranks;
  result_.rows_shared = rows_shared;
  result_.decomposed = decomposed;
}

void RunReport::stopped(const std::string& why, const std::string& cause) {
  result_.status = "stopped";
  result_.message = why;
  result_.cause = cause;
}

void RunReport::error(const std::string& why) {
  result_.status = "error";
  result_.message = why;
}

void RunReport::interrupted(const std::string& message) {
  result_.status = "interrupted";
  result_.message = message;
}

void RunReport::finish(bool talk) {
  std::error_code ec;
  if (!fs::is_directory(out_, ec)) return;
  const fs::path csv = out_ / "diagnostics.csv";
  const bool ended = result_.status == "finished" || result_.status == "stopped";
  if (ended && !metrics_.empty() && fs::exists(csv, ec)) {
    // One metric that cannot be evaluated (a window after the run's end) leaves the rest.
    try {
      const DiagnosticsTable table = read_diagnostics(csv);
      for (const auto& m : metrics_) {
        try {
          result_.metrics.push_back(evaluate_metric(m, table));
        } catch (const std::runtime_error& e) {
          std::fprintf(stderr, "isphdem run: %s (left out of result.json)\n", e.what());
        }
      }
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "isphdem run: %s (no metrics in result.json)\n", e.what());
    }
  }
  if (talk)
    for (const auto& m : result_.metrics) {
      if (std::isnan(m.expected))
        std::printf("  reference %s: %.6g\n", m.name.c_str(), m.value);
      else if (m.relative)
        std::printf("  reference %s: %.6g against %.6g (%+.3g%%)\n", m.name.c_str(), m.value,
                    m.expected, 100 * m.error);
      else
        std::printf("  reference %s: %.6g against %.6g (%+.3g)\n", m.name.c_str(), m.value,
                    m.expected, m.error);
    }
  write_run_result(out_ / run_result_file_name(), result_);
}

}  // namespace isphdem
