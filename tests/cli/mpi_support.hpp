#pragma once
// `isphdem run` under mpirun, and snapshots read back by particle id, for the tests that compare
// a run on several ranks with the same run on one.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "../output/h5_read.hpp"
#include "cli_support.hpp"

namespace isphdem::cli {

// 2 in the default suite; the slow variant sets 4.
inline int ranks() {
  const char* n = std::getenv("ISPHDEM_MPI_RANKS");
  return n ? std::atoi(n) : 2;
}

// Open MPI refuses root unless told (CI runs as root on 2 cores): set here, in the harness only.
inline Result mpirun_run(int np, const std::string& args) {
  return run_shell(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 mpirun "
      "--oversubscribe -np " +
      std::to_string(np) + " " + isphdem() + " run " + args);
}

inline std::filesystem::path last_snapshot(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> snaps;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().rfind("snap_", 0) == 0) snaps.push_back(e.path());
  std::sort(snaps.begin(), snaps.end());
  return snaps.empty() ? std::filesystem::path() : snaps.back();
}

// The case ONE_CASE run with ARGS on one rank and MANY_CASE (the same case, where the DEM script
// needs a processor grid of its own) on ranks(), into scratch(SCRATCH)/np1 and /npN, with the
// pressure solved over the ranks (amg) to 1e-10; returns the two runs' last snapshots. A run that
// fails is a test failure (callers stop on ::testing::Test::HasFailure()), and so is a run on
// several ranks whose fluid rows were not shared between them (result.json): it would test the
// replicated stepping only. The fluid is decomposed unless ARGS say parallel.decompose=false
// (docs/parallel.md).
inline std::pair<std::filesystem::path, std::filesystem::path> run_cases_on_one_and_many(
    const std::string& scratch_name, const std::string& one_case, const std::string& many_case,
    const std::string& args) {
  const auto dir = scratch(scratch_name);
  const std::string tight =
      " --quiet --set solver.preconditioner=amg --set solver.pressure_tolerance=1e-10 ";
  for (const auto& [np, sub] : {std::pair{1, "np1"}, std::pair{ranks(), "npN"}}) {
    const Result r = mpirun_run(
        np, (np == 1 ? one_case : many_case) + " --out " + (dir / sub).string() + tight + args);
    EXPECT_EQ(r.exit_code, 0) << r.output;
  }
  const std::string result = read_file(dir / "npN" / "result.json");
  EXPECT_NE(result.find("\"ranks\": " + std::to_string(ranks())), std::string::npos) << result;
  EXPECT_NE(result.find("\"rows_shared\": true"), std::string::npos) << result;
  const bool decomposed = args.find("parallel.decompose=false") == std::string::npos;
  EXPECT_NE(result.find(std::string("\"decomposed\": ") + (decomposed ? "true" : "false")),
            std::string::npos)
      << result;
  return {last_snapshot(dir / "np1"), last_snapshot(dir / "npN")};
}

// The example NAME on one rank and on ranks() (above).
inline std::pair<std::filesystem::path, std::filesystem::path> run_on_one_and_many(
    const std::string& scratch_name, const std::string& name, const std::string& args) {
  return run_cases_on_one_and_many(scratch_name, example(name), example(name), args);
}

struct Fields {
  int dim = 0;
  std::vector<double> x, v, p;   // sorted by particle id
  std::vector<std::int64_t> id;  // sorted
};

// The group's (fluid, dem, bodies) positions, velocities and, for the fluid, pressures, sorted
// by id.
inline Fields read_fields(const std::filesystem::path& file, const std::string& group = "fluid") {
  h5_read::File f(file.string());
  const auto id = f.read(group + "/id");
  const auto x = f.read(group + "/position"), v = f.read(group + "/velocity");
  const auto p = group == "fluid" ? f.read("fluid/pressure") : h5_read::Array{};
  const std::size_t n = id.i64.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return id.i64[a] < id.i64[b]; });
  Fields out;
  out.dim = static_cast<int>(x.dims.at(1));
  for (const auto k : order) {
    out.id.push_back(id.i64[k]);
    for (int d = 0; d < out.dim; ++d) {
      out.x.push_back(x.f64[k * out.dim + d]);
      out.v.push_back(v.f64[k * out.dim + d]);
    }
    if (!p.f64.empty()) out.p.push_back(p.f64[k]);
  }
  return out;
}

inline double max_difference(const std::vector<double>& a, const std::vector<double>& b,
                             double period = 0.0) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    double d = a[k] - b[k];
    if (period > 0.0) d -= period * std::round(d / period);  // a particle wrapped in one run only
    worst = std::max(worst, std::abs(d));
  }
  return worst;
}

inline double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (const double x : a) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace isphdem::cli
