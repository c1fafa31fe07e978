#pragma once
// What the tests of checkpoints and --resume share (test_resume, test_resume_mpi): snapshots
// compared bit for bit, diagnostics.csv without its wall-clock column, the .xdmf's times, and a
// run signalled once a condition holds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../output/h5_read.hpp"
#include "cli_support.hpp"
#include "mpi_support.hpp"

namespace isphdem::cli {

namespace fs = std::filesystem;

inline std::vector<fs::path> files_named(const fs::path& dir, const std::string& prefix) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

// Every dataset of /fluid and the root attributes, bit for bit (storage order).
inline void expect_same_snapshot(const fs::path& a, const fs::path& b) {
  ASSERT_EQ(a.filename(), b.filename());
  h5_read::File fa(a.string()), fb(b.string());
  EXPECT_EQ(fa.attribute_f64("time"), fb.attribute_f64("time"));
  EXPECT_EQ(fa.attribute_i64("step"), fb.attribute_i64("step"));
  for (const char* name :
       {"position", "velocity", "pressure", "porosity", "kind", "free_surface", "id"}) {
    const std::string path = std::string("fluid/") + name;
    const h5_read::Array x = fa.read(path), y = fb.read(path);
    EXPECT_EQ(x.dims, y.dims) << path;
    EXPECT_TRUE(x.f64 == y.f64) << path << " differs in " << a.filename();
    EXPECT_TRUE(x.i64 == y.i64) << path;
    EXPECT_TRUE(x.i32 == y.i32) << path;
  }
}

// The rows without their wall-clock column, as text (the shortest round-trip spelling: equal
// text is equal bits).
inline std::vector<Row> diagnostics_without_wall(const fs::path& dir) {
  auto rows = read_csv(dir / "diagnostics.csv");
  for (auto& r : rows) r.erase("wall_seconds");
  return rows;
}

// The Time values fluid.xdmf lists, in order.
inline std::vector<std::string> xdmf_times(const fs::path& dir) {
  return spans_between(read_file(dir / "fluid.xdmf"), "<Time Value=\"", "\"", "0123456789.e-+");
}

// Runs `isphdem run ARGS --out OUT` in the background and sends SIGNAL once `ready` (a shell test)
// holds; returns the run's exit status (-1 when it never ended) and output. LAUNCH is what goes
// before the executable ("" or "mpirun ... -np N ").
inline Result run_and_signal(const fs::path& out, const std::string& args,
                             const std::string& signal, const std::string& ready,
                             const std::string& launch = "") {
  const std::string script = "(" + launch + isphdem() + " run " + args + " --out " + out.string() +
                             " > " + (out.string() + ".log") +
                             " 2>&1 & pid=$!; for i in $(seq 1 30000); do " + ready +
                             " && break; kill -0 $pid 2> /dev/null || break; sleep 0.01; done; "
                             "kill -" +
                             signal + " $pid; wait $pid; echo \"exit=$?\")";
  Result r = run_shell(script);
  r.output += read_file(out.string() + ".log");
  const auto at = r.output.find("exit=");
  r.exit_code = at == std::string::npos ? -1 : std::stoi(r.output.substr(at + 5));
  return r;
}

// The fluid, grain and body positions of two coupled snapshots, the same ids in each group and
// no position further than `tolerance` m apart (the largest distance printed per group).
inline void expect_positions_within(const fs::path& ours, const fs::path& theirs,
                                    double tolerance) {
  for (const char* group : {"fluid", "dem", "bodies"}) {
    const Fields a = read_fields(ours, group), b = read_fields(theirs, group);
    ASSERT_EQ(a.id, b.id) << group;
    const double moved = max_difference(a.x, b.x);
    std::printf("%s: positions differ by up to %.3g m\n", group, moved);
    EXPECT_LT(moved, tolerance) << group;
  }
}

// A checkpoint is in OUT.
inline std::string has_checkpoint(const fs::path& out) {
  return "ls -d " + out.string() + "/checkpoint_* > /dev/null 2>&1";
}

}  // namespace isphdem::cli
