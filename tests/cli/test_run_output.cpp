// `isphdem run` end to end: the output contract on disk, read back as ParaView reads it.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

TEST(RunOutput, TaylorGreenWritesTheContractAndParaViewReadsIt) {
  const auto dir = scratch("taylor_green");
  // 20 x 20 particles, 5 snapshot intervals; --set overrides as a user gives them.
  const Result r =
      run(example("taylor_green_2d") + " --out " + (dir / "out").string() +
          " --set particles.spacing=0.05 --set time.end=0.1 --set output.interval=0.02");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("particle-steps/s"), std::string::npos) << r.output;
  EXPECT_EQ(count_snapshots(dir / "out"), 6);  // t = 0, 0.02, ..., 0.1
  ASSERT_TRUE(std::filesystem::exists(dir / "out" / "fluid.xdmf"));
  ASSERT_TRUE(std::filesystem::exists(dir / "out" / "case_used.toml"));

  std::ifstream csv(dir / "out" / "diagnostics.csv");
  std::string header;
  std::getline(csv, header);
  for (const char* col : {"time", "step", "wall_seconds", "ppe_iterations", "max_speed"})
    EXPECT_NE(header.find(col), std::string::npos) << col;
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_GT(rows, 0);

  if (!has_pvpython()) GTEST_SKIP() << "pvpython not installed";
  EXPECT_EQ(paraview_check(dir / "out",
                           "--steps 6 --expect fluid=400:pressure,velocity/3,porosity,kind,id"),
            0);
}

TEST(RunOutput, ProgressLineIsQuietWhenNotATerminal) {
  const auto dir = scratch("quiet");
  const Result r = run(example("taylor_green_2d") + " --out " + (dir / "out").string() +
                       " --set particles.spacing=0.05 --set time.end=0.02");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "progress redraws leaked into a pipe";
}

}  // namespace
}  // namespace isphdem::cli
