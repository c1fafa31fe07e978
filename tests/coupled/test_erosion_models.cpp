// The reduced erosion layer (examples/internal_erosion_2d/reduced.toml) at the seed's 0.5 cm/s,
// semi-resolved against resolved at the same spacing (dx = 0.5 mm, fines 2 spacings across), as
// a two-point study with the resolved point as its reference: the reduced form of
// examples/studies/erosion_models.toml (docs/study.md). Measured there over 0.3 s: with the fines
// resolved the pore jets lift them and the layer's surface rises 0.85 mm at this spacing (2.5 mm
// at 0.25 mm); with the fines unresolved (porosity and drag) it moves by 0.02 mm. Over the 0.15 s
// here: 0.73 mm against 0.03 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "../cli/cli_support.hpp"

namespace isphdem::cli {
namespace {

TEST(ErosionModels, OnlyResolvedFinesLiftTheLayerSurfaceAtTheSeedsInflow) {
  const auto dir = scratch("erosion_models");
  auto by_name = run_small_study(
      dir, "base = \"" + std::string(ISPHDEM_SOURCE_DIR) +
               "/examples/internal_erosion_2d/reduced.toml\"\n"
               "reference = \"model=resolved\"\n"
               "[set]\n\"dem.variables.packing_dir\" = \"" +
               reduced_packing_dir().string() +
               "\"\n\"time.end\" = 0.15\n\"output.interval\" = 0.15\n"
               "\"output.diagnostics_every\" = 10\n\"inflow.velocity\" = 0.005\n"
               "\"solver.preconditioner\" = \"amg\"\n\"particles.spacing\" = 0.0005\n"
               "\"time.dt\" = 5e-5\n\"dem.substeps\" = 50\n"
               "[grid]\n\"coupling.model\" = [\"semi-resolved\", \"resolved\"]\n");
  ASSERT_EQ(by_name.size(), 2u);
  const Row& semi = by_name.at("model=semi-resolved");
  const Row& resolved = by_name.at("model=resolved");
  ASSERT_EQ(semi.at("status"), "finished");
  ASSERT_EQ(resolved.at("status"), "finished");
  const double rise_semi = std::stod(semi.at("surface_rise"));
  const double rise_res = std::stod(resolved.at("surface_rise"));
  const double speed_semi = std::stod(semi.at("grain_speed"));
  const double speed_res = std::stod(resolved.at("grain_speed"));
  std::printf(
      "surface rise: semi-resolved %.3f mm, resolved %.3f mm; fastest grain %.4f against %.4f "
      "m/s; pore jet %s against %s v_in (%+.1f%%)\n",
      1e3 * rise_semi, 1e3 * rise_res, speed_semi, speed_res, semi.at("pore_jet").c_str(),
      resolved.at("pore_jet").c_str(), 100 * std::stod(semi.at("pore_jet_error")));
  // Resolved fines rise out of the surface pores by a good part of their diameter (1 mm)...
  EXPECT_GT(rise_res, 0.3e-3);
  // ... unresolved ones stay: the surface moves less than a tenth of a fine.
  EXPECT_LT(std::abs(rise_semi), 0.1e-3);
  EXPECT_GT(speed_res, 20 * speed_semi);
  // The study measured the semi-resolved point against the resolved one.
  EXPECT_NEAR(std::stod(semi.at("surface_rise_error")), rise_semi - rise_res, 1e-12);
  EXPECT_DOUBLE_EQ(std::stod(semi.at("grain_speed_expected")), speed_res);
}

}  // namespace
}  // namespace isphdem::cli
