// The seed's internal-erosion case itself (examples/internal_erosion_2d/case.toml: free surface,
// 384 grains, the seed's layer), semi-resolved at v_in = 0.5 cm/s, run through `isphdem` as the
// README runs it, for 1 s at the seed's fluid step 1e-4 s and at 5e-4 s (the DEM step held at
// 1e-6 s). With alpha_s = 0.001 per step the run at the seed's own step broke at 0.69 s (a fluid
// particle in a pore at 17 m/s); with the case's density relaxation time both reach 1 s. Their
// pore jets read 25.90 and 24.80 v_in. One run is one realization of a granular layer: v_in
// changed by 2e-6 of itself gave 26.26 and 23.27, so the tolerance is 15%, not the 5% issue 46
// asks of the step (docs/internal_erosion.md, "Time step").
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "../cli/cli_support.hpp"
#include "erosion_step_run.hpp"

namespace isphdem {
namespace {

TEST(ErosionSeedCase, SemiResolvedRunsAtTheSeedsStepAndPoreJetsAgreeAtFiveTimesIt) {
  ASSERT_TRUE(std::filesystem::exists(cli::seed_packing_dir() / "packing.restart"))
      << "pack the layer first (ctest runs the erosion_packing fixture)";
  std::map<std::string, double> jet, end;
  for (const std::string dt : {"1e-4", "5e-4"}) {
    const auto run = erosion_test::run_semi_resolved_at_step(
        cli::seed_case(), "erosion_seed_case_dt_" + dt, dt, "1.0", " --set output.interval=0.5");
    ASSERT_EQ(run.result.exit_code, 0) << dt << ": " << run.result.output;
    ASSERT_GT(run.rows, 50);
    end[dt] = run.end_time;
    jet[dt] = run.pore_jet;
  }
  std::printf(
      "case.toml, semi-resolved, 0.5 cm/s: pore jets (v_in), mean over 0.1-1 s: dt 1e-4 s "
      "%.2f, 5e-4 s %.2f (%+.1f%%)\n",
      jet["1e-4"], jet["5e-4"], 100 * (jet["5e-4"] / jet["1e-4"] - 1));
  EXPECT_GT(end["1e-4"], 0.999);
  EXPECT_GT(end["5e-4"], 0.999);
  EXPECT_NEAR(jet["5e-4"], jet["1e-4"], 0.15 * jet["1e-4"]);
  EXPECT_GT(jet["1e-4"], 15.0);  // the seed's jets, far above the unresolved model's 5-8
}

}  // namespace
}  // namespace isphdem
