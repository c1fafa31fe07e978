// A fixed bed of spheres in 3D (examples/fixed_bed_3d: a simple cubic array of touching spheres,
// periodic) under Stokes seepage, unresolved against resolved over d/dx: the reduced form of
// examples/studies/fixed_bed.toml (docs/study.md). The drive that holds the Darcy velocity is the
// bed's pressure gradient, compared with Ergun; the drag per sphere with Zick & Homsy's exact
// K = 42.1 for this array. Measured in the full study: unresolved +2.2% (Ergun) at d/dx = 1,
// -14% at 2 and -85% at 4 (the porosity field resolves the grains, and the flow bypasses them);
// resolved K -83%, -65%, -26% at d/dx = 2, 4, 8 (2026-12-07).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "../cli/cli_support.hpp"

namespace isphdem::cli {
namespace {

std::string point(const std::string& name, const std::string& model, double d, int cells,
                  double end) {
  std::string s = "[[points]]\nname = \"" + name + "\"\nset = { \"coupling.model\" = \"" + model +
                  "\", \"dem.variables.d\" = " + std::to_string(d) +
                  ", \"dem.variables.cells\" = " + std::to_string(cells) +
                  ", \"unresolved.grain_diameter\" = " + std::to_string(d) +
                  ", \"time.end\" = " + std::to_string(end) + " }\n";
  return s;
}

TEST(FixedBed, UnresolvedHoldsErgunUpToDOverDxOneAndResolvedConvergesWithDOverDx) {
  const auto dir = scratch("fixed_bed");
  auto by_name = run_small_study(
      dir, "base = \"" + std::string(ISPHDEM_SOURCE_DIR) + "/examples/fixed_bed_3d/case.toml\"\n" +
               "[set]\n\"output.interval\" = 0.3\n\"output.diagnostics_every\" = 10\n" +
               point("unresolved_d1dx", "unresolved", 0.001, 8, 0.3) +
               point("unresolved_d4dx", "unresolved", 0.004, 2, 0.6) +
               point("resolved_d2dx", "resolved", 0.002, 4, 0.3) +
               point("resolved_d4dx", "resolved", 0.004, 2, 0.6) +
               point("resolved_d8dx", "resolved", 0.008, 1, 1.2));
  ASSERT_EQ(by_name.size(), 5u);
  std::map<std::string, double> ergun, zh;
  for (const auto& [name, row] : by_name) {
    ASSERT_EQ(row.at("status"), "finished") << name << ": " << row.at("message");
    ergun[name] = std::stod(row.at("pressure_gradient_error"));
    zh[name] = std::stod(row.at("drag_factor_error"));
    std::printf("%-16s pressure gradient %+6.1f%% against Ergun, K %+6.1f%% against Zick & Homsy\n",
                name.c_str(), 100 * ergun[name], 100 * zh[name]);
  }
  // Unresolved drag is Ergun's: at d/dx = 1 the bed gives it back within 5%...
  EXPECT_LT(std::abs(ergun["unresolved_d1dx"]), 0.05);
  // ... and with grains four spacings across the porosity field has holes the flow runs through.
  EXPECT_LT(ergun["unresolved_d4dx"], -0.3);
  // Resolved, the error falls as the grains get more particles (first order: halves per doubling).
  EXPECT_LT(std::abs(zh["resolved_d4dx"]), std::abs(zh["resolved_d2dx"]));
  EXPECT_LT(std::abs(zh["resolved_d8dx"]), 0.75 * std::abs(zh["resolved_d4dx"]));
}

// The resolved bed at d/dx = 8 held at the flux its particles carry (inflow.flux = "particles"),
// with the density error relaxed at a rate (solver.density_relaxation_time) and the no-slip ghosts
// fitted as a parabola: K = -8.4% / -8.15% at dt = 1e-3 / 5e-4 s (issue 46). Holding the particles'
// mean velocity instead, with alpha_s per step and linear ghosts (the case's defaults), K read
// -25.6% / -21.7%: the shifts carry a backward flux that the velocities do not show
// (docs/resolved.md, "The resolved fixed bed across fluid steps").
TEST(FixedBed, ResolvedDragHoldsAcrossStepsWhenTheDriveHoldsTheParticlesFlux) {
  const auto dir = scratch("fixed_bed_steps");
  const std::string keys =
      "\"coupling.model\" = \"resolved\", \"dem.variables.d\" = 0.008, "
      "\"dem.variables.cells\" = 1, \"time.end\" = 1.2, \"inflow.flux\" = \"particles\", "
      "\"solver.density_relaxation_time\" = 0.25, \"solver.wall_ghosts\" = \"quadratic\"";
  auto by_name = run_small_study(
      dir, "base = \"" + std::string(ISPHDEM_SOURCE_DIR) + "/examples/fixed_bed_3d/case.toml\"\n" +
               "[set]\n\"output.interval\" = 0.3\n\"output.diagnostics_every\" = 10\n" +
               "[[points]]\nname = \"dt1e-3\"\nset = { " + keys + " }\n" +
               "[[points]]\nname = \"dt5e-4\"\nset = { " + keys +
               ", \"time.dt\" = 5e-4, \"dem.variables.dem_dt\" = 5e-5 }\n");
  ASSERT_EQ(by_name.size(), 2u);
  std::map<std::string, double> zh;
  for (const auto& [name, row] : by_name) {
    ASSERT_EQ(row.at("status"), "finished") << name << ": " << row.at("message");
    zh[name] = std::stod(row.at("drag_factor_error"));
    std::printf("resolved d/dx = 8, %s: K %+6.2f%% against Zick & Homsy\n", name.c_str(),
                100 * zh[name]);
  }
  EXPECT_LT(std::abs(zh["dt1e-3"] - zh["dt5e-4"]), 0.01);
  EXPECT_LT(std::abs(zh["dt1e-3"]), 0.12);
  EXPECT_LT(std::abs(zh["dt5e-4"]), 0.12);
}

}  // namespace
}  // namespace isphdem::cli
