#include "study/reference_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace isphdem {

std::vector<std::string> reference_keys() {
  return {"reference.metrics.name", "reference.metrics.value", "reference.metrics.expected",
          "reference.metrics.error"};
}

namespace {

DiagnosticsExpression formula(const toml::table& t, const std::string& key,
                              const std::string& context) {
  const auto* node = t.get(key);
  if (!node)
    throw CaseError(context + " needs '" + key + "' (a formula over diagnostics.csv columns" +
                    (key == "expected" ? ", or a number)" : ", e.g. \"last(max_speed)\")"));
  std::string text;
  if (const auto s = node->value<std::string>()) {
    text = *s;
  } else if (const auto x = node->value<double>(); x && key == "expected") {
    std::ostringstream o;
    o.precision(17);
    o << *x;
    text = o.str();
  } else {
    throw CaseError(context + "." + key + " must be a formula in quotes" +
                    (key == "expected" ? std::string(" or a number") : std::string()));
  }
  try {
    return DiagnosticsExpression(text);
  } catch (const std::invalid_argument& e) {
    throw CaseError(context + "." + key + " = \"" + text + "\": " + e.what());
  }
}

}  // namespace

std::vector<ReferenceMetric> parse_reference(const CaseFile& c) {
  std::vector<ReferenceMetric> metrics;
  if (!c.has("reference")) return metrics;
  std::set<std::string> names;
  const auto tables = c.tables("reference.metrics");
  if (tables.empty())
    throw CaseError(
        "[reference] has no metric: add [[reference.metrics]] with name, value and "
        "expected (" +
        c.where("reference") + ")");
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const toml::table& t = *tables[k];
    const std::string context = "reference.metrics[" + std::to_string(k) + "]";
    const auto name = t["name"].value<std::string>();
    if (!name || name->empty())
      throw CaseError(context + " needs a name (name = \"...\"), the column it gets in study.csv");
    if (!names.insert(*name).second)
      throw CaseError(context + ": the name '" + *name + "' is used twice");
    const std::string error = t["error"].value_or(std::string("relative"));
    if (error != "relative" && error != "absolute")
      throw CaseError(context + ".error = \"" + error + "\": use \"relative\" or \"absolute\"");
    std::optional<DiagnosticsExpression> expected;
    if (t.contains("expected")) expected = formula(t, "expected", context);
    metrics.push_back({*name, formula(t, "value", context), expected, error == "relative"});
  }
  return metrics;
}

void check_reference_columns(const std::vector<ReferenceMetric>& metrics,
                             const std::vector<std::string>& columns) {
  for (const auto& m : metrics)
    for (const auto* e : {&m.value, m.expected ? &*m.expected : &m.value})
      for (const auto& col : e->columns())
        if (std::find(columns.begin(), columns.end(), col) == columns.end())
          throw CaseError("reference metric '" + m.name + "': this run writes no column '" + col +
                          "' to diagnostics.csv; the closest is '" + closest(col, columns) + "'");
}

void compare(MetricResult& r, double expected) {
  r.expected = expected;
  // Relative against zero is meaningless: fall back to the absolute difference.
  r.relative = r.relative && expected != 0.0;
  r.error = r.relative ? (r.value - expected) / std::abs(expected) : r.value - expected;
}

std::vector<MetricResult> evaluate_reference(const std::vector<ReferenceMetric>& metrics,
                                             const DiagnosticsTable& table) {
  std::vector<MetricResult> out;
  for (const auto& m : metrics) {
    MetricResult r;
    r.name = m.name;
    try {
      r.value = m.value.evaluate(table);
      r.expected = m.expected ? m.expected->evaluate(table) : NAN;
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("reference metric '" + m.name + "': " + e.what());
    }
    r.relative = m.relative;
    r.error = NAN;
    if (m.expected) compare(r, r.expected);
    out.push_back(r);
  }
  return out;
}

}  // namespace isphdem
