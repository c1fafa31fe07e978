#pragma once
// A formula over the columns of diagnostics.csv, for error metrics written in a case file:
//   sqrt(last(kinetic_energy) / first(kinetic_energy))
//   mean_after(max_grain_speed, 0.5)        mean of the rows with time >= 0.5 s
//   exp(-8 * pi^2 * last(time) / 100)
// Numbers, + - * / ^, parentheses, pi; sqrt abs exp log log10 min(a, b) max(a, b); and the
// reductions of one column: first last min max mean (all rows), at(col, t) (interpolated in the
// time column), mean_after(col, t), max_after(col, t), min_after(col, t); and the analytic
// references of reference_formulas.hpp: stokes_velocity(d, rho_p, rho_f, nu, g),
// schiller_naumann_velocity(d, rho_p, rho_f, nu, g), ergun_gradient(eps, d, nu, rho, U),
// cubic_array_drag_factor(phi).
// Bare names other than pi are the named constants given to the constructor (a case's
// [reference.constants]: a grain diameter that a study varies, say).
#include <map>
#include <string>
#include <vector>

#include "study/diagnostics_table.hpp"

namespace isphdem {

class DiagnosticsExpression {
 public:
  // Parses `text`. std::invalid_argument says what was expected where ("at 'foo(' (column 4):
  // unknown function 'foo'; known: ...").
  explicit DiagnosticsExpression(std::string text,
                                 const std::map<std::string, double>& constants = {});

  const std::string& text() const { return text_; }
  // The diagnostics.csv columns the formula reads (time included where at() or *_after need it).
  const std::vector<std::string>& columns() const { return columns_; }
  // std::runtime_error naming a missing column, or a reduction over no rows.
  double evaluate(const DiagnosticsTable& table) const;

  struct Node {
    enum Kind { kNumber, kNegate, kBinary, kFunction, kReduction } kind = kNumber;
    double value = 0.0;
    char op = 0;
    std::string name;    // function, or reduction
    std::string column;  // reductions only
    std::vector<Node> args;
  };

 private:
  std::string text_;
  Node root_;
  std::vector<std::string> columns_;
};

}  // namespace isphdem
