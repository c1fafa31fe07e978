#pragma once
// Runs `isphdem run` the way a user does and captures what it prints.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace isphdem::cli {

struct Result {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs a whole shell command line (stdout and stderr captured together).
inline Result run_shell(const std::string& command_line) {
  const std::string cmd = command_line + " 2>&1";
  Result r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (std::fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// How often `what` occurs in `text` (a message shown once, say).
inline int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Every run of `chars` in `text` that follows `before` and is followed by `after`, in order of
// appearance (std::regex draws -Wmaybe-uninitialized from libstdc++ in the sanitized build).
inline std::vector<std::string> spans_between(const std::string& text, const std::string& before,
                                              const std::string& after,
                                              const char* chars = "0123456789.") {
  std::vector<std::string> found;
  for (auto at = text.find(before); at != std::string::npos; at = text.find(before, at + 1)) {
    const auto from = at + before.size();
    const auto to = text.find_first_not_of(chars, from);
    if (to != from && to != std::string::npos && text.compare(to, after.size(), after) == 0)
      found.push_back(text.substr(from, to - from));
  }
  return found;
}

inline std::string isphdem() { return std::string(ISPHDEM_BINARY_DIR) + "/coupling/isphdem"; }

inline Result run(const std::string& args) { return run_shell(isphdem() + " run " + args); }

// A fresh scratch directory per test.
inline std::filesystem::path scratch(const std::string& name) {
  const auto d = std::filesystem::path(ISPHDEM_BINARY_DIR) / "test_output" / "cli" / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// The reduced erosion layer's packing, written into the build tree by the ctest fixture
// erosion_reduced_packing (tests/CMakeLists.txt, REDUCED_PACKING_DIR), not beside the case.
inline std::filesystem::path reduced_packing_dir() {
  return std::filesystem::path(ISPHDEM_BINARY_DIR) / "test_output" / "erosion_reduced_packing";
}

// A case file of examples/internal_erosion_2d with the override that reads its packing from
// packing_dir, ready for `isphdem run` (more --set may follow).
inline std::string erosion_case_with_packing(const std::string& file,
                                             const std::filesystem::path& packing_dir) {
  return std::string(ISPHDEM_SOURCE_DIR) + "/examples/internal_erosion_2d/" + file +
         " --set 'dem.variables.packing_dir=\"" + packing_dir.string() + "\"'";
}

// reduced.toml reading that packing.
inline std::string reduced_case() {
  return erosion_case_with_packing("reduced.toml", reduced_packing_dir());
}

// The seed's layer (examples/internal_erosion_2d/in.packing), written into the build tree by the
// ctest fixture erosion_packing, and case.toml reading it.
inline std::filesystem::path seed_packing_dir() {
  return std::filesystem::path(ISPHDEM_BINARY_DIR) / "test_output" / "erosion_packing";
}

inline std::string seed_case() {
  return erosion_case_with_packing("case.toml", seed_packing_dir());
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

using Edits = std::vector<std::pair<std::string, std::string>>;

// A copy of examples/NAME in scratch(SCRATCH_NAME) whose in.liggghts has each `from` replaced by
// its `to` (std::runtime_error if one is missing).
inline std::filesystem::path edited_example(const std::string& scratch_name,
                                            const std::string& name, const Edits& edits) {
  const auto dir = scratch(scratch_name);
  for (const auto& e : std::filesystem::directory_iterator(
           std::filesystem::path(ISPHDEM_SOURCE_DIR) / "examples" / name))
    if (e.is_regular_file()) std::filesystem::copy_file(e.path(), dir / e.path().filename());
  std::string script = read_file(dir / "in.liggghts");
  for (const auto& [from, to] : edits) {
    const auto at = script.find(from);
    if (at == std::string::npos) throw std::runtime_error("'" + from + "' not in " + name);
    script.replace(at, from.size(), to);
  }
  write_file(dir / "in.liggghts", script);
  return dir;
}

inline std::string example(const std::string& name) {
  return std::string(ISPHDEM_SOURCE_DIR) + "/examples/" + name + "/case.toml";
}

inline int count_snapshots(const std::filesystem::path& dir) {
  int n = 0;
  if (!std::filesystem::exists(dir)) return 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    n += e.path().filename().string().rfind("snap_", 0) == 0;
  return n;
}

// Runs ParaView's own XDMF reader over an output directory (tests/output/check_xdmf.py checks
// every step). Returns the exit status and prints what the checker said.
inline int paraview_check(const std::filesystem::path& out, const std::string& args) {
  const std::string cmd = "QT_QPA_PLATFORM=offscreen pvpython --force-offscreen-rendering " +
                          std::string(ISPHDEM_SOURCE_DIR) + "/tests/output/check_xdmf.py " +
                          out.string() + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 512> buf;
  std::string said;
  while (std::fgets(buf.data(), buf.size(), p)) said += buf.data();
  const int status = pclose(p);
  std::printf("pvpython: %s", said.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline bool has_pvpython() { return std::system("command -v pvpython > /dev/null 2>&1") == 0; }

// A CSV the runs write (study.csv, diagnostics.csv): one map of column -> text per row.
using Row = std::map<std::string, std::string>;

inline std::vector<Row> read_csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line;
  std::vector<std::string> header;
  std::vector<Row> rows;
  auto split = [](const std::string& l) {
    std::vector<std::string> f;
    std::string cur;
    bool quoted = false;
    for (char c : l) {
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted) {
        f.push_back(cur);
        cur.clear();
      } else
        cur += c;
    }
    f.push_back(cur);
    return f;
  };
  if (std::getline(in, line)) header = split(line);
  while (std::getline(in, line)) {
    const auto f = split(line);
    Row r;
    for (std::size_t k = 0; k < header.size() && k < f.size(); ++k) r[header[k]] = f[k];
    rows.push_back(r);
  }
  return rows;
}

// Writes TEXT as DIR/study.toml, runs `isphdem study` on it two points at a time into DIR/out and
// returns the rows of its study.csv by point name (none, and a failure, when the study failed).
inline std::map<std::string, Row> run_small_study(const std::filesystem::path& dir,
                                                  const std::string& text) {
  const std::filesystem::path f = dir / "study.toml";
  write_file(f, text);
  const Result r =
      run_shell(isphdem() + " study " + f.string() + " --out " + (dir / "out").string() + " -j 2");
  std::printf("%s", r.output.c_str());
  std::map<std::string, Row> by_name;
  if (r.exit_code != 0) {
    ADD_FAILURE() << "the study exited with " << r.exit_code;
    return by_name;
  }
  for (const auto& row : read_csv(dir / "out" / "study.csv")) by_name[row.at("point")] = row;
  return by_name;
}

}  // namespace isphdem::cli
