// `mpirun -np N isphdem run` on fluid-only cases (each rank holds and steps its own part of the
// fluid, or with parallel.decompose = false every rank holds the fluid and computes its block of
// rows of each stage; the PPE one PETSc system over the ranks): the same result as one rank to
// solver tolerance, and a run that must stop stops every rank with one message and valid output.
//
// "To solver tolerance" is checked over a few steps, at solver.pressure_tolerance = 1e-10, in max
// norms: positions in units of dx, velocities of the flow's speed scale, pressures of the largest
// |p|. Over longer runs the particle arrangement of the two runs parts (Taylor-Green: 2e-8 m at
// step 10, 5e-3 m at step 20), exactly as two one-rank runs at tolerances 1e-8 and 1e-10 do
// (docs/parallel.md): the comparison then is of the flow's observables, not of particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mpi_support.hpp"

namespace isphdem::cli {
namespace {

// Runs CASE with ARGS on one rank and on ranks(), and compares their last snapshots.
void expect_same_as_one_rank(const std::string& name, const std::string& args, double dx,
                             double speed, double period, double bound = 1e-5) {
  const auto [a_file, b_file] = run_on_one_and_many("fluid_mpi_" + name, name, args);
  ASSERT_FALSE(::testing::Test::HasFailure());
  ASSERT_EQ(a_file.filename(), b_file.filename()) << "the runs took different steps";
  const Fields a = read_fields(a_file), b = read_fields(b_file);
  ASSERT_EQ(a.p.size(), b.p.size());
  // The ranks wrote the file together, each its rows: every particle once.
  EXPECT_EQ(a.id, b.id);
  const double dxs = max_difference(a.x, b.x, period) / dx;
  const double dv = max_difference(a.v, b.v) / speed;
  const double dp = max_difference(a.p, b.p) / max_abs(a.p);
  std::printf(
      "%s, 1 vs %d ranks at %s: max |dx| = %.2e dx, max |dv| = %.2e U, "
      "max |dp| = %.2e max|p|\n",
      name.c_str(), ranks(), a_file.filename().c_str(), dxs, dv, dp);
  // Measured (2 ranks, decomposed): 3e-9 / 2e-10 / 2e-9 (Taylor-Green), 3e-10 / 1e-10 / 2e-9
  // (tank), 9e-7 / 1.4e-7 / 3e-7 (dam break, whose toe amplifies: two one-rank runs at
  // tolerances 1e-10 and 1e-11 differ there by 5e-7 dx). A wrong row block, halo or gather gives
  // differences of order 1.
  EXPECT_LE(dxs, bound);
  EXPECT_LE(dv, bound);
  EXPECT_LE(dp, bound);
}

TEST(FluidMpi, TaylorGreenMatchesOneRank) {
  // 10 steps of the periodic vortex (U = 1 m/s, dx = 0.02 m).
  expect_same_as_one_rank("taylor_green_2d", "--set time.end=0.05 --set output.interval=0.05", 0.02,
                          1.0, 1.0);
}

TEST(FluidMpi, TaylorGreenWithSharedRowsMatchesOneRank) {
  // The same vortex with every rank holding the whole fluid (parallel.decompose = false).
  expect_same_as_one_rank("taylor_green_2d",
                          "--set time.end=0.05 --set output.interval=0.05 "
                          "--set parallel.decompose=false",
                          0.02, 1.0, 1.0);
}

TEST(FluidMpi, HydrostaticTankMatchesOneRank) {
  // Free surface and walls; speeds are round-off, so pressures and positions are compared and
  // velocities against sqrt(g H) (H = 0.2 m).
  expect_same_as_one_rank("hydrostatic_2d", "--set time.end=0.1 --set output.interval=0.1", 0.005,
                          std::sqrt(9.81 * 0.2), 0.0);
}

TEST(FluidMpi, CirculationTankWithSurfaceRemeshMatchesOneRank) {
  // The seed's tank under its surface remesh (every 50 steps: five remeshes in 0.03 s), each rank
  // holding its part of the fluid: the remeshed rows are gathered from the ranks, remeshed alike
  // and handed back (sph/surface_remesh.hpp). Velocities against 1 cm/s, twice the pumped 5 mm/s.
  // A rank remeshing only its own part of the surface gives differences of order dx.
  expect_same_as_one_rank("circulation_tank_2d", "--set time.end=0.03 --set output.interval=0.03",
                          0.001, 0.01, 0.0);
}

TEST(FluidMpi, DamBreakMatchesOneRank) {
  // The column's first 0.03 s (automatic time step: the runs must also agree on the steps).
  // Decomposed over 4 ranks the toe's particles differ by 1.1e-5 dx at tolerance 1e-10 and by
  // 7.6e-8 dx at 1e-12 (the solver's tolerance, amplified, not the decomposition): 5e-5 here.
  expect_same_as_one_rank("dam_break_2d", "--set time.end=0.03 --set output.interval=0.03", 0.0025,
                          std::sqrt(2 * 9.81 * 0.1), 0.0, 5e-5);
}

TEST(FluidMpi, UnstableRunStopsEveryRankWithOneMessage) {
  // As test_unstable_run: a fixed step far beyond the CFL limit once the surge speeds up.
  const auto dir = scratch("fluid_mpi_unstable");
  const Result r =
      mpirun_run(ranks(), example("dam_break_2d") + " --out " + (dir / "out").string() +
                              " --set solver.preconditioner=amg"
                              " --set particles.spacing=0.005 --set time.dt=0.005"
                              " --set output.interval=0.01");
  std::printf("%s", r.output.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "beyond the CFL limit"), 1);
  EXPECT_EQ(count(r.output, "complete and valid"), 1);
  // The particle named is the fastest of all ranks (decomposed, each rank knows its own).
  const auto quoted = spans_between(r.output, "max |u| = ", " m/s");
  const auto named = spans_between(r.output, "m (", " m/s)");
  ASSERT_FALSE(quoted.empty());
  ASSERT_FALSE(named.empty());
  EXPECT_EQ(quoted.front(), named.front());
  int snaps = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "out")) {
    if (e.path().filename().string().rfind("snap_", 0) != 0) continue;
    const Fields f = read_fields(e.path());
    EXPECT_TRUE(std::all_of(f.x.begin(), f.x.end(), [](double x) { return std::isfinite(x); }))
        << e.path();
    ++snaps;
  }
  EXPECT_GE(snaps, 2);
  std::ifstream json(dir / "out" / "result.json");
  const std::string result((std::istreambuf_iterator<char>(json)), {});
  EXPECT_NE(result.find("\"status\": \"stopped\""), std::string::npos) << result;
}

TEST(FluidMpi, SplitSceneWithAParticleOutsideStopsEveryRankWithItsMessage) {
  // Decomposed from the start, each rank builds only its share of the scene (particle ids
  // round-robin over the ranks): a one-particle block outside the domain, the scene's last
  // particle (id 399 of 21 x 19 + 1), is a rank's other than 0. Every rank must stop with that
  // rank's message, said once, before any snapshot.
  const auto dir = scratch("fluid_mpi_split_outside");
  write_file(dir / "case.toml", R"([case]
dimension = 2
[domain]
min = [0.0, 0.0]
max = [0.11, 0.2]
[particles]
spacing = 0.005
[[fluid.blocks]]
min = [0.0, 0.0]
max = [0.105, 0.095]
[[fluid.blocks]]
min = [0.11, 0.0]
max = [0.115, 0.005]
[solver]
preconditioner = "amg"
[time]
end = 0.01
)");
  const Result r =
      mpirun_run(ranks(), (dir / "case.toml").string() + " --out " + (dir / "out").string());
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count(r.output, "particle 399 at (0.1125, 0.0025) starts outside the domain box"), 1);
  EXPECT_EQ(count_snapshots(dir / "out"), 0);
}

TEST(FluidMpi, ParticleLeavingOnOneRankStopsEveryRankWithItsMessage) {
  // A block of water "falls" freely upwards out of the top of an open domain. Decomposed, the
  // tall domain is cut across the block (rank 0 below), and the highest particles, which leave
  // first, are the last rank's alone: rank 0 must print that rank's message, every rank must
  // stop, and the snapshots stay valid.
  const auto dir = scratch("fluid_mpi_particle_left");
  write_file(dir / "case.toml", R"([case]
dimension = 2
[domain]
min = [0.0, 0.0]
max = [0.1, 0.4]
[particles]
spacing = 0.005
[fluid]
gravity = [0.0, 9.81]
[[fluid.blocks]]
min = [0.0, 0.25]
max = [0.1, 0.35]
[solver]
preconditioner = "amg"
[time]
end = 0.3
[output]
interval = 0.05
)");
  const Result r =
      mpirun_run(ranks(), (dir / "case.toml").string() + " --out " + (dir / "out").string());
  std::printf("%s", r.output.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "left the domain at (0.0"), 1);
  EXPECT_NE(r.output.find(", 0.40"), std::string::npos);  // through the top
  EXPECT_EQ(count(r.output, "complete and valid"), 1);
  EXPECT_GE(count_snapshots(dir / "out"), 2);  // t = 0 and 0.05 s, before the block leaves
  for (const auto& e : std::filesystem::directory_iterator(dir / "out")) {
    if (e.path().filename().string().rfind("snap_", 0) == 0) {
      EXPECT_EQ(read_fields(e.path()).id.size(), 400u) << e.path();
    }
  }
  const std::string result = read_file(dir / "out" / "result.json");
  EXPECT_NE(result.find("\"cause\": \"fluid_left_domain\""), std::string::npos) << result;
  EXPECT_NE(result.find("\"decomposed\": true"), std::string::npos) << result;
}

TEST(FluidMpi, DecomposeWithoutADistributedSolverStopsWithTheFix) {
  // The vortex's own jacobi preconditioner solves on each rank alone: it cannot take the ranks'
  // parts of a decomposed fluid.
  const auto dir = scratch("fluid_mpi_decompose_jacobi");
  const Result r =
      mpirun_run(ranks(), example("taylor_green_2d") + " --out " + (dir / "out").string() +
                              " --set time.end=0.01 --set parallel.decompose=true");
  std::printf("%s", r.output.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "solver.preconditioner = \"amg\""), 1);
  EXPECT_EQ(count_snapshots(dir / "out"), 0);
}

TEST(FluidMpi, RanksWithDifferentCasesStop) {
  // mpirun's "a : b" form gives each rank its own command line: here the vortex starts with
  // amplitude 1 on rank 0 and 1.001 on rank 1. The copies differ from the first snapshot on.
  const auto dir = scratch("fluid_mpi_different_cases");
  const std::string run = " " + isphdem() + " run " + example("taylor_green_2d") + " --out " +
                          (dir / "out").string() + " --set time.end=0.01 --set initial.amplitude=";
  const Result r = run_shell(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 mpirun "
      "--oversubscribe -np 1" +
      run + "1.0 : -np 1" + run + "1.001");
  std::printf("%s", r.output.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "the ranks' copies of the fluid differ at step 0"), 1);
  EXPECT_EQ(count_snapshots(dir / "out"), 0);
}

}  // namespace
}  // namespace isphdem::cli
