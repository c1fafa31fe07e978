// A run whose fixed time step passes the start-up checks but is far beyond the CFL limit once
// the flow speeds up must stop with a message that names the cause and the fix, exit non-zero,
// and leave every snapshot it wrote readable (never NaN-filled files).
#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

TEST(UnstableRun, StopsCleanlyWithOutputIntact) {
  const auto dir = scratch("unstable");
  // Dam break at dx = 5 mm: still water passes the force limit (8.9 ms) with dt = 5 ms, but the
  // surge reaches ~1.5 m/s, where the CFL limit is below 1 ms.
  const Result r =
      run(example("dam_break_2d") + " --out " + (dir / "out").string() +
          " --set particles.spacing=0.005 --set time.dt=0.005 --set output.interval=0.01");
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("beyond the CFL limit"), std::string::npos);
  EXPECT_NE(r.output.find("time.dt = \"auto\""), std::string::npos);
  // ... and says where: a fluid particle of the surge, with its support (no solids here).
  EXPECT_NE(r.output.find("the fastest is fluid particle"), std::string::npos);
  EXPECT_NE(r.output.find(" 0 solid and "), std::string::npos);
  EXPECT_NE(r.output.find("complete and valid"), std::string::npos);
  const int snaps = count_snapshots(dir / "out");
  EXPECT_GE(snaps, 2);
  // result.json says how it ended, for `isphdem study` and scripts.
  std::ifstream json(dir / "out" / "result.json");
  const std::string result((std::istreambuf_iterator<char>(json)), {});
  EXPECT_NE(result.find("\"status\": \"stopped\""), std::string::npos) << result;
  EXPECT_NE(result.find("beyond the CFL limit"), std::string::npos) << result;
  EXPECT_NE(result.find("\"cause\": \"cfl\""), std::string::npos) << result;

  if (!has_pvpython()) GTEST_SKIP() << "pvpython not installed";
  // ParaView loads every step listed in the XDMF.
  EXPECT_EQ(paraview_check(dir / "out", "--steps " + std::to_string(snaps)), 0);
}

// A DEM step as long as the contact (dem_dt = t_c / 1.6 in the fluidization column, the seed's
// is t_c / 16) lets grains pass into each other in one fluid step: the run stops on the overlap,
// naming both grains and the fix, instead of running on with grains flung apart.
TEST(UnstableRun, DemStepTooLongForTheContactStopsOnGrainOverlap) {
  const auto dir = scratch("overlap");
  const Result r = run(example("fluidization_2d") + " --out " + (dir / "out").string() +
                       " --set time.end=0.01 --set dem.variables.dem_dt=1e-5"
                       " --set dem.substeps=10 --set output.interval=0.001");
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("of the smaller radius"), std::string::npos);
  EXPECT_NE(r.output.find("Shorten the DEM timestep"), std::string::npos);
  EXPECT_GE(count_snapshots(dir / "out"), 1);  // the initial state, complete
  std::ifstream json(dir / "out" / "result.json");
  const std::string result((std::istreambuf_iterator<char>(json)), {});
  EXPECT_NE(result.find("\"cause\": \"grain_overlap\""), std::string::npos) << result;
  // The seed's DEM step in the same column: no contact goes deeper than a thousandth of a radius.
  const Result ok = run(example("fluidization_2d") + " --out " + (dir / "ok").string() +
                        " --set time.end=0.01 --set output.interval=0.01");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  const auto rows = read_csv(dir / "ok" / "diagnostics.csv");
  ASSERT_FALSE(rows.empty());
  ASSERT_EQ(rows.back().count("max_overlap"), 1u);
  const double deepest = std::stod(rows.back().at("max_overlap"));
  EXPECT_LT(deepest, 1e-3);
  EXPECT_GE(deepest, 0.0);
}

}  // namespace
}  // namespace isphdem::cli
