#include "study/diagnostics_expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <stdexcept>

#include "study/reference_formulas.hpp"

namespace isphdem {

namespace {

using Node = DiagnosticsExpression::Node;

// Functions of numbers, by arity.
const std::map<std::string, std::pair<int, std::function<double(const std::vector<double>&)>>>&
functions() {
  static const std::map<std::string,
                        std::pair<int, std::function<double(const std::vector<double>&)>>>
      f{{"sqrt", {1, [](const auto& a) { return std::sqrt(a[0]); }}},
        {"abs", {1, [](const auto& a) { return std::abs(a[0]); }}},
        {"exp", {1, [](const auto& a) { return std::exp(a[0]); }}},
        {"log", {1, [](const auto& a) { return std::log(a[0]); }}},
        {"log10", {1, [](const auto& a) { return std::log10(a[0]); }}},
        {"min", {2, [](const auto& a) { return std::min(a[0], a[1]); }}},
        {"max", {2, [](const auto& a) { return std::max(a[0], a[1]); }}},
        {"stokes_velocity",
         {5, [](const auto& a) { return stokes_velocity(a[0], a[1], a[2], a[3], a[4]); }}},
        {"schiller_naumann_velocity",
         {5,
          [](const auto& a) { return schiller_naumann_velocity(a[0], a[1], a[2], a[3], a[4]); }}},
        {"ergun_gradient",
         {5, [](const auto& a) { return ergun_gradient(a[0], a[1], a[2], a[3], a[4]); }}},
        {"cubic_array_drag_factor",
         {1, [](const auto& a) { return cubic_array_drag_factor(a[0]); }}}};
  return f;
}

// Reductions of a column: how many numeric arguments follow the column name.
const std::map<std::string, int>& reductions() {
  static const std::map<std::string, int> r{{"first", 0},      {"last", 0},      {"min", 0},
                                            {"max", 0},        {"mean", 0},      {"at", 1},
                                            {"mean_after", 1}, {"max_after", 1}, {"min_after", 1}};
  return r;
}

std::string known_names() {
  std::string s;
  for (const auto& [name, arity] : functions()) s += (s.empty() ? "" : ", ") + name;
  for (const auto& [name, arity] : reductions())
    if (!functions().count(name)) s += ", " + name;
  return s;
}

class Parser {
 public:
  Parser(const std::string& text, const std::map<std::string, double>& constants)
      : s_(text), constants_(constants) {}

  Node parse(std::vector<std::string>& columns) {
    columns_ = &columns;
    Node n = sum();
    skip();
    if (i_ != s_.size()) fail("an operator or the end");
    return n;
  }

 private:
  [[noreturn]] void fail(const std::string& expected) const {
    const std::string here = i_ < s_.size() ? "'" + s_.substr(i_, 12) + "'" : "the end";
    throw std::invalid_argument("at " + here + " (column " + std::to_string(i_ + 1) +
                                "): expected " + expected);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  std::string identifier() {
    skip();
    const std::size_t start = i_;
    if (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) return {};
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_'))
      ++i_;
    return s_.substr(start, i_ - start);
  }
  static Node binary(char op, Node a, Node b) {
    Node n;
    n.kind = Node::kBinary;
    n.op = op;
    n.args.push_back(std::move(a));
    n.args.push_back(std::move(b));
    return n;
  }
  Node sum() {
    Node n = product();
    for (;;) {
      if (eat('+'))
        n = binary('+', std::move(n), product());
      else if (eat('-'))
        n = binary('-', std::move(n), product());
      else
        return n;
    }
  }
  Node product() {
    Node n = unary();
    for (;;) {
      if (eat('*'))
        n = binary('*', std::move(n), unary());
      else if (eat('/'))
        n = binary('/', std::move(n), unary());
      else
        return n;
    }
  }
  Node unary() {
    if (eat('-')) {
      Node n;
      n.kind = Node::kNegate;
      n.args.push_back(unary());
      return n;
    }
    if (eat('+')) return unary();
    Node base = primary();
    if (eat('^')) return binary('^', std::move(base), unary());  // right-associative
    return base;
  }
  Node primary() {
    skip();
    if (i_ >= s_.size()) fail("a number, a function or '('");
    if (eat('(')) {
      Node n = sum();
      if (!eat(')')) fail("')'");
      return n;
    }
    if (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.') {
      char* end = nullptr;
      Node n;
      n.value = std::strtod(s_.c_str() + i_, &end);
      if (end == s_.c_str() + i_) fail("a number");
      i_ = static_cast<std::size_t>(end - s_.c_str());
      return n;
    }
    const std::size_t at = i_;
    const std::string name = identifier();
    if (name.empty()) fail("a number, a function or '('");
    if (!eat('(')) {
      const auto k = constants_.find(name);
      if (name == "pi" || k != constants_.end()) {
        Node n;
        n.value = name == "pi" ? M_PI : k->second;
        return n;
      }
      i_ = at;
      fail("a function call such as last(" + name +
           ") (a column is read through a reduction), or a constant of [reference.constants]");
    }
    Node n;
    n.name = name;
    const auto r = reductions().find(name);
    const auto f = functions().find(name);
    // min/max of a column name (one argument, an identifier) is the reduction; of two numbers the
    // function.
    skip();
    const std::size_t after_paren = i_;
    std::string column = identifier();
    skip();
    // An identifier first is the column of a reduction, unless a ',' follows and the reduction
    // takes no further argument: min(d, 1) is then the function of two numbers.
    const bool column_first = !column.empty() && column != "pi" &&
                              (i_ == s_.size() || s_[i_] == ')' ||
                               (s_[i_] == ',' && r != reductions().end() && r->second > 0));
    if (r != reductions().end() && column_first) {
      n.kind = Node::kReduction;
      n.column = column;
      columns_->push_back(column);
      if (r->second > 0) columns_->push_back("time");
      for (int k = 0; k < r->second; ++k) {
        if (!eat(',')) fail("',' and a time: " + name + "(column, t)");
        n.args.push_back(sum());
      }
      if (!eat(')')) fail("')' after " + std::to_string(r->second + 1) + " argument(s) of " + name);
      return n;
    }
    i_ = after_paren;
    if (f == functions().end()) {
      i_ = at;
      if (r != reductions().end()) fail(name + "(column" + (r->second ? ", t)" : ")"));
      fail("a known function, not '" + name + "' (known: " + known_names() + ")");
    }
    n.kind = Node::kFunction;
    n.args.push_back(sum());
    while (eat(',')) n.args.push_back(sum());
    if (!eat(')')) fail("')'");
    if (static_cast<int>(n.args.size()) != f->second.first)
      throw std::invalid_argument(name + "() takes " + std::to_string(f->second.first) +
                                  " argument(s), not " + std::to_string(n.args.size()));
    return n;
  }

  const std::string& s_;
  const std::map<std::string, double>& constants_;
  std::size_t i_ = 0;
  std::vector<std::string>* columns_ = nullptr;
};

const std::vector<double>& column_of(const DiagnosticsTable& t, const std::string& name) {
  const auto c = t.columns.find(name);
  if (c == t.columns.end()) {
    std::string list;
    for (const auto& n : t.names) list += (list.empty() ? "" : ", ") + n;
    throw std::runtime_error("diagnostics.csv has no column '" + name + "' (it has: " + list + ")");
  }
  if (c->second.empty()) throw std::runtime_error("diagnostics.csv has no rows");
  return c->second;
}

double reduce(const Node& n, const DiagnosticsTable& t, const std::vector<double>& args) {
  const auto& v = column_of(t, n.column);
  if (n.name == "first") return v.front();
  if (n.name == "last") return v.back();
  if (n.name == "min") return *std::min_element(v.begin(), v.end());
  if (n.name == "max") return *std::max_element(v.begin(), v.end());
  if (n.name == "mean") {
    double s = 0.0;
    for (double x : v) s += x;
    return s / double(v.size());
  }
  const auto& time = column_of(t, "time");
  if (n.name == "at") {
    const double at = args[0];
    if (at <= time.front()) return v.front();
    for (std::size_t k = 1; k < time.size(); ++k)
      if (time[k] >= at) {
        const double w = (at - time[k - 1]) / (time[k] - time[k - 1]);
        return (1.0 - w) * v[k - 1] + w * v[k];
      }
    return v.back();
  }
  // *_after(col, t0): over the rows with time >= t0.
  double sum = 0.0, lo = INFINITY, hi = -INFINITY;
  std::size_t count = 0;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (time[k] >= args[0]) {
      sum += v[k];
      lo = std::min(lo, v[k]);
      hi = std::max(hi, v[k]);
      ++count;
    }
  if (count == 0)
    throw std::runtime_error(n.name + "(" + n.column + ", " + std::to_string(args[0]) +
                             "): no row has time >= " + std::to_string(args[0]));
  if (n.name == "mean_after") return sum / double(count);
  return n.name == "max_after" ? hi : lo;
}

double evaluate_node(const Node& n, const DiagnosticsTable& t) {
  std::vector<double> a;
  for (const auto& arg : n.args) a.push_back(evaluate_node(arg, t));
  switch (n.kind) {
    case Node::kNumber:
      return n.value;
    case Node::kNegate:
      return -a[0];
    case Node::kBinary:
      switch (n.op) {
        case '+':
          return a[0] + a[1];
        case '-':
          return a[0] - a[1];
        case '*':
          return a[0] * a[1];
        case '/':
          return a[0] / a[1];
        default:
          return std::pow(a[0], a[1]);
      }
    case Node::kFunction:
      return functions().at(n.name).second(a);
    case Node::kReduction:
      return reduce(n, t, a);
  }
  return NAN;
}

}  // namespace

DiagnosticsExpression::DiagnosticsExpression(std::string text,
                                             const std::map<std::string, double>& constants)
    : text_(std::move(text)) {
  root_ = Parser(text_, constants).parse(columns_);
  std::sort(columns_.begin(), columns_.end());
  columns_.erase(std::unique(columns_.begin(), columns_.end()), columns_.end());
}

double DiagnosticsExpression::evaluate(const DiagnosticsTable& table) const {
  return evaluate_node(root_, table);
}

}  // namespace isphdem
