// Coupled runs under mpirun: LIGGGHTS on its own decomposition over the ranks, the fluid held by
// every rank, its rows shared between them, one PPE over them. A grain's trajectory and loads must
// be those of the one-rank run to solver tolerance, and a script that leaves the ranks without
// grains must stop the run, not let the fluid run alone.
#include <gtest/gtest.h>

#include "mpi_support.hpp"

namespace isphdem::cli {
namespace {

TEST(CoupledMpi, SettlingGrainFollowsTheOneRankTrajectory) {
  // Unresolved: one fine grain settling at its terminal speed (0.15 m/s) after 0.1 s; the fluid
  // decomposed over the ranks, the drag on the grain summed over them.
  const auto [a_file, b_file] =
      run_on_one_and_many("coupled_mpi_settling_grain", "settling_grain", "--set time.end=0.1");
  ASSERT_EQ(a_file.filename(), b_file.filename());
  const Fields a = read_fields(a_file, "dem"), b = read_fields(b_file, "dem");
  ASSERT_EQ(a.x.size(), b.x.size());
  ASSERT_FALSE(a.x.empty());
  const double dx = max_difference(a.x, b.x), dv = max_difference(a.v, b.v);
  std::printf("settling grain, 1 vs %d ranks: |dx| = %.2e m, |dv| = %.2e of %.4f m/s\n", ranks(),
              dx, dv, max_abs(a.v));
  // Measured at 2 ranks over 0.3 s: 5e-11 m and 3e-11 m/s.
  EXPECT_LE(dx, 1e-8);
  EXPECT_LE(dv, 1e-6 * max_abs(a.v));
}

TEST(CoupledMpi, ErosionLayerMatchesOneRank) {
  // The reduced erosion layer (unresolved, 32 fines and 6 clumps as spheres' porosity), 200
  // steps: the fluid decomposed, the drag of each grain summed over the ranks that hold fluid
  // around it. Positions in dx (1 mm) and grain radii, velocities in v_in (5 mm/s).
  const std::string dir = std::string(ISPHDEM_SOURCE_DIR) + "/examples/internal_erosion_2d";
  ASSERT_TRUE(std::filesystem::exists(dir + "/packing_reduced.restart"))
      << "pack the layer first (ctest runs the erosion_reduced_packing fixture)";
  const auto out = scratch("coupled_mpi_erosion_layer");
  for (const int np : {1, ranks()}) {
    const Result r = mpirun_run(
        np, dir + "/reduced.toml --out " + (out / std::to_string(np)).string() +
                " --quiet --set solver.preconditioner=amg --set solver.pressure_tolerance=1e-10"
                " --set time.end=0.02 --set output.interval=0.02");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const std::string result = read_file(out / std::to_string(ranks()) / "result.json");
  EXPECT_NE(result.find("\"decomposed\": true"), std::string::npos) << result;
  const auto a_file = last_snapshot(out / "1"),
             b_file = last_snapshot(out / std::to_string(ranks()));
  ASSERT_EQ(a_file.filename(), b_file.filename());
  const Fields ga = read_fields(a_file, "dem"), gb = read_fields(b_file, "dem");
  const Fields fa = read_fields(a_file), fb = read_fields(b_file);
  ASSERT_EQ(ga.id, gb.id);
  ASSERT_EQ(fa.id, fb.id);
  const double grain_dx = max_difference(ga.x, gb.x) / 1e-3,
               grain_dv = max_difference(ga.v, gb.v) / 5e-3;
  const double fluid_dx = max_difference(fa.x, fb.x) / 1e-3,
               fluid_dv = max_difference(fa.v, fb.v) / 5e-3;
  const double dp = max_difference(fa.p, fb.p) / max_abs(fa.p);
  std::printf(
      "erosion layer, 1 vs %d ranks at %s: grains |dx| = %.2e dx, |dv| = %.2e v_in; "
      "fluid |dx| = %.2e dx, |dv| = %.2e v_in, |dp| = %.2e max|p|\n",
      ranks(), a_file.filename().c_str(), grain_dx, grain_dv, fluid_dx, fluid_dv, dp);
  EXPECT_LE(grain_dx, 1e-6);
  EXPECT_LE(grain_dv, 1e-6);
  EXPECT_LE(fluid_dx, 1e-6);
  EXPECT_LE(fluid_dv, 1e-6);
  EXPECT_LE(dp, 1e-6);
}

TEST(CoupledMpi, BuoyancyClumpTakesTheOneRankLoad) {
  // Resolved: the held clump's hydrodynamic force is its buoyancy, 9.759e-5 N.
  const auto [a_file, b_file] =
      run_on_one_and_many("coupled_mpi_buoyancy_clump", "buoyancy_clump", "--set time.end=0.05",
                          true);  // PMS bodies: the rows stay shared
  ASSERT_EQ(a_file.filename(), b_file.filename());
  h5_read::File a(a_file.string()), b(b_file.string());
  const auto fa = a.read("bodies/force_hydro").f64, fb = b.read("bodies/force_hydro").f64;
  ASSERT_EQ(fa.size(), 3u);
  ASSERT_EQ(fb.size(), 3u);
  std::printf("buoyancy clump, 1 vs %d ranks: F_y %.9e against %.9e N\n", ranks(), fb[1], fa[1]);
  // Measured at 2 ranks after 0.2 s: 2.8e-8 relative (the PMS pressures to solver tolerance).
  EXPECT_NEAR(fb[1], fa[1], 1e-6 * std::abs(fa[1]));
  EXPECT_NEAR(fb[1], 9.759e-5, 1e-3 * 9.759e-5);
  const Fields pa = read_fields(a_file, "bodies"), pb = read_fields(b_file, "bodies");
  EXPECT_LE(max_difference(pa.x, pb.x), 1e-10);
}

TEST(CoupledMpi, ScriptWithoutGrainsOnTheRanksStopsTheRun) {
  // The settling clump's insertion region (2 mm, around the box centre) is cut by the processor
  // boundary on 2 ranks, and LIGGGHTS only warns that it inserted nothing.
  const auto dir = scratch("coupled_mpi_no_grains");
  const Result r = mpirun_run(2, example("settling_clump_2d") + " --out " + (dir / "out").string() +
                                     " --set time.end=0.01");
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count(r.output, "created no grains"), 1);
  EXPECT_NE(r.output.find("`processors` command"), std::string::npos);
  EXPECT_EQ(count_snapshots(dir / "out"), 0);
}

TEST(CoupledMpi, GrainLeavingOnRankOneStopsEveryRankWithItsMessage) {
  // The settling grain in a box cut off 3 mm above it, split in y over the 2 ranks
  // (`processors 1 2 1`: rank 1 holds the upper half, the grain's), rising at 0.3 m/s: it leaves
  // the box after about 10 ms and LIGGGHTS drops it silently on rank 1.
  const auto dir =
      edited_example("coupled_mpi_grain_lost", "settling_grain",
                     {{"region          box", "processors      1 2 1\nregion          box"},
                      {"box block 0 0.02 -0.01 0.11", "box block 0 0.02 -0.01 0.083"},
                      {"run             0", "velocity all set 0.0 0.3 0.0\nrun 0"}});
  const Result r = mpirun_run(2, (dir / "case.toml").string() + " --out " + (dir / "out").string() +
                                     " --set time.end=0.05 --set output.interval=0.005");
  std::printf("%s", r.output.c_str());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "grain 1 left the DEM simulation between t = "), 1);
  EXPECT_NE(r.output.find("last seen at"), std::string::npos);
  // The snapshots written before stay readable, with the grain in the first.
  EXPECT_GE(count_snapshots(dir / "out"), 2);
  const Fields first = read_fields(dir / "out" / "snap_00000000.h5", "dem");
  EXPECT_EQ(first.x.size(), 3u);
}

}  // namespace
}  // namespace isphdem::cli
