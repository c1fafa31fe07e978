// Bad input stops `isphdem run` before any output is touched, with a message that names the
// cause (the key, the file, the line) and the fix, and a non-zero exit code.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

const char* kGoodCase = R"(
[case]
dimension = 2
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
periodic = [true, true]
[particles]
spacing = 0.05
[fluid]
viscosity = 0.01
gravity = [0.0, 0.0]
[[fluid.blocks]]
min = [0.0, 0.0]
max = [1.0, 1.0]
[initial]
velocity = "taylor_green"
[solver]
free_surface = false
[time]
end = 0.05
[output]
interval = 0.01
)";

// Runs a bad case into a directory that already holds a previous run's valid output, and checks
// that the failure left that output exactly as it was.
Result run_bad_case(const std::string& name, const std::string& case_text,
                    const std::string& extra = "") {
  const auto dir = scratch(name);
  write_file(dir / "good.toml", kGoodCase);
  const Result good =
      run((dir / "good.toml").string() + " --out " + (dir / "out").string() + " --quiet");
  EXPECT_EQ(good.exit_code, 0) << good.output;
  const int snaps_before = count_snapshots(dir / "out");
  EXPECT_GT(snaps_before, 0);
  const auto xdmf_time = std::filesystem::last_write_time(dir / "out" / "fluid.xdmf");

  write_file(dir / "bad.toml", case_text);
  const Result bad =
      run((dir / "bad.toml").string() + " --out " + (dir / "out").string() + " " + extra);
  EXPECT_NE(bad.exit_code, 0) << bad.output;
  EXPECT_EQ(count_snapshots(dir / "out"), snaps_before) << "bad input touched earlier output";
  EXPECT_EQ(std::filesystem::last_write_time(dir / "out" / "fluid.xdmf"), xdmf_time);
  std::printf("%s: exit %d: %s", name.c_str(), bad.exit_code, bad.output.c_str());
  return bad;
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(BadInput, MalformedTomlNamesTheLine) {
  const Result r = run_bad_case("malformed", with(kGoodCase, "[domain]", "[domain"));
  EXPECT_NE(r.output.find("malformed case file"), std::string::npos);
  EXPECT_NE(r.output.find("line 4"), std::string::npos);  // the text starts with a newline
}

TEST(BadInput, MisspeltKeySuggestsTheClosest) {
  const Result r = run_bad_case("misspelt", with(kGoodCase, "spacing = 0.05", "spaceing = 0.05"));
  EXPECT_NE(r.output.find("unknown key 'particles.spaceing'"), std::string::npos);
  EXPECT_NE(r.output.find("did you mean 'particles.spacing'"), std::string::npos);
}

TEST(BadInput, MisspeltOverrideSuggestsTheClosest) {
  const Result r = run_bad_case("misspelt_set", kGoodCase, "--set time.ned=1");
  EXPECT_NE(r.output.find("unknown key 'time.ned' (--set)"), std::string::npos);
  EXPECT_NE(r.output.find("did you mean 'time.end'"), std::string::npos);
}

TEST(BadInput, ZeroAndNegativeSpacing) {
  for (const char* v : {"0.0", "-0.01"}) {
    const Result r = run_bad_case(std::string("spacing") + v,
                                  with(kGoodCase, "spacing = 0.05", std::string("spacing = ") + v));
    EXPECT_NE(r.output.find("'particles.spacing'"), std::string::npos);
    EXPECT_NE(r.output.find("positive"), std::string::npos);
  }
}

TEST(BadInput, WrongTypeNamesTheExpectedType) {
  const Result r = run_bad_case(
      "wrong_type", with(kGoodCase, "max = [1.0, 1.0]\nperiodic", "max = [1.0]\nperiodic"));
  EXPECT_NE(r.output.find("'domain.max'"), std::string::npos);
  EXPECT_NE(r.output.find("an array of 2 numbers"), std::string::npos);
}

TEST(BadInput, NegativeInflowRamp) {
  const Result r = run_bad_case(
      "inflow_ramp", with(kGoodCase, "[time]",
                          "[inflow]\nmin = [0.2, 0.2]\nmax = [0.4, 0.4]\nvelocity = 0.01\n"
                          "direction = [0.0, 1.0]\nramp = -0.5\n[time]"));
  EXPECT_NE(r.output.find("'inflow.ramp' must be >= 0"), std::string::npos);
}

TEST(BadInput, SurfaceRemeshNeedsAFreeSurfaceUnderGravity) {
  const Result r = run_bad_case(
      "surface_remesh",
      with(kGoodCase, "free_surface = false", "free_surface = false\nsurface_remesh_rows = 4"));
  EXPECT_NE(r.output.find("solver.surface_remesh_rows needs a free surface under gravity"),
            std::string::npos);
  const Result n = run_bad_case(
      "surface_remesh_rows", with(kGoodCase, "free_surface = false", "surface_remesh_rows = -1"));
  EXPECT_NE(n.output.find("'solver.surface_remesh_rows' must be >= 0"), std::string::npos);
}

TEST(BadInput, InflowStartWithoutForcingZone) {
  const Result r = run_bad_case(
      "inflow_start", with(kGoodCase, "velocity = \"taylor_green\"", "velocity = \"inflow\""));
  EXPECT_NE(r.output.find("add an [inflow] zone"), std::string::npos);
}

TEST(BadInput, UnstableExplicitTimeStepNamesTheLimit) {
  const Result r =
      run_bad_case("unstable_dt", with(kGoodCase, "end = 0.05", "end = 0.05\ndt = 0.1"));
  EXPECT_NE(r.output.find("time.dt = 0.1"), std::string::npos);
  EXPECT_NE(r.output.find("beyond the stable limit"), std::string::npos);
  EXPECT_NE(r.output.find("\"auto\""), std::string::npos);
}

TEST(BadInput, MissingCaseFile) {
  const auto dir = scratch("missing");
  const Result r = run((dir / "nope.toml").string() + " --out " + (dir / "out").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(BadInput, MissingOutOption) {
  const Result r = run(example("taylor_green_2d"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--out DIR"), std::string::npos) << r.output;
}

TEST(BadInput, ParticleOutsideTheDomain) {
  const Result r =
      run_bad_case("outside", with(kGoodCase, "min = [0.0, 0.0]\nmax = [1.0, 1.0]\n[initial]",
                                   "min = [0.0, 0.0]\nmax = [1.5, 1.0]\n[initial]"));
  EXPECT_NE(r.output.find("outside the domain"), std::string::npos);
  EXPECT_NE(r.output.find("enlarge domain"), std::string::npos);
}

// Coupled cases (fluid + [dem] + [unresolved]): the fluid step must be fixed, and
// [unresolved] needs both sides.
TEST(BadInput, CoupledCaseNeedsAFixedTimeStep) {
  const std::string script =
      std::string(ISPHDEM_SOURCE_DIR) + "/examples/settling_grain/in.liggghts";
  const Result r = run_bad_case(
      "coupled_auto_dt",
      with(kGoodCase, "[time]",
           "[unresolved]\ngrain_diameter = 1e-3\nslab_thickness = 1e-3\n[dem]\nscript = \"" +
               script + "\"\nsubsteps = 100\n[time]"));
  EXPECT_NE(r.output.find("a coupled case needs a fixed fluid step: set time.dt"),
            std::string::npos);
}

// A coupled case refused after the DEM script has run (here the fluid step beyond the force
// limit, found when the fluid is built) must stop with its own message. With a multisphere
// restart LIGGGHTS refused to close before a run had set the clumps up (an error inside its
// destructor: a segmentation fault instead of the message).
TEST(BadInput, CoupledCaseRefusedAfterAMultisphereRestartShowsItsMessage) {
  const auto dir = scratch("coupled_refused_after_restart");
  const Result r = run(reduced_case() + " --out " + (dir / "out").string() +
                       " --set time.dt=5e-3 --set dem.substeps=5000");
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("is beyond the stable limit"), std::string::npos);
  EXPECT_NE(r.output.find("force limit"), std::string::npos);
  // A coupled step cannot be "auto": the advice names the DEM substeps instead.
  EXPECT_NE(r.output.find("and [dem] substeps with it"), std::string::npos);
  EXPECT_EQ(r.output.find("use \"auto\""), std::string::npos);
  EXPECT_EQ(r.output.find("Segmentation fault"), std::string::npos);
  EXPECT_EQ(r.output.find("LIGGGHTS stopped the run"), std::string::npos);
}

// TOML admits nan, inf and -inf as numbers. Every numeric key refuses them when the case is read,
// naming the key (with the element's index) and its line, or --set: before, a NaN viscosity
// started the run and stopped it later ("pressure solver failed ... relative residual nan").

// "bad.toml:N: " for the line of TEXT that holds NEEDLE (after the first newline of it).
std::string bad_toml_line(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  const auto line = 1 + std::count(text.begin(), text.begin() + at, '\n');
  return "bad.toml:" + std::to_string(line) + ": ";
}

const char* kNotFinite = " is not a finite number; give a number such as 1e-6";

TEST(BadInput, NanScalarFromSetIsRefusedBeforeAnyStep) {
  const Result r = run_bad_case("nan_scalar_set", kGoodCase, "--set fluid.viscosity=nan");
  EXPECT_NE(r.output.find(std::string("fluid.viscosity = nan (from --set)") + kNotFinite),
            std::string::npos);
  EXPECT_EQ(r.output.find("pressure solver"), std::string::npos);
}

TEST(BadInput, NanInAVectorNamesTheElementAndLine) {
  const std::string text = with(kGoodCase, "gravity = [0.0, 0.0]", "gravity = [0.0, nan]");
  const Result r = run_bad_case("nan_vector", text);
  EXPECT_NE(r.output.find(bad_toml_line(text, "gravity =") + "fluid.gravity[1] = nan" + kNotFinite),
            std::string::npos);
  const Result s = run_bad_case("nan_vector_set", kGoodCase, "--set 'fluid.gravity=[0, nan]'");
  EXPECT_NE(s.output.find(std::string("fluid.gravity[1] = nan (from --set)") + kNotFinite),
            std::string::npos);
}

TEST(BadInput, NanInATableEntryNamesTheEntry) {
  // An element of an array of tables, by its index.
  const std::string block =
      with(kGoodCase, "[[fluid.blocks]]\nmin = [0.0, 0.0]", "[[fluid.blocks]]\nmin = [nan, 0.0]");
  const Result b = run_bad_case("nan_fluid_block", block);
  EXPECT_NE(b.output.find(bad_toml_line(block, "min = [nan") + "fluid.blocks[0].min[0] = nan" +
                          kNotFinite),
            std::string::npos);
  const std::string walls = std::string(kGoodCase) +
                            "[[walls.blocks]]\nmin = [0.0, 0.0]\nmax = [0.3, 0.3]\n"
                            "[[walls.blocks]]\nmin = [0.5, nan]\nmax = [0.6, 0.6]\n";
  const Result w = run_bad_case("nan_walls_block", walls);
  EXPECT_NE(w.output.find(bad_toml_line(walls, "min = [0.5, nan]") +
                          "walls.blocks[1].min[1] = nan" + kNotFinite),
            std::string::npos);
  // A [[reference.metrics]] number and a free-form table's entry.
  const std::string metric = std::string(kGoodCase) +
                             "[[reference.metrics]]\nname = \"speed\"\n"
                             "value = \"last(max_speed)\"\nexpected = nan\n";
  const Result m = run_bad_case("nan_reference_metric", metric);
  EXPECT_NE(m.output.find(bad_toml_line(metric, "expected = nan") +
                          "reference.metrics[0].expected = nan" + kNotFinite),
            std::string::npos);
  const std::string variables = std::string(kGoodCase) +
                                "[dem]\nscript = \"in.liggghts\"\nsubsteps = 10\n"
                                "[dem.variables]\nnfines = 32\nd = nan\n";
  const Result v = run_bad_case("nan_dem_variable", variables);
  EXPECT_NE(
      v.output.find(bad_toml_line(variables, "d = nan") + "dem.variables.d = nan" + kNotFinite),
      std::string::npos);
}

TEST(BadInput, InfinityIsRefusedToo) {
  const std::string text = with(kGoodCase, "spacing = 0.05", "spacing = inf");
  const Result r = run_bad_case("inf_scalar", text);
  EXPECT_NE(
      r.output.find(bad_toml_line(text, "spacing = inf") + "particles.spacing = inf" + kNotFinite),
      std::string::npos);
  const Result s = run_bad_case("inf_scalar_set", kGoodCase, "--set time.end=-inf");
  EXPECT_NE(s.output.find(std::string("time.end = -inf (from --set)") + kNotFinite),
            std::string::npos);
}

// In a coupled case the fluid's viscosity is named as the fluid's key: it was blamed on
// [unresolved], whose drag law divides by it ("[unresolved]: drag: kinematic viscosity must be
// > 0"), whether NaN or 0.
TEST(BadInput, CoupledCaseNamesTheFluidsViscosity) {
  const auto dir = scratch("coupled_viscosity");
  const std::string base = example("settling_grain") + " --out " + (dir / "out").string();
  const Result nan = run(base + " --set fluid.viscosity=nan");
  std::printf("%s", nan.output.c_str());
  EXPECT_EQ(nan.exit_code, 2);
  EXPECT_NE(nan.output.find(std::string("fluid.viscosity = nan (from --set)") + kNotFinite),
            std::string::npos);
  EXPECT_EQ(nan.output.find("[unresolved]:"), std::string::npos);
  const Result zero = run(base + " --set fluid.viscosity=0.0");
  std::printf("%s", zero.output.c_str());
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.output.find("'fluid.viscosity' (--set) must be positive in a case with "
                             "[unresolved]"),
            std::string::npos);
  EXPECT_EQ(zero.output.find("[unresolved]:"), std::string::npos);
  EXPECT_EQ(count_snapshots(dir / "out"), 0);
}

// A fresh clone has no packing: reduced.toml's script reads packing_reduced.restart, which only
// `isphdem dem in.packing -var ...` makes. Before this check LIGGGHTS stopped with "Cannot open
// restart file" and an MPI_ABORT banner; now the run stops before LIGGGHTS starts and prints the
// case's [dem] prepare command, with this isphdem's path, to paste.
TEST(BadInput, MissingPackingNamesTheCommandThatMakesIt) {
  const auto dir = scratch("missing_packing");  // empty: no packing_reduced.restart in it
  const Result r =
      run(std::string(ISPHDEM_SOURCE_DIR) + "/examples/internal_erosion_2d/reduced.toml --out " +
          (dir / "out").string() + " --set 'dem.variables.packing_dir=\"" + dir.string() + "\"'");
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("[dem] the script in.liggghts (line 16: read_restart) reads '" +
                          (dir / "packing_reduced.restart").string() + "', which does not exist"),
            std::string::npos);
  EXPECT_EQ(count(r.output, "Make it first ([dem] prepare in the case file):\n  cd " +
                                std::string(ISPHDEM_SOURCE_DIR) +
                                "/examples/internal_erosion_2d && " + isphdem() +
                                " dem in.packing -var packing packing_reduced.restart -var "
                                "nclumps 6 -var nfines 32 -var x_lo 0.010 -var x_hi 0.026 -var "
                                "mesh_y 0.014 -var box_x 0.036 -var box_y 0.07\n"),
            1);
  EXPECT_EQ(r.output.find("MPI_ABORT"), std::string::npos);
  EXPECT_EQ(r.output.find("Cannot open restart file"), std::string::npos);
  EXPECT_EQ(r.output.find("LIGGGHTS stopped the run"), std::string::npos);
  // LIGGGHTS never started: it writes its screen file (liggghts.screen) as it starts.
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "liggghts.screen"));
}

TEST(BadInput, UnresolvedWithoutDemNamesBothTables) {
  const Result r = run_bad_case(
      "unresolved_alone", with(kGoodCase, "[time]", "[unresolved]\ngrain_diameter = 1e-3\n[time]"));
  EXPECT_NE(r.output.find("[unresolved] couples a fluid with [dem] grains"), std::string::npos);
}

}  // namespace
}  // namespace isphdem::cli
