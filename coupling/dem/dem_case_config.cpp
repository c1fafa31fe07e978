#include "dem/dem_case_config.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
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

// ${name} and $x of a LIGGGHTS input line with the values known; nullopt if one is unknown or
// the line has an immediate $(...) expression.
std::optional<std::string> substitute(const std::string& line,
                                      const std::map<std::string, std::string>& vars) {
  std::string out;
  for (size_t i = 0; i < line.size(); i++) {
    if (line[i] != '$') {
      out += line[i];
      continue;
    }
    if (i + 1 >= line.size() || line[i + 1] == '(') return std::nullopt;
    std::string name;
    if (line[i + 1] == '{') {
      const size_t close = line.find('}', i + 2);
      if (close == std::string::npos) return std::nullopt;
      name = line.substr(i + 2, close - i - 2);
      i = close;
    } else {
      name = line.substr(i + 1, 1);
      i++;
    }
    const auto v = vars.find(name);
    if (v == vars.end()) return std::nullopt;
    out += v->second;
  }
  return out;
}

std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> w;
  std::istringstream in(line);
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

// The script's read_restart files that do not exist, with the line that names them: the script
// read as LIGGGHTS reads it (comments, `&` continuations; `variable NAME index|string VALUE`
// after the -var values, which win over index defaults), stopping at the first command whose
// variables are not all known. Included files are not followed.
void check_restart_files(const DemCaseConfig& c, const std::optional<std::string>& prepare,
                         const std::filesystem::path& case_dir) {
  std::ifstream in(c.script);
  std::map<std::string, std::string> vars(c.variables.begin(), c.variables.end());
  std::string line, joined;
  int number = 0, first = 0;
  while (std::getline(in, line)) {
    number++;
    if (joined.empty()) first = number;
    bool quoted = false;
    for (size_t i = 0; i < line.size(); i++) {
      if (line[i] == '"') quoted = !quoted;
      if (line[i] == '#' && !quoted) {
        line.resize(i);
        break;
      }
    }
    const size_t end = line.find_last_not_of(" \t\r");
    line.resize(end == std::string::npos ? 0 : end + 1);
    if (!line.empty() && line.back() == '&') {
      line.pop_back();
      joined += line + " ";
      continue;
    }
    joined += line;
    const auto w0 = words(joined);
    const std::string raw = joined;
    joined.clear();
    if (w0.empty()) continue;
    const auto expanded = substitute(raw, vars);
    if (!expanded) {
      if (w0[0] == "variable" && w0.size() >= 2) vars.erase(w0[1]);  // value unknown from here
      continue;
    }
    const auto w = words(*expanded);
    if (w.empty()) continue;
    if (w[0] == "variable" && w.size() >= 4) {
      if (w[2] == "index" && !vars.count(w[1]))
        vars[w[1]] = w[3];
      else if (w[2] == "string")
        vars[w[1]] = w[3];
      else if (w[2] != "index")
        vars.erase(w[1]);
    } else if (w[0] == "read_restart" && w.size() >= 2) {
      // LIGGGHTS opens it from the working directory; '*' is a step number, '%' per processor.
      if (w[1].find_first_of("*%") != std::string::npos) continue;
      if (std::filesystem::exists(w[1])) continue;
      std::string m = "the script " + c.script.filename().string() + " (line " +
                      std::to_string(first) + ": read_restart) reads '" + w[1] +
                      "', which does not exist";
      if (prepare) {
        // The command as the case file gives it, with this isphdem's path for a leading
        // "isphdem" so that it can be pasted as it is.
        std::string command = *prepare;
        std::error_code ec;
        const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec && command.rfind("isphdem ", 0) == 0) command = self.string() + command.substr(7);
        const std::filesystem::path dir = case_dir.empty() ? "." : case_dir;
        m += ". Make it first ([dem] prepare in the case file):\n  cd " +
             std::filesystem::absolute(dir).lexically_normal().string() + " && " + command;
      } else {
        m += " (make it first; [dem] prepare = \"COMMAND\" in the case file prints the command "
             "that does)";
      }
      throw std::runtime_error("[dem] " + m);
    }
  }
}
}  // namespace

std::vector<std::string> dem_table_keys() {
  return {"script", "substeps", "exchange", "variables", "log", "screen", "prepare"};
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
  if (dem.contains("exchange")) {
    const std::string e = string_key(dem, "exchange");
    if (e == "staggered")
      c.exchange = DemExchange::staggered;
    else if (e != "sequential")
      throw bad("exchange", "'" + e +
                                "' is not an exchange: \"sequential\" (the DEM after the fluid "
                                "step, with its loads) or \"staggered\" (the DEM beside it on a "
                                "thread of its own, with the loads of the step before)");
  }

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
  std::optional<std::string> prepare;
  if (dem.contains("prepare")) prepare = string_key(dem, "prepare");
  check_restart_files(c, prepare, case_dir);
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
