// Dam break after Martin & Moyce (1952): a column a wide and 2a high collapses into a dry tank.
// The surge front Z = x/a (the largest x of fluid near the floor, plus half a spacing for the
// volume each particle carries) against T = t sqrt(2g/a). The run must reach T = 3, also at a
// small CFL number (0.05: until the toe fixes of docs/fluid.md it failed at t = 0.071 s, the
// quickest reproducer of the toe blow-ups).
//
// The front is asserted against an instant-release solution of the same tank, not against the
// experiment: Martin & Moyce's column was released by removing a barrier, which takes time, while
// the simulation starts from rest with the barrier gone. An independent grid solver shows how
// much that matters: OpenFOAM's interFoam (VOF, two phases, 40 and 80 cells per a, the same within
// 0.3%) leads the experiment by up to +19.7% at T = 1.19 and matches it within -3.1/+1.5% when
// delayed by dT = 0.285 (20 ms at a = 0.1 m), so no instant-release solver can come within 5% of
// the table. Both tables are printed.
//
// DAM_BREAK_RESOLUTION (particles across a) is 40 for the default build of this test (the issue's
// minimum; the case's solver.alpha_s = 0.05 relaxes the compression of the toe, which made it
// trail the reference by up to 9.1% with the default 0.001) and 80 for the slow variant. Measured
// worst differences from the reference for T <= 2.5: 4.7% at a/dx = 40 (T = 1.63) and 7.1% at
// a/dx = 80 (T = 2.20, where the toe breaks into fragments and the surge front jumps back; the
// furthest particle stays within 4.4% there): the slow variant is work_in_progress.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "case_path.hpp"
#include "run/fluid_run.hpp"

#ifndef DAM_BREAK_RESOLUTION
#define DAM_BREAK_RESOLUTION 40
#endif

namespace isphdem::validation {
namespace {

// Front positions Z = x/a at the times T of Martin & Moyce (1952), n^2 = 2 (column twice as high
// as wide): theirs, and the instant-release reference's at the same T (interFoam, 40 cells per a,
// front where alpha = 0.5 in the bottom cell row; scripts/dam_break_vof_reference.py, OpenFOAM
// v1912 from Debian's openfoam package, 3.5 min on one core; 80 cells per a give the same within
// 0.3%, the script's header).
struct FrontRow {
  double T, martin_moyce, instant_release;
};
const std::vector<FrontRow> kFrontTable = {
    {0.00, 1.00, 1.000}, {0.41, 1.11, 1.119}, {0.84, 1.23, 1.410}, {1.19, 1.44, 1.721},
    {1.43, 1.67, 1.966}, {1.63, 1.89, 2.194}, {1.82, 2.11, 2.422}, {1.97, 2.33, 2.610},
    {2.20, 2.56, 2.912}, {2.32, 2.78, 3.072}, {2.50, 3.00, 3.324}, {2.64, 3.22, 3.526},
    {2.82, 3.44, 3.795}, {2.96, 3.67, 4.006}};

// Front of the continuous surge: the largest x among fluid particles within 2 dx of the floor
// that have at least 6 fluid neighbours within 2 dx (a full lattice has 12), plus dx/2. Single
// spray particles thrown ahead of the toe are not the surge front the experiment filmed.
double front(const isph::IsphSolver<2>& s, double a, bool connected) {
  const auto& P = s.particles();
  const double dx = P.spacing;
  double xmax = -1e9;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != isph::kFluid || P.x[i][1] >= 2.0 * dx || P.x[i][0] <= xmax) continue;
    if (connected) {
      int close = 0;
      for (std::size_t j = 0; j < P.size(); ++j)
        close += j != i && P.kind[j] == isph::kFluid && (P.x[j] - P.x[i]).norm() <= 2.0 * dx;
      if (close < 6) continue;
    }
    xmax = P.x[i][0];
  }
  return (xmax + 0.5 * dx) / a;
}

struct DamBreakResult {
  std::vector<double> z, z_any;  // per table row reached
  double t_end_scaled = 0.0;     // T reached
  long steps = 0;
  std::string failure;
};

// One run per CFL number (0: the case's own), shared by the tests below.
DamBreakResult run_dam_break(double cfl) {
  const double a = 0.1, g = 9.81;
  const double dx = a / DAM_BREAK_RESOLUTION;
  std::vector<std::string> overrides = {"particles.spacing=" + std::to_string(dx)};
  if (cfl > 0.0) overrides.push_back("time.cfl=" + std::to_string(cfl));
  const CaseFile c = load_example("dam_break_2d", overrides);
  FluidRun<2> run(build_fluid_scene<2>(c), parse_run_settings(c));
  auto& s = run.solver();
  const double t_scale = std::sqrt(2.0 * g / a);  // T = t * t_scale
  DamBreakResult out;
  try {
    for (const auto& row : kFrontTable) {
      if (row.T > 0.0) run.run_until(row.T / t_scale);
      out.z.push_back(front(s, a, true));
      out.z_any.push_back(front(s, a, false));
    }
    run.run_until(3.0 / t_scale);
  } catch (const isph::SimulationError& e) {
    out.failure = e.what();
  }
  out.t_end_scaled = s.time() * t_scale;
  out.steps = s.steps();
  std::printf("  a/dx = %d, CFL %s, %ld steps, reached T = %.3f\n", DAM_BREAK_RESOLUTION,
              cfl > 0.0 ? std::to_string(cfl).c_str() : "of the case", out.steps, out.t_end_scaled);
  std::printf(
      "     T   Z (M&M)  Z (VOF)   Z (surge)  vs VOF   vs M&M    Z (any particle)  vs VOF\n");
  for (std::size_t k = 0; k < out.z.size(); ++k) {
    const double mm = kFrontTable[k].martin_moyce, vof = kFrontTable[k].instant_release;
    auto pct = [](double z, double ref) { return 100.0 * (z - ref) / ref; };
    std::printf(
        "  %5.2f   %5.2f    %6.3f    %6.3f  %+6.1f%%  %+6.1f%%    %6.3f           %+6.1f%%\n",
        kFrontTable[k].T, mm, vof, out.z[k], pct(out.z[k], vof), pct(out.z[k], mm), out.z_any[k],
        pct(out.z_any[k], vof));
  }
  if (!out.failure.empty()) std::printf("  stopped: %s\n", out.failure.c_str());
  return out;
}

const DamBreakResult& dam_break() {
  static const DamBreakResult r = run_dam_break(0.0);
  return r;
}

TEST(DamBreak, RunsStablyToT3AtSmallCfl) {
  const DamBreakResult r = run_dam_break(0.05);
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_GE(r.t_end_scaled, 3.0 - 1e-6);
}

TEST(DamBreak, RunsStablyToT3) {
  const auto& r = dam_break();
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_GE(r.t_end_scaled, 3.0 - 1e-6);
}

TEST(DamBreak, SurgeFrontMatchesInstantReleaseReference) {
  const auto& r = dam_break();
  ASSERT_EQ(r.z.size(), kFrontTable.size()) << "run stopped early: " << r.failure;
  double worst = 0.0, worst_T = 0.0, worst_mm = 0.0;
  for (std::size_t k = 1; k < r.z.size(); ++k) {
    const FrontRow& row = kFrontTable[k];
    if (row.T > 2.5) continue;
    const double e = std::abs(r.z[k] - row.instant_release) / row.instant_release;
    if (e > worst) worst = e, worst_T = row.T;
    worst_mm = std::max(worst_mm, std::abs(r.z[k] - row.martin_moyce) / row.martin_moyce);
  }
  std::printf(
      "  a/dx = %d, T <= 2.5: worst difference from the instant-release reference %.1f%% (at T = "
      "%.2f; allowed 5%%); from Martin & Moyce %.1f%% (not asserted: the experiment's release "
      "lags)\n",
      DAM_BREAK_RESOLUTION, 100.0 * worst, worst_T, 100.0 * worst_mm);
  EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace isphdem::validation
