// `isphdem run` end to end: the output contract on disk, read back as ParaView reads it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

// result.json's stage_seconds (bench/fluid/run_profile.sh reads them): every stage of the fluid
// step, each measured (> 0 where the run has that work, none negative), and the parts of the
// wall time adding up to no more than it (the "output" part is what they leave). `extra`: the
// parts a coupled run adds. Exit status 0 when all hold.
int check_stage_seconds(const std::filesystem::path& out, const std::string& extra) {
  const std::string script =
      "import json,sys; r=json.load(open(sys.argv[1])); s=r['stage_seconds']; "
      "fluid=['neighbours','free_surface','operators','predictor','pressure_rhs','assembly',"
      "'solve_setup','solve_iterations','correction','shifting','advection','other']; "
      "need=fluid+[k for k in sys.argv[2].split(',') if k]+['output']; missing=[k for k in need if "
      "k not in s]; "
      "parts=sum(s[k] for k in need); print('stage_seconds', s, 'wall', r['wall_seconds']); "
      "ok=not missing and min(s.values())>=0 and s['neighbours']>0 and s['solve_iterations']>0 "
      "and all(s[k]>0 for k in [k for k in sys.argv[2].split(',') if k]) "
      "and abs(parts-r['wall_seconds'])<=1e-3*r['wall_seconds'] and s['output']>0; "
      "print('missing', missing); sys.exit(0 if ok else 1)";
  return std::system(("/usr/bin/python3 -c \"" + script + "\" " + (out / "result.json").string() +
                      " " + extra + ",")
                         .c_str());
}

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
  if (std::filesystem::exists("/usr/bin/python3")) {
    EXPECT_EQ(check_stage_seconds(dir / "out", ""), 0);
  }

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

// A coupled case (fluid + [dem] + [unresolved]) through `isphdem run`: /dem with force_hydro,
// dem.xdmf, the coupled diagnostics columns and the cost split.
TEST(RunOutput, CoupledCaseWritesDemLoadsAndBedHeight) {
  const auto dir = scratch("coupled");
  const Result r = run(example("settling_grain") + " --out " + (dir / "out").string() +
                       " --set time.end=0.02 --set output.interval=0.01");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("DEM substeps"), std::string::npos) << r.output;
  EXPECT_EQ(count_snapshots(dir / "out"), 3);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "dem.xdmf"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "fluid.xdmf"));
  std::ifstream csv(dir / "out" / "diagnostics.csv");
  std::string header;
  std::getline(csv, header);
  for (const char* col : {"bed_height", "max_grain_speed", "max_body_speed", "min_porosity",
                          "drag_total_up", "dem_seconds", "coupling_seconds", "fluid_seconds"})
    EXPECT_NE(header.find(col), std::string::npos) << col;
  // The grain's hydrodynamic load after 0.02 s: buoyancy plus drag, upward, below its weight.
  if (!std::filesystem::exists("/usr/bin/python3")) GTEST_SKIP() << "no /usr/bin/python3";
  EXPECT_EQ(check_stage_seconds(dir / "out", "coupling,dem"), 0);
  const std::string script =
      "import h5py,sys; f=h5py.File(sys.argv[1]); fy=f['dem/force_hydro'][0][1]; "
      "w=2600*9.81*3.14159265/6*1e-9; print('force_hydro_y/weight', fy/w); "
      "sys.exit(0 if 0.3 < fy/w < 1.0 else 1)";
  const int rc = std::system(
      ("/usr/bin/python3 -c \"" + script + "\" " + (dir / "out" / "snap_00000200.h5").string())
          .c_str());
  EXPECT_EQ(rc, 0);
}

}  // namespace
}  // namespace isphdem::cli
