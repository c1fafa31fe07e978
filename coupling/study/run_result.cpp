#include "study/run_result.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"

namespace isphdem {

using nlohmann::json;

namespace {

// JSON has no NaN: write null, read null back as NaN.
json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
double number(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : NAN;
}

}  // namespace

std::string run_result_file_name() { return "result.json"; }

void write_run_result(const std::filesystem::path& file, const RunResult& r) {
  json metrics = json::array();
  for (const auto& m : r.metrics)
    metrics.push_back({{"name", m.name},
                       {"value", number(m.value)},
                       {"expected", number(m.expected)},
                       {"error", number(m.error)},
                       {"error_kind", m.relative ? "relative" : "absolute"}});
  const json j = {{"status", r.status},
                  {"message", r.message},
                  {"overrides", r.overrides},
                  {"time", number(r.time)},
                  {"steps", r.steps},
                  {"particles", r.particles},
                  {"wall_seconds", number(r.wall_seconds)},
                  {"particle_steps_per_second", number(r.particle_steps_per_second)},
                  {"ppe_iterations_per_step", number(r.ppe_iterations_per_step)},
                  {"metrics", metrics}};
  write_file_atomically(file, j.dump(2) + "\n");
}

std::optional<RunResult> read_run_result(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  const json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("status") || !j["status"].is_string())
    return std::nullopt;
  RunResult r;
  r.status = j["status"].get<std::string>();
  r.message = j.value("message", "");
  if (j.contains("overrides") && j["overrides"].is_array())
    for (const auto& o : j["overrides"])
      if (o.is_string()) r.overrides.push_back(o.get<std::string>());
  r.time = number(j, "time");
  r.steps = j.value("steps", 0L);
  r.particles = j.value("particles", 0L);
  r.wall_seconds = number(j, "wall_seconds");
  r.particle_steps_per_second = number(j, "particle_steps_per_second");
  r.ppe_iterations_per_step = number(j, "ppe_iterations_per_step");
  if (j.contains("metrics") && j["metrics"].is_array())
    for (const auto& m : j["metrics"]) {
      if (!m.is_object() || !m.contains("name")) continue;
      MetricResult x;
      x.name = m.value("name", "");
      x.value = number(m, "value");
      x.expected = number(m, "expected");
      x.error = number(m, "error");
      x.relative = m.value("error_kind", "relative") == "relative";
      r.metrics.push_back(x);
    }
  return r;
}

}  // namespace isphdem
