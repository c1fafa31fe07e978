#include "study/study_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "io/atomic_file.hpp"

namespace isphdem {

namespace {

std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string number(double x) {
  if (std::isnan(x)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

}  // namespace

void compare_with_reference_point(const Study& study, std::vector<PointOutcome>& outcomes) {
  if (study.reference_point.empty()) return;
  const PointOutcome* ref = nullptr;
  for (std::size_t k = 0; k < study.points.size(); ++k)
    if (study.points[k].name == study.reference_point) ref = &outcomes[k];
  // A stopped reference is no reference: its metrics are over a run that blew up.
  const bool usable = ref && ref->status == "finished";
  if (!usable)
    std::fprintf(stderr,
                 "isphdem study: the reference point '%s' did not finish (%s): no errors in "
                 "study.csv\n",
                 study.reference_point.c_str(), ref ? ref->status.c_str() : "missing");
  const std::vector<MetricResult> values =
      usable ? ref->result.metrics : std::vector<MetricResult>{};
  for (auto& o : outcomes)
    for (auto& m : o.result.metrics) {
      const auto r = std::find_if(values.begin(), values.end(),
                                  [&](const MetricResult& x) { return x.name == m.name; });
      if (r == values.end()) {
        m.expected = m.error = NAN;
      } else {
        compare(m, r->value);
      }
    }
}

void write_study_table(const std::filesystem::path& file, const Study& study,
                       const std::vector<PointOutcome>& outcomes) {
  std::vector<std::string> metrics;
  for (const auto& o : outcomes)
    for (const auto& m : o.result.metrics)
      if (std::find(metrics.begin(), metrics.end(), m.name) == metrics.end())
        metrics.push_back(m.name);
  std::string csv = "point";
  for (const auto& k : study.varied) csv += "," + field(k);
  csv +=
      ",status,cause,message,time,steps,particles,wall_seconds,particle_steps_per_second,"
      "ppe_iterations_per_step";
  for (const auto& m : metrics) csv += "," + m + "," + m + "_expected," + m + "_error";
  csv += "\n";
  for (std::size_t k = 0; k < study.points.size(); ++k) {
    const auto& p = study.points[k];
    const auto& o = outcomes[k];
    const auto& r = o.result;
    std::map<std::string, std::string> values(p.values.begin(), p.values.end());
    csv += field(p.name);
    for (const auto& key : study.varied) csv += "," + field(values.count(key) ? values[key] : "");
    const bool ran = o.status == "finished" || o.status == "stopped";
    csv += "," + o.status + "," + field(o.result.cause) + "," + field(o.message);
    for (double x : {r.time, double(r.steps), double(r.particles), r.wall_seconds,
                     r.particle_steps_per_second, r.ppe_iterations_per_step})
      csv += "," + (ran ? number(x) : std::string("nan"));
    for (const auto& name : metrics) {
      const auto m = std::find_if(r.metrics.begin(), r.metrics.end(),
                                  [&](const MetricResult& x) { return x.name == name; });
      if (m == r.metrics.end())
        csv += ",nan,nan,nan";
      else
        csv += "," + number(m->value) + "," + number(m->expected) + "," + number(m->error);
    }
    csv += "\n";
  }
  write_file_atomically(file, csv);
}

}  // namespace isphdem
