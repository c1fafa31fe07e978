#include "study/run_result.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
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

void remove_run_result(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::remove(dir / run_result_file_name(), ec);
}

std::string case_fingerprint(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::uint64_t h = 1469598103934665603ull;
  char c;
  while (in.get(c)) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

void write_run_result(const std::filesystem::path& file, const RunResult& r) {
  json metrics = json::array();
  for (const auto& m : r.metrics)
    metrics.push_back({{"name", m.name},
                       {"value", number(m.value)},
                       {"expected", number(m.expected)},
                       {"error", number(m.error)},
                       {"error_kind", m.relative ? "relative" : "absolute"}});
  json stages = json::object();
  for (const auto& [name, seconds] : r.stage_seconds) stages[name] = number(seconds);
  const json j = {{"status", r.status},
                  {"message", r.message},
                  {"cause", r.cause},
                  {"overrides", r.overrides},
                  {"case_file", r.case_file},
                  {"case_fingerprint", r.case_fingerprint},
                  {"time", number(r.time)},
                  {"steps", r.steps},
                  {"particles", r.particles},
                  {"wall_seconds", number(r.wall_seconds)},
                  {"particle_steps_per_second", number(r.particle_steps_per_second)},
                  {"ppe_iterations_per_step", number(r.ppe_iterations_per_step)},
                  {"ranks", r.ranks},
                  {"rows_shared", r.rows_shared},
                  {"decomposed", r.decomposed},
                  {"stage_seconds", stages},
                  {"metrics", metrics}};
  // A message with bytes that are not UTF-8 (a path, LIGGGHTS's words) must not lose the file.
  write_file_atomically(file, j.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

namespace {

std::string text(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

std::optional<RunResult> read_run_result(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  const json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("status") || !j["status"].is_string())
    return std::nullopt;
  RunResult r;
  r.status = j["status"].get<std::string>();
  r.message = text(j, "message");
  r.cause = text(j, "cause");
  r.case_file = text(j, "case_file");
  r.case_fingerprint = text(j, "case_fingerprint");
  if (j.contains("overrides") && j["overrides"].is_array())
    for (const auto& o : j["overrides"])
      if (o.is_string()) r.overrides.push_back(o.get<std::string>());
  r.time = number(j, "time");
  r.steps = std::isfinite(number(j, "steps")) ? long(number(j, "steps")) : 0;
  r.particles = std::isfinite(number(j, "particles")) ? long(number(j, "particles")) : 0;
  r.wall_seconds = number(j, "wall_seconds");
  r.particle_steps_per_second = number(j, "particle_steps_per_second");
  r.ppe_iterations_per_step = number(j, "ppe_iterations_per_step");
  r.ranks = std::isfinite(number(j, "ranks")) ? int(number(j, "ranks")) : 1;
  r.rows_shared =
      j.contains("rows_shared") && j["rows_shared"].is_boolean() && j["rows_shared"].get<bool>();
  r.decomposed =
      j.contains("decomposed") && j["decomposed"].is_boolean() && j["decomposed"].get<bool>();
  if (j.contains("stage_seconds") && j["stage_seconds"].is_object())
    for (const auto& [name, seconds] : j["stage_seconds"].items())
      r.stage_seconds.emplace_back(name, seconds.is_number() ? seconds.get<double>() : NAN);
  if (j.contains("metrics") && j["metrics"].is_array())
    for (const auto& m : j["metrics"]) {
      if (!m.is_object() || text(m, "name").empty()) continue;
      MetricResult x;
      x.name = text(m, "name");
      x.value = number(m, "value");
      x.expected = number(m, "expected");
      x.error = number(m, "error");
      x.relative = text(m, "error_kind") != "absolute";
      r.metrics.push_back(x);
    }
  return r;
}

}  // namespace isphdem
