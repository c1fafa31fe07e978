#pragma once
// [reference] in a case file: error metrics the run computes itself at its end, from its own
// diagnostics.csv, and writes to OUT/result.json (where `isphdem study` collects them):
//   [[reference.metrics]]
//   name = "amplitude"
//   value = "sqrt(last(kinetic_energy) / first(kinetic_energy))"
//   expected = "exp(-8 * pi^2 * (last(time) - first(time)) / 100)"   # or a number
//   error = "relative"                                               # or "absolute"
// Without `expected` the run reports the value alone: a quantity with no analytic answer, which a
// study compares with one of its points (a fine-resolution run; study file `reference`).
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "study/diagnostics_expression.hpp"

namespace isphdem {

struct ReferenceMetric {
  std::string name;
  DiagnosticsExpression value;
  std::optional<DiagnosticsExpression> expected;  // none: the value alone
  bool relative = true;  // (value - expected) / |expected|; absolute: value - expected
};

struct MetricResult {
  std::string name;
  double value = 0.0, expected = 0.0, error = 0.0;  // expected, error NaN: no expectation
  bool relative = true;
};

std::vector<std::string> reference_keys();

// The metrics of a case (none without [reference]). CaseError names the metric and the key for
// a missing name or value, a duplicate name, or a formula that does not parse.
std::vector<ReferenceMetric> parse_reference(const CaseFile& c);

// CaseError, before the first step, when a metric reads a column the run does not write.
void check_reference_columns(const std::vector<ReferenceMetric>& metrics,
                             const std::vector<std::string>& columns);

// Sets r's expected value and its error against it (relative, or absolute against 0 or when
// the metric says so).
void compare(MetricResult& r, double expected);

// std::runtime_error naming the metric when it cannot be evaluated (no rows, say).
MetricResult evaluate_metric(const ReferenceMetric& m, const DiagnosticsTable& table);

}  // namespace isphdem
