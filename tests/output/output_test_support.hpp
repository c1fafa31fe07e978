// Shared by the output tests: a scratch directory per test, sample snapshots with known contents,
// and running external programs (pvpython, python3).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/snapshot.hpp"

namespace output_test {

namespace fs = std::filesystem;

// build/test_output/<suite>.<test>, emptied first and left behind for inspection.
inline fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(ISPHDEM_BINARY_DIR) / "test_output" /
                       (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::set<std::string> file_names(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Fluid block of `n` particles in `dim` dimensions; every value depends on (step, particle, column)
// so a wrong row, column, step or dataset shows up. The last quarter are walls (kind 1).
inline void add_fluid(isphdem::Snapshot& s, std::size_t n, int dim) {
  auto& g = s.group("fluid");
  const double t = static_cast<double>(s.step);
  g.add_generated<double>("position", n, dim, [&](std::size_t i, std::size_t c) {
    return 0.01 * static_cast<double>(i % 10) +
           (c == 1 ? 0.013 * static_cast<double>(i / 10) : 0.0) + (c == 2 ? 0.1 : 0.0);
  });
  g.add_generated<double>("velocity", n, dim, [&](std::size_t i, std::size_t c) {
    return 1e-3 * (i + 1) * (c + 1) + t;
  });
  g.add_generated<double>("pressure", n, 1,
                          [&](std::size_t i, std::size_t) { return 1000.0 + i + 0.5 * t; });
  g.add_generated<double>("porosity", n, 1,
                          [&](std::size_t i, std::size_t) { return 0.4 + 0.5 * i / n; });
  g.add_generated<std::int32_t>("kind", n, 1,
                                [&](std::size_t i, std::size_t) { return i >= 3 * n / 4 ? 1 : 0; });
  g.add_generated<std::int64_t>("id", n, 1, [&](std::size_t i, std::size_t) {
    return static_cast<std::int64_t>(i) + (1LL << 40);
  });
}

inline void add_dem(isphdem::Snapshot& s, std::size_t m) {
  auto& g = s.group("dem");
  g.add_generated<double>("position", m, 3,
                          [&](std::size_t i, std::size_t c) { return 0.002 * i + 0.1 * c; });
  g.add_generated<double>("velocity", m, 3,
                          [&](std::size_t i, std::size_t c) { return -0.1 * i * (c + 1); });
  g.add_generated<double>("radius", m, 1,
                          [&](std::size_t i, std::size_t) { return 5e-4 + 1e-5 * i; });
  g.add_generated<std::int64_t>("id", m, 1, [&](std::size_t i, std::size_t) { return i + 1; });
  g.add_generated<std::int64_t>("body", m, 1,
                                [&](std::size_t i, std::size_t) { return i % 2 ? -1 : 0; });
  g.add_generated<double>("force_hydro", m, 3,
                          [&](std::size_t i, std::size_t c) { return 1e-6 * i - 1e-7 * c; });
}

inline void add_bodies(isphdem::Snapshot& s, std::size_t b) {
  auto& g = s.group("bodies");
  auto vec = [&](const char* name, std::size_t cols, double scale) {
    g.add_generated<double>(name, b, cols,
                            [&](std::size_t i, std::size_t c) { return scale * (i + 1) + c; });
  };
  vec("position", 3, 0.01);
  vec("velocity", 3, 0.1);
  vec("omega", 3, 1.0);
  vec("quat", 4, 0.25);
  vec("mass", 1, 1e-3);
  vec("volume", 1, 1e-6);
  vec("force_hydro", 3, 1e-5);
  vec("torque_hydro", 3, 1e-8);
}

inline isphdem::Snapshot sample(long step, double time, std::size_t fluid, int dim,
                                std::size_t grains = 0, std::size_t bodies = 0) {
  isphdem::Snapshot s;
  s.step = step;
  s.time = time;
  add_fluid(s, fluid, dim);
  if (grains) add_dem(s, grains);
  if (bodies) add_bodies(s, bodies);
  return s;
}

struct Result {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs a shell command line, capturing its output.
inline Result run(const std::string& command) {
  Result r;
  std::FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Full path of `program` on PATH, or "" if absent.
inline std::string find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const fs::path p = fs::path(dir.empty() ? "." : dir) / program;
    if (access(p.c_str(), X_OK) == 0) return p.string();
  }
  return "";
}

}  // namespace output_test
