#include "study/study_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "case/case_file.hpp"
#include "study/reference_metrics.hpp"

namespace isphdem {

namespace fs = std::filesystem;

const char* study_file_help() {
  return "A study file (TOML) names a base case and the keys to vary:\n"
         "  base = \"../taylor_green_2d/case.toml\"   # relative to the study file\n"
         "  [set]                                    # applied to every point\n"
         "  \"time.end\" = 0.2\n"
         "  [grid]                                   # every combination of these values\n"
         "  \"particles.spacing\" = [0.04, 0.02]\n"
         "  \"solver.preconditioner\" = [\"jacobi\", \"ilu0\"]\n"
         "  [[points]]                               # single points, besides the grid\n"
         "  name = \"fine\"                            # optional; else made from the values\n"
         "  set = { \"particles.spacing\" = 0.01 }\n"
         "  reference = \"fine\"                      # optional: every metric against this\n"
         "                                           # point's value, not the case's expected\n"
         "  [plot]                                   # study.png: |error| against wall time\n"
         "  metric = \"amplitude\"                     # a [reference] metric of the case\n"
         "  series = \"solver.preconditioner\"         # one line per value of this key\n"
         "  label = \"particles.spacing\"              # the value written beside each point\n"
         "                                           # (\"point\": the point's name)\n"
         "  stability = [\"particles.spacing\", \"time.cfl\"]  # stability.png: how each point\n"
         "                                           # ended over two varied keys (by its\n"
         "                                           # cause: cfl, nan, grain_overlap, ...),\n"
         "                                           # a panel per series value\n"
         "  convergence = \"time.dt\"                  # convergence.png (+ .csv): every metric\n"
         "                                           # against this key, a line per value of\n"
         "                                           # the other varied keys, with the observed\n"
         "                                           # order and the departure from the finest\n"
         "Keys are any case keys, written as for --set (quoted, or as dotted TOML keys). The\n"
         "metrics are the base case's [reference] metrics, computed by each run into its\n"
         "result.json.\n";
}

namespace {

// Leaves of a table as dotted keys; arrays are leaves.
void flatten(const toml::table& t, const std::string& prefix,
             std::vector<std::pair<std::string, const toml::node*>>& out) {
  for (const auto& [k, v] : t) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table())
      flatten(*sub, key, out);
    else
      out.emplace_back(key, &v);
  }
}

// A value as TOML text, numbers in the shortest form that reads back the same (0.05, not
// 0.050000000000000003): it becomes part of point names and of --set.
std::string toml_text(const toml::node& n) {
  if (const auto* arr = n.as_array()) {
    std::string s = "[";
    for (std::size_t k = 0; k < arr->size(); ++k) s += (k ? ", " : "") + toml_text(*arr->get(k));
    return s + "]";
  }
  if (n.is_floating_point()) {
    std::array<char, 32> buf;
    const double x = *n.value<double>();
    auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    std::string s(buf.data(), r.ptr);
    // TOML needs a dot or an exponent to keep a float a float (1.0, not 1).
    if (std::isfinite(x) && s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
  }
  std::ostringstream s;
  n.visit([&](const auto& x) { s << x; });
  return s.str();
}

// A value as a user reads it: strings without quotes.
std::string display_text(const toml::node& n) {
  return n.is_string() ? *n.value<std::string>() : toml_text(n);
}

// A value as it appears in a point's name: no quotes, no spaces.
std::string name_text(const toml::node& n) {
  const std::string s = display_text(n);
  std::string out;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+')
      out += c;
    else if (c == ',' || c == '_')
      out += '_';
  return out.empty() ? "value" : out;
}

std::string short_key(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

const char* type_name(const toml::node& n) {
  if (n.is_number()) return "a number";
  if (n.is_string()) return "a string";
  if (n.is_boolean()) return "true or false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date or time";
}

bool same_type(const toml::node& a, const toml::node& b) {
  if (a.is_number() && b.is_number()) return true;
  if (a.is_array() && b.is_array()) {
    const auto& x = *a.as_array();
    const auto& y = *b.as_array();
    return x.empty() || y.empty() || same_type(x[0], y[0]);
  }
  return a.type() == b.type();
}

struct Setting {
  std::string key;
  const toml::node* value;
  std::string where;  // "[grid]", "points[2].set"
};

class StudyLoader {
 public:
  StudyLoader(const fs::path& file, const std::vector<std::string>& extra,
              const std::vector<std::string>& known)
      : extra_(extra), known_(known) {
    study_.file = fs::absolute(file);
    if (!fs::exists(file))
      throw CaseError("study file '" + file.string() + "' does not exist: check the path");
    try {
      root_ = toml::parse_file(study_.file.string());
    } catch (const toml::parse_error& e) {
      std::ostringstream msg;
      msg << "malformed study file " << file.string() << " line " << e.source().begin.line
          << ", column " << e.source().begin.column << ": " << e.description();
      throw CaseError(msg.str());
    }
  }

  Study load() {
    for (const auto& [k, v] : root_) {
      static const std::set<std::string> top{"base", "set", "grid", "points", "plot", "reference"};
      if (!top.count(std::string(k.str())))
        throw CaseError(here(v) + ": unknown key '" + std::string(k.str()) +
                        "' in the study file; did you mean '" +
                        closest(std::string(k.str()), {top.begin(), top.end()}) + "'?");
    }
    const auto base = root_["base"].value<std::string>();
    if (!base)
      throw CaseError(study_.file.filename().string() +
                      ": no base case: add base = \"path/to/case.toml\" (relative to the study)");
    study_.base = fs::weakly_canonical(study_.file.parent_path() / *base);
    base_case_ = CaseFile::load(study_.base, extra_, known_);
    std::vector<Setting> common;
    if (const auto* set = root_["set"].as_table())
      common = settings(*set, "[set]");
    else if (root_.contains("set"))
      throw CaseError("'set' must be a table: [set] with key = value");
    grid_points(common);
    listed_points(common);
    if (study_.points.empty())
      throw CaseError(study_.file.filename().string() +
                      ": the study has no points: add [grid] with key = [values, ...] or "
                      "[[points]] with set = { key = value }");
    unique_names();
    reference_point();
    check_extra();
    plot();
    for (const auto& p : study_.points) check_point(p);
    return study_;
  }

 private:
  std::string here(const toml::node& n) const {
    return study_.file.filename().string() + " line " + std::to_string(n.source().begin.line);
  }

  std::vector<Setting> settings(const toml::table& t, const std::string& where) {
    std::vector<std::pair<std::string, const toml::node*>> leaves;
    flatten(t, "", leaves);
    std::vector<Setting> out;
    for (const auto& [k, v] : leaves) out.push_back({k, v, where});
    return out;
  }

  // The base case's type at `key`, when it sets one; a value of another type stops the study.
  void check_type(const Setting& s) const {
    const auto at = base_case_.table().at_path(s.key);
    if (!at || same_type(*at.node(), *s.value)) return;
    throw CaseError(here(*s.value) + ": " + s.where + " '" + s.key + "' = " + toml_text(*s.value) +
                    " is " + type_name(*s.value) + ", but the base case " +
                    base_case_.path().filename().string() + " has " + type_name(*at.node()) +
                    " there (" + base_case_.where(s.key) + ")");
  }

  void add_point(const std::vector<Setting>& common, const std::vector<Setting>& own,
                 std::string name) {
    StudyPoint p;
    for (const auto* list : {&common, &own})
      for (const auto& s : *list) {
        check_type(s);
        p.overrides.push_back(s.key + "=" + toml_text(*s.value));
      }
    for (const auto& e : extra_) p.overrides.push_back(e);
    std::string made;
    for (const auto& s : own) {
      p.values.emplace_back(s.key, display_text(*s.value));
      if (std::find(study_.varied.begin(), study_.varied.end(), s.key) == study_.varied.end())
        study_.varied.push_back(s.key);
      made += (made.empty() ? "" : "_") + short_key(s.key) + "=" + name_text(*s.value);
    }
    p.name = name.empty() ? (made.empty() ? "base" : made) : name;
    study_.points.push_back(std::move(p));
  }

  void grid_points(const std::vector<Setting>& common) {
    if (!root_.contains("grid")) return;
    const auto* grid = root_["grid"].as_table();
    if (!grid) throw CaseError("'grid' must be a table: [grid] with key = [values, ...]");
    const auto axes = settings(*grid, "[grid]");
    if (axes.empty()) throw CaseError(here(*grid) + ": [grid] is empty: add key = [values, ...]");
    std::vector<const toml::array*> values;
    for (const auto& a : axes) {
      const auto* arr = a.value->as_array();
      if (!arr)
        throw CaseError(here(*a.value) + ": [grid] '" + a.key + "' = " + toml_text(*a.value) +
                        " must be an array of the values to try, e.g. [" + toml_text(*a.value) +
                        "]");
      if (arr->empty())
        throw CaseError(here(*a.value) + ": [grid] '" + a.key +
                        "' has no values: give at least one, or remove the key");
      values.push_back(arr);
    }
    // Every combination; the last key varies fastest.
    std::vector<std::size_t> index(axes.size(), 0);
    for (;;) {
      std::vector<Setting> own;
      for (std::size_t a = 0; a < axes.size(); ++a)
        own.push_back({axes[a].key, values[a]->get(index[a]), "[grid]"});
      add_point(common, own, "");
      std::size_t a = axes.size();
      while (a > 0 && ++index[a - 1] == values[a - 1]->size()) index[--a] = 0;
      if (a == 0) break;
    }
  }

  void listed_points(const std::vector<Setting>& common) {
    if (!root_.contains("points")) return;
    const auto* arr = root_["points"].as_array();
    if (!arr || !arr->is_array_of_tables())
      throw CaseError("'points' must be an array of tables: [[points]] with set = { ... }");
    for (std::size_t k = 0; k < arr->size(); ++k) {
      const auto& t = *arr->get(k)->as_table();
      const std::string where = "points[" + std::to_string(k) + "]";
      for (const auto& [key, v] : t)
        if (key.str() != "name" && key.str() != "set")
          throw CaseError(here(v) + ": unknown key '" + std::string(key.str()) + "' in " + where +
                          " (a point has name and set)");
      const auto* set = t["set"].as_table();
      if (!set || set->empty())
        throw CaseError(here(t) + ": " + where +
                        " sets nothing: add set = { \"key\" = value, ... }");
      if (t.contains("name") && !t["name"].is_string())
        throw CaseError(here(t) + ": " + where + ".name must be a string");
      const std::string name = t["name"].value_or(std::string());
      static const std::set<std::string> reserved{".", "..", "study.csv", "study.png",
                                                  "stability.png"};
      if (reserved.count(name))
        throw CaseError(here(t) + ": " + where + ".name '" + name +
                        "' would not be a point's own directory under --out: choose another");
      for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) ||
              std::string("._-=+").find(c) != std::string::npos))
          throw CaseError(here(t) + ": " + where + ".name '" + name +
                          "' is a directory name: use letters, digits and . _ - = + only");
      add_point(common, settings(*set, where + ".set"), name);
    }
  }

  void unique_names() {
    std::set<std::string> taken;
    for (auto& p : study_.points) {
      const std::string wanted = p.name;
      for (int k = 2; !taken.insert(p.name).second; ++k) p.name = wanted + "-" + std::to_string(k);
    }
  }

  // --set on the study reaches every point, so it must not also be a key the study varies: it
  // would make the points the same.
  void check_extra() const {
    for (const auto& e : extra_) {
      const std::string key = e.substr(0, e.find('='));
      if (std::find(study_.varied.begin(), study_.varied.end(), key) != study_.varied.end())
        throw CaseError("--set " + e + ": '" + key +
                        "' is a key the study varies; --set would make every point the same "
                        "(change [grid] or [[points]] instead)");
    }
  }

  void reference_point() {
    if (!root_.contains("reference")) return;
    const auto name = root_["reference"].value<std::string>();
    std::vector<std::string> names;
    for (const auto& p : study_.points) names.push_back(p.name);
    if (!name)
      throw CaseError(here(*root_.get("reference")) +
                      ": reference must be the name of a point in quotes (points: " + join(names) +
                      ")");
    if (std::find(names.begin(), names.end(), *name) == names.end())
      throw CaseError(here(*root_.get("reference")) + ": reference = \"" + *name +
                      "\" is not a point of the study; did you mean '" + closest(*name, names) +
                      "'? (give the point a name = \"...\" in [[points]])");
    study_.reference_point = *name;
  }

  void plot() {
    if (!root_.contains("plot")) return;
    const auto* t = root_["plot"].as_table();
    if (!t) throw CaseError("'plot' must be a table: [plot] with metric, series and label");
    for (const auto& [key, v] : *t) {
      const std::string k(key.str());
      if (k != "metric" && k != "series" && k != "label" && k != "stability" && k != "convergence")
        throw CaseError(here(v) + ": unknown key '" + k +
                        "' in [plot]; it has metric, series, label, stability and convergence");
      if (k == "stability") {
        const auto* arr = v.as_array();
        if (!arr || arr->size() != 2 || !(*arr)[0].is_string() || !(*arr)[1].is_string())
          throw CaseError(here(v) +
                          ": [plot] stability must be two varied keys, [\"x.key\", \"y.key\"]");
        for (const auto& el : *arr) study_.stability.push_back(*el.value<std::string>());
      } else if (!v.is_string()) {
        throw CaseError(here(v) + ": [plot] " + k + " must be a string");
      }
    }
    study_.plot_metric = (*t)["metric"].value_or(std::string());
    if (!study_.plot_metric.empty()) {
      std::vector<std::string> names;
      for (const auto& m : parse_reference(base_case_)) names.push_back(m.name);
      if (std::find(names.begin(), names.end(), study_.plot_metric) == names.end())
        throw CaseError("[plot] metric '" + study_.plot_metric +
                        "' is not a [reference] metric of the base case (it has: " +
                        (names.empty() ? std::string("none") : join(names)) + ")");
    }
    study_.plot_series = (*t)["series"].value_or(std::string());
    study_.plot_label = (*t)["label"].value_or(std::string());
    study_.convergence = (*t)["convergence"].value_or(std::string());
    std::vector<const std::string*> keys{&study_.plot_series, &study_.plot_label,
                                         &study_.convergence};
    for (const auto& k : study_.stability) keys.push_back(&k);
    for (const auto* k : keys)
      if (!k->empty() && !(k == &study_.plot_label && *k == "point") &&
          std::find(study_.varied.begin(), study_.varied.end(), *k) == study_.varied.end())
        throw CaseError("[plot] '" + *k +
                        "' is not a key the study varies (it varies: " + join(study_.varied) + ")");
  }

  static std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  }

  // The point's case as `isphdem run` would load it: unknown keys, keys that cannot be set.
  void check_point(const StudyPoint& p) const {
    try {
      parse_reference(CaseFile::load(study_.base, p.overrides, known_));
    } catch (const CaseError& e) {
      throw CaseError("point '" + p.name + "': " + e.what());
    }
  }

  Study study_;
  toml::table root_;
  CaseFile base_case_;
  std::vector<std::string> extra_;
  std::vector<std::string> known_;
};

}  // namespace

Study load_study(const fs::path& file, const std::vector<std::string>& extra,
                 const std::vector<std::string>& known_keys) {
  return StudyLoader(file, extra, known_keys).load();
}

}  // namespace isphdem
