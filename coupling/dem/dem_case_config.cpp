#include "dem/dem_case_config.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace isphdem {

namespace {

std::runtime_error bad(const std::string& key, const std::string& what) {
  return std::runtime_error("[dem] " + key + ": " + what);
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); j++) row[j] = j;
  for (size_t i = 1; i <= a.size(); i++) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); j++) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string closest(const std::string& key, const std::vector<std::string>& known) {
  return *std::min_element(known.begin(), known.end(), [&](const auto& x, const auto& y) {
    return edit_distance(key, x) < edit_distance(key, y);
  });
}

std::string as_text(const std::string& key, const toml::node& v) {
  if (auto s = v.value_exact<std::string>()) return *s;
  if (auto i = v.value_exact<int64_t>()) return std::to_string(*i);
  if (auto d = v.value_exact<double>()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", *d);
    return buf;
  }
  if (auto b = v.value_exact<bool>()) return *b ? "1" : "0";
  throw bad(key, "must be a string, number or boolean (it is passed like liggghts -var)");
}

std::string string_key(const toml::table& t, const std::string& key) {
  auto s = t[key].value_exact<std::string>();
  if (!s || s->empty()) throw bad(key, "must be a non-empty string");
  return *s;
}

}  // namespace

std::vector<std::string> dem_table_keys() {
  return {"script", "substeps", "variables", "log", "screen"};
}

DemCaseConfig parse_dem_table(const toml::table& dem, const std::filesystem::path& case_dir) {
  const auto known = dem_table_keys();
  for (auto&& [k, v] : dem) {
    const std::string key(k.str());
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw bad(key, "unknown key (did you mean '" + closest(key, known) + "'?)");
  }

  DemCaseConfig c;
  if (!dem.contains("script"))
    throw bad("script", "missing: name the LIGGGHTS input script, e.g. script = \"in.liggghts\"");
  c.script = string_key(dem, "script");
  if (c.script.is_relative()) c.script = case_dir / c.script;
  if (!std::filesystem::is_regular_file(c.script))
    throw bad("script", "no such file '" + c.script.string() +
                            "' (a relative path is taken from the case file's directory)");

  if (!dem.contains("substeps"))
    throw bad("substeps", "missing: DEM steps per fluid step, e.g. substeps = 100");
  auto n = dem["substeps"].value_exact<int64_t>();
  if (!n || *n < 1 || *n > 1000000000)
    throw bad("substeps", "must be an integer >= 1 (DEM steps per fluid step)");
  c.substeps = static_cast<int>(*n);

  if (dem.contains("variables")) {
    const toml::table* vars = dem["variables"].as_table();
    if (!vars) throw bad("variables", "must be a table of name = value, e.g. [dem.variables]");
    for (auto&& [k, v] : *vars) {
      const std::string name(k.str());
      const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
      });
      if (!ok) throw bad("variables." + name, "a LIGGGHTS variable name has letters, digits, _");
      c.variables.emplace_back(name, as_text("variables." + name, v));
    }
  }
  // LIGGGHTS resolves paths inside the script (include, read_restart, meshes) from the working
  // directory, not the script's; ${case_dir} lets a script name the files beside it.
  const bool has_case_dir = std::any_of(c.variables.begin(), c.variables.end(),
                                        [](const auto& v) { return v.first == "case_dir"; });
  if (!has_case_dir) {
    const std::filesystem::path dir = case_dir.empty() ? std::filesystem::path(".") : case_dir;
    c.variables.emplace_back("case_dir",
                             std::filesystem::absolute(dir).lexically_normal().string());
    std::sort(c.variables.begin(), c.variables.end());
  }
  if (dem.contains("log")) c.log = string_key(dem, "log");
  if (dem.contains("screen")) {
    c.screen = string_key(dem, "screen");
    if (*c.screen == "none")
      throw bad("screen", "'none' makes LIGGGHTS 3.8 crash on insertion; use a file or /dev/null");
  }
  return c;
}

std::vector<std::string> DemCaseConfig::liggghts_args(const std::filesystem::path& out_dir) const {
  std::vector<std::string> a;
  for (const auto& [name, value] : variables) a.insert(a.end(), {"-var", name, value});
  auto place = [&](const std::string& p) {
    if (p == "none" || out_dir.empty() || std::filesystem::path(p).is_absolute()) return p;
    return (out_dir / p).string();
  };
  if (log) a.insert(a.end(), {"-log", place(*log)});
  if (screen) a.insert(a.end(), {"-screen", place(*screen)});
  return a;
}

void check_fluid_dt(double fluid_dt, int substeps, double dem_dt) {
  const double expected = substeps * dem_dt;
  if (std::fabs(fluid_dt - expected) <= 1e-9 * std::fabs(expected)) return;
  std::ostringstream m;
  m.precision(17);
  m << "fluid time step " << fluid_dt << " s is not [dem] substeps x DEM time step = " << substeps
    << " x " << dem_dt << " s = " << expected << " s; set the fluid dt to that, or substeps to "
    << fluid_dt / dem_dt << " (rounded), or change the script's timestep";
  throw std::runtime_error(m.str());
}

}  // namespace isphdem
