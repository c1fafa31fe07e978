#include "case/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace isphdem {

namespace fs = std::filesystem;

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    prev.swap(cur);
  }
  return prev[b.size()];
}

std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

namespace {

std::string source_line(const toml::node& n) {
  const auto& s = n.source();
  if (!s.path || s.begin.line == 0) return "--set";
  return fs::path(*s.path).filename().string() + " line " + std::to_string(s.begin.line);
}

// Collects every key path, with array-of-table elements flattened (no index).
void collect_keys(const toml::table& t, const std::string& prefix,
                  std::vector<std::pair<std::string, const toml::node*>>& out) {
  for (const auto& [k, v] : t) {
    const std::string path =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table()) {
      collect_keys(*sub, path, out);
    } else if (const auto* arr = v.as_array(); arr && !arr->empty() && arr->is_array_of_tables()) {
      for (const auto& el : *arr) collect_keys(*el.as_table(), path, out);
    } else {
      out.emplace_back(path, &v);
    }
  }
}

// TOML reads nan, inf and -inf as numbers. Refused here, for every key at once (scalars, array
// elements, entries of arrays of tables, free-form tables such as dem.variables): a NaN viscosity
// or corner would only show later, as a failed pressure solve or a misplaced particle, and under
// another table's name. PATH names the node: "fluid.gravity[1]", "walls.blocks[0].min[0]".
void refuse_non_finite(const toml::node& n, const std::string& path) {
  if (const auto* t = n.as_table()) {
    for (const auto& [k, v] : *t)
      refuse_non_finite(v, path.empty() ? std::string(k.str()) : path + "." + std::string(k.str()));
  } else if (const auto* a = n.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i)
      refuse_non_finite(*a->get(i), path + "[" + std::to_string(i) + "]");
  } else if (const auto* f = n.as_floating_point()) {
    const double x = f->get();
    if (std::isfinite(x)) return;
    const std::string what = path + " = " + (std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf");
    const std::string fix = " is not a finite number; give a number such as 1e-6";
    const auto& s = n.source();
    if (!s.path || s.begin.line == 0) throw CaseError(what + " (from --set)" + fix);
    throw CaseError(fs::path(*s.path).filename().string() + ":" + std::to_string(s.begin.line) +
                    ": " + what + fix);
  }
}

void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw CaseError("--set '" + assignment + "': expected key=value, e.g. --set time.end=0.2");
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    // Not a TOML value: take it as a bare string (e.g. --set initial.velocity=taylor_green).
    parsed = toml::table{{"v", text}};
  }
  toml::table* t = &root;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw CaseError("--set '" + assignment + "': empty key component");
    if (dot == std::string::npos) {
      t->insert_or_assign(part, *parsed.get("v"));
      return;
    }
    auto* next = t->get(part);
    if (!next) {
      t->insert(part, toml::table{});
      next = t->get(part);
    }
    if (!next->is_table())
      throw CaseError("--set '" + assignment + "': '" + key.substr(0, dot) +
                      "' is not a table in the case file, so '" + key + "' cannot be set");
    t = next->as_table();
    start = dot + 1;
  }
}

}  // namespace

CaseFile CaseFile::load(const fs::path& path, const std::vector<std::string>& overrides,
                        const std::vector<std::string>& known_keys) {
  if (!fs::exists(path))
    throw CaseError("case file '" + path.string() + "' does not exist: check the path");
  if (fs::is_directory(path))
    throw CaseError("'" + path.string() +
                    "' is a directory: give the case file (case.toml) itself");
  CaseFile c;
  c.path_ = fs::absolute(path);
  try {
    c.table_ = toml::parse_file(c.path_.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << "malformed case file " << path.string() << " line " << e.source().begin.line
        << ", column " << e.source().begin.column << ": " << e.description()
        << " (fix the TOML syntax there)";
    throw CaseError(msg.str());
  }
  for (const auto& o : overrides) apply_override(c.table_, o);

  std::vector<std::pair<std::string, const toml::node*>> keys;
  collect_keys(c.table_, "", keys);
  // A known key ending in ".*" admits any key below it (free-form tables such as dem.variables).
  auto known = [&](const std::string& k) {
    for (const auto& pattern : known_keys) {
      if (pattern == k) return true;
      if (pattern.size() > 2 && pattern.compare(pattern.size() - 2, 2, ".*") == 0 &&
          k.compare(0, pattern.size() - 1, pattern, 0, pattern.size() - 1) == 0)
        return true;
    }
    return false;
  };
  for (const auto& [k, node] : keys) {
    if (known(k)) continue;
    throw CaseError("unknown key '" + k + "' (" + source_line(*node) + "); did you mean '" +
                    closest(k, known_keys) + "'?");
  }
  refuse_non_finite(c.table_, "");
  return c;
}

CaseFile CaseFile::with_override(const std::string& assignment) const {
  CaseFile c = *this;
  apply_override(c.table_, assignment);
  refuse_non_finite(c.table_, "");
  return c;
}

toml::node_view<const toml::node> CaseFile::node(const std::string& key) const {
  return table_.at_path(key);
}

bool CaseFile::has(const std::string& key) const { return static_cast<bool>(node(key)); }

std::string CaseFile::where(const std::string& key) const {
  const auto n = node(key);
  return n ? source_line(*n.node()) : "not set";
}

void CaseFile::type_error(const std::string& key, const std::string& expected) const {
  throw CaseError("'" + key + "' (" + where(key) + ") must be " + expected);
}

double CaseFile::number(const std::string& key) const {
  const auto n = node(key);
  if (!n) throw CaseError("missing required key '" + key + "' in " + path_.filename().string());
  if (auto v = n.value<double>(); v && (n.is_number())) return *v;
  type_error(key, "a number");
}

double CaseFile::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double CaseFile::positive(const std::string& key) const {
  const double v = number(key);
  if (!(v > 0.0)) type_error(key, "a positive number (got " + std::to_string(v) + ")");
  return v;
}

double CaseFile::positive(const std::string& key, double fallback) const {
  return has(key) ? positive(key) : fallback;
}

long CaseFile::integer(const std::string& key, long fallback) const {
  const auto n = node(key);
  if (!n) return fallback;
  if (!n.is_integer()) type_error(key, "an integer");
  return static_cast<long>(*n.value<int64_t>());
}

bool CaseFile::boolean(const std::string& key, bool fallback) const {
  const auto n = node(key);
  if (!n) return fallback;
  if (!n.is_boolean()) type_error(key, "true or false");
  return *n.value<bool>();
}

std::string CaseFile::string(const std::string& key, const std::string& fallback) const {
  const auto n = node(key);
  if (!n) return fallback;
  if (!n.is_string()) type_error(key, "a string");
  return *n.value<std::string>();
}

std::vector<double> CaseFile::numbers(const std::string& key, std::size_t size) const {
  const auto n = node(key);
  if (!n) throw CaseError("missing required key '" + key + "' in " + path_.filename().string());
  const auto* arr = n.as_array();
  const std::string expected = "an array of " + std::to_string(size) + " numbers";
  if (!arr || arr->size() != size) type_error(key, expected);
  std::vector<double> out;
  for (const auto& el : *arr) {
    if (!el.is_number()) type_error(key, expected);
    out.push_back(*el.value<double>());
  }
  return out;
}

std::vector<double> CaseFile::numbers(const std::string& key, std::size_t size,
                                      const std::vector<double>& fallback) const {
  return has(key) ? numbers(key, size) : fallback;
}

std::vector<bool> CaseFile::booleans(const std::string& key, std::size_t size,
                                     const std::vector<bool>& fallback) const {
  const auto n = node(key);
  if (!n) return fallback;
  const auto* arr = n.as_array();
  const std::string expected = "an array of " + std::to_string(size) + " booleans";
  if (!arr || arr->size() != size) type_error(key, expected);
  std::vector<bool> out;
  for (const auto& el : *arr) {
    if (!el.is_boolean()) type_error(key, expected);
    out.push_back(*el.value<bool>());
  }
  return out;
}

std::vector<const toml::table*> CaseFile::tables(const std::string& key) const {
  const auto n = node(key);
  std::vector<const toml::table*> out;
  if (!n) return out;
  const auto* arr = n.as_array();
  if (!arr || !arr->is_array_of_tables())
    type_error(key, "an array of tables, written [[" + key + "]]");
  for (const auto& el : *arr) out.push_back(el.as_table());
  return out;
}

std::vector<double> table_numbers(const toml::table& t, const std::string& key, std::size_t size,
                                  const std::string& context) {
  const auto* arr = t[key].as_array();
  const std::string msg =
      "'" + context + "." + key + "' must be an array of " + std::to_string(size) + " numbers";
  if (!arr) throw CaseError(msg + " (missing)");
  if (arr->size() != size) throw CaseError(msg);
  std::vector<double> out;
  for (const auto& el : *arr) {
    if (!el.is_number()) throw CaseError(msg);
    out.push_back(*el.value<double>());
  }
  return out;
}

}  // namespace isphdem
