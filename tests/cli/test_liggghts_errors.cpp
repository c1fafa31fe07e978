// A LIGGGHTS error during `isphdem run` or `isphdem dem` reaches the user: LIGGGHTS's own ERROR
// line on stderr with the command that failed and a hint, a non-zero exit status, a screen file
// that holds LIGGGHTS's output and no stray bytes, and the snapshots written before it intact.
// LIGGGHTS ends the process itself (exit(1) in Error::all, MPI_Abort in Error::one), so each
// case runs the real binary on a broken copy of a shipped example.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <utility>
#include <vector>

#include "../output/h5_read.hpp"
#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

namespace fs = std::filesystem;

// A copy of examples/NAME whose in.liggghts has each `from` replaced by its `to`.
fs::path broken_example(const std::string& test, const std::string& name, const Edits& edits) {
  return edited_example("liggghts_errors_" + test, name, edits);
}

// The screen file holds printable text only, and its last line is LIGGGHTS's ERROR line.
void expect_clean_screen(const fs::path& screen, const std::string& error) {
  const std::string text = read_file(screen);
  ASSERT_FALSE(text.empty()) << screen;
  int stray = 0;
  for (unsigned char c : text) stray += !(c == '\n' || c == '\t' || (c >= 0x20 && c < 0x7f));
  EXPECT_EQ(stray, 0) << "bytes that are not text in " << screen;
  ASSERT_EQ(text.back(), '\n');
  const auto last = text.substr(text.rfind('\n', text.size() - 2) + 1);
  EXPECT_EQ(last.rfind("ERROR: " + error, 0), 0u) << "last line of the screen: " << last;
}

// Every snapshot opens and holds its fluid, and the XDMF names exactly the snapshots on disk.
void expect_valid_snapshots(const fs::path& out, int at_least) {
  std::set<std::string> on_disk;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string f = e.path().filename().string();
    if (f.rfind("snap_", 0) != 0) continue;
    on_disk.insert(f);
    h5_read::File h5(e.path().string());
    const auto x = h5.read("/fluid/position");
    EXPECT_EQ(x.dims.size(), 2u) << f;
    EXPECT_GT(x.dims[0], 0u) << f;
  }
  EXPECT_GE(static_cast<int>(on_disk.size()), at_least);
  const std::string xdmf = read_file(out / "fluid.xdmf");
  std::set<std::string> named;  // every "snap_<digits>.h5" the XDMF names
  for (const auto& step : spans_between(xdmf, "snap_", ".h5", "0123456789"))
    named.insert("snap_" + step + ".h5");
  EXPECT_EQ(named, on_disk);
  std::printf("%zu snapshots written before the error, all readable and in fluid.xdmf\n",
              on_disk.size());
}

Result run_case(const fs::path& dir) {
  const Result r = run((dir / "case.toml").string() + " --out " + (dir / "out").string());
  std::printf("%s", r.output.c_str());
  return r;
}

TEST(LiggghtsErrors, BadPairCoeffIsShownWithTheCommandAndAHint) {
  const auto dir = broken_example("pair_coeff", "settling_grain",
                                  {{"pair_coeff      * *", "pair_coeff      * * bogus"}});
  const Result r = run_case(dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ERROR: Incorrect args for pair coefficients"), 1);
  EXPECT_NE(r.output.find("while running `pair_coeff * * bogus`"), std::string::npos);
  EXPECT_NE(r.output.find("in.liggghts"), std::string::npos);
  EXPECT_NE(r.output.find("hint: granular pair styles take no coefficients"), std::string::npos);
  expect_clean_screen(dir / "out" / "liggghts.screen", "Incorrect args for pair coefficients");
}

TEST(LiggghtsErrors, UnknownFixStyle) {
  const auto dir =
      broken_example("fix_style", "settling_grain", {{"nve all nve/sphere", "nve all nve/spheer"}});
  const Result r = run_case(dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ERROR: Invalid fix style"), 1);
  EXPECT_NE(r.output.find("hint: check the spelling of the fix style"), std::string::npos);
  expect_clean_screen(dir / "out" / "liggghts.screen", "Invalid fix style");
}

TEST(LiggghtsErrors, MultisphereWithOneSphere) {
  const auto dir = broken_example("nspheres", "settling_clump_3d", {{"nspheres 7", "nspheres 1"}});
  const Result r = run_case(dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("illegal number of spheres"), std::string::npos);
  EXPECT_NE(r.output.find("hint: a single sphere is not a multisphere body; use a plain sphere"),
            std::string::npos);
  expect_clean_screen(dir / "out" / "liggghts.screen", "Fix particletemplate/multisphere");
}

TEST(LiggghtsErrors, GrainCreatedOutsideTheBox) {
  // The box ends at y = 0.11 m: create_atoms creates nothing there, and `set` then fails.
  const auto dir = broken_example("outside", "settling_grain",
                                  {{"single 0.01 0.08 0.0005", "single 0.01 0.2 0.0005"}});
  const Result r = run_case(dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("ERROR: Set command with no atoms existing"), std::string::npos);
  EXPECT_NE(r.output.find("outside the simulation box"), std::string::npos);
  expect_clean_screen(dir / "out" / "liggghts.screen", "Set command with no atoms existing");
}

// The grain starts 2.5 mm under the top of a box with a fixed boundary and rises at 0.3 m/s: it
// leaves the box after about 20 ms, two snapshots into the run.
Edits rising_grain_in_low_box(const std::string& before_run) {
  return {{"box block 0 0.02 -0.01 0.11 0 0.001", "box block 0 0.02 -0.01 0.083 0 0.001"},
          {"run             0", "velocity all set 0.0 0.3 0.0\n" + before_run + "run 0"}};
}

TEST(LiggghtsErrors, LostGrainStopsLiggghtsMidRunAndEarlierSnapshotsStayValid) {
  // thermo_modify lost error: LIGGGHTS itself stops on the lost atom (its default ignores it).
  const auto dir = broken_example("lost_liggghts", "settling_grain",
                                  rising_grain_in_low_box("thermo_modify lost error\n"));
  const Result r = run_case(dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ERROR: Lost atoms"), 1);
  EXPECT_NE(r.output.find("while running `run 100 pre no post no` in the DEM substeps"),
            std::string::npos);
  EXPECT_NE(r.output.find("hint: a grain left the DEM box"), std::string::npos);
  expect_clean_screen(dir / "out" / "liggghts.screen", "Lost atoms");
  expect_valid_snapshots(dir / "out", 2);
}

TEST(LiggghtsErrors, GrainLostSilentlyByLiggghtsStopsTheRunByName) {
  const auto dir = broken_example("lost_silent", "settling_grain", rising_grain_in_low_box(""));
  const Result r = run_case(dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("grain 1 left the DEM simulation between t = "), std::string::npos);
  EXPECT_NE(r.output.find("Enlarge the box"), std::string::npos);
  expect_valid_snapshots(dir / "out", 2);
}

TEST(LiggghtsErrors, DemCommandShowsTheErrorToo) {
  const auto dir = broken_example("dem_verb", "settling_grain",
                                  {{"pair_coeff      * *", "pair_coeff      * * bogus"}});
  const Result r = run_shell("cd " + dir.string() + " && " + isphdem() +
                             " dem in.liggghts -log none -screen dem.screen");
  std::printf("%s", r.output.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ERROR: Incorrect args for pair coefficients"), 1);
  EXPECT_NE(r.output.find("in script in.liggghts"), std::string::npos);
  expect_clean_screen(dir / "dem.screen", "Incorrect args for pair coefficients");
}

}  // namespace
}  // namespace isphdem::cli
