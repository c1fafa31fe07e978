#include "study/reference_metrics.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace isphdem {

std::vector<std::string> reference_keys() {
  return {"reference.metrics.name", "reference.metrics.value", "reference.metrics.expected",
          "reference.metrics.error", "reference.constants.*"};
}

namespace {

using Constants = std::map<std::string, double>;

DiagnosticsExpression formula(const toml::table& t, const std::string& key,
                              const std::string& context, const Constants& constants) {
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
    return DiagnosticsExpression(text, constants);
  } catch (const std::invalid_argument& e) {
    throw CaseError(context + "." + key + " = \"" + text + "\": " + e.what());
  }
}

// [reference.constants]: name = number, or name = "case.key" for that key's number, so that a
// formula follows a value a study varies (a grain diameter) without repeating it.
Constants parse_constants(const CaseFile& c) {
  Constants constants;
  if (!c.has("reference.constants")) return constants;
  const toml::table* table = c.table().at_path("reference.constants").as_table();
  if (!table)
    throw CaseError("reference.constants must be a table: [reference.constants] with name = value");
  for (const auto& [k, node] : *table) {
    const std::string name(k.str()), context = "reference.constants." + std::string(k.str());
    bool word = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
    for (char ch : name) word = word && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
    if (!word || name == "pi")
      throw CaseError(context +
                      ": a constant's name is a word of letters, digits and '_' (not pi)");
    if (const auto x = node.value<double>()) {
      constants[name] = *x;
    } else if (const auto key = node.value<std::string>()) {
      if (!c.has(*key))
        throw CaseError(context + " = \"" + *key + "\": the case does not set '" + *key +
                        "' (a default is not read here): write it in the case, or give the number");
      try {
        constants[name] = c.number(*key);
      } catch (const CaseError& e) {
        throw CaseError(context + " = \"" + *key + "\": " + e.what());
      }
    } else {
      throw CaseError(context + " must be a number or a case key in quotes (\"fluid.viscosity\")");
    }
  }
  return constants;
}

}  // namespace

std::vector<ReferenceMetric> parse_reference(const CaseFile& c) {
  std::vector<ReferenceMetric> metrics;
  if (!c.has("reference")) return metrics;
  std::set<std::string> names;
  const Constants constants = parse_constants(c);
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
    if (t.contains("expected")) expected = formula(t, "expected", context, constants);
    metrics.push_back(
        {*name, formula(t, "value", context, constants), expected, error == "relative"});
  }
  return metrics;
}

void check_reference_columns(const std::vector<ReferenceMetric>& metrics,
                             const std::vector<std::string>& columns) {
  auto check = [&](const ReferenceMetric& m, const DiagnosticsExpression& e) {
    for (const auto& col : e.columns())
      if (std::find(columns.begin(), columns.end(), col) == columns.end())
        throw CaseError("reference metric '" + m.name + "': this run writes no column '" + col +
                        "' to diagnostics.csv; the closest is '" + closest(col, columns) + "'");
  };
  for (const auto& m : metrics) {
    check(m, m.value);
    if (m.expected) check(m, *m.expected);
  }
}

void compare(MetricResult& r, double expected) {
  r.expected = expected;
  // Relative against zero is meaningless: fall back to the absolute difference.
  r.relative = r.relative && expected != 0.0;
  r.error = r.relative ? (r.value - expected) / std::abs(expected) : r.value - expected;
}

MetricResult evaluate_metric(const ReferenceMetric& m, const DiagnosticsTable& table) {
  MetricResult r;
  r.name = m.name;
  r.relative = m.relative;
  r.expected = r.error = NAN;
  try {
    r.value = m.value.evaluate(table);
    if (m.expected) compare(r, m.expected->evaluate(table));
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("reference metric '" + m.name + "': " + e.what());
  }
  return r;
}

}  // namespace isphdem
