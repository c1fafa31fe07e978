// A DEM-only case ([dem] table, no fluid) through run_dem_case: chunks of substeps until t_end.
#include "dem/dem_run_case.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace {

namespace fs = std::filesystem;

isphdem::DemCaseConfig example_config() {
  const fs::path dir = fs::path(ISPHDEM_SOURCE_DIR) / "examples" / "dem_only";
  const toml::table table = toml::parse_file((dir / "case.toml").string());
  auto config = isphdem::parse_dem_table(*table["dem"].as_table(), dir);
  config.variables = {{"nclumps", "10"}, {"nspheres", "100"}};  // smaller than the example
  return config;
}

TEST(DemRunCase, AdvancesInChunksUntilEndTime) {
  const auto config = example_config();
  ASSERT_EQ(config.substeps, 100);
  isphdem::DemRunOptions options;
  options.out_dir = fs::path(ISPHDEM_BINARY_DIR) / "tests" / "dem_run_case";
  fs::create_directories(options.out_dir);
  options.fluid_dt = 1e-4;
  long chunks = 0;
  std::size_t atoms = 0, bodies = 0;
  double last_time = 0;
  std::int64_t first_step = -1, last_step = 0;
  options.after_chunk = [&](isphdem::DemBackend& dem, long chunk) {
    EXPECT_EQ(chunk, ++chunks);
    const auto& s = dem.state();
    if (first_step < 0) first_step = s.step;
    last_step = s.step;
    last_time = s.time;
    atoms = s.atoms.size();
    bodies = s.bodies.size();
  };
  EXPECT_EQ(isphdem::run_dem_case(config, 2e-3, options), 0);
  std::printf("run_dem_case: %ld chunks, %zu atoms, %zu clumps, DEM time %.6g s\n", chunks, atoms,
              bodies, last_time);
  EXPECT_EQ(chunks, 20);
  EXPECT_EQ(last_step - first_step, 19 * 100);
  EXPECT_NEAR(last_time, 2e-3, 1e-15);
  EXPECT_EQ(bodies, 10u);
  EXPECT_EQ(atoms, 100u + 3 * 10u);
  EXPECT_TRUE(fs::exists(options.out_dir / "liggghts.screen"));
}

TEST(DemRunCase, RejectsAFluidStepThatIsNotSubstepsDemSteps) {
  isphdem::DemRunOptions options;
  // Its own directory: ctest runs tests side by side (scripts/test.sh).
  options.out_dir = fs::path(ISPHDEM_BINARY_DIR) / "tests" / "dem_run_case_reject";
  fs::create_directories(options.out_dir);
  options.fluid_dt = 2e-4;
  EXPECT_THROW(isphdem::run_dem_case(example_config(), 1e-3, options), std::runtime_error);
}

}  // namespace
