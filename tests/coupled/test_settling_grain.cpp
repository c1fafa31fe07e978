// One 1 mm grain (2600 kg/m3) settling in water through the coupled driver (LIGGGHTS + ISPH +
// UnresolvedCoupling): terminal velocity within 5% of 0.152 m/s (Schiller-Naumann) at a fluid
// spacing dx = 2 d (examples/settling_grain). The error at dx = d is printed, not asserted: there
// the grain is as wide as a fluid particle, outside the unresolved model's range (dx >= 3 d in
// the seed's references [1, 2]), and the porosity near it drops to about 0.87, where the seed's
// Wen-Yu branch (eps^-2.7, Re with eps^2) no longer reduces to Schiller-Naumann.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "coupled_case.hpp"
#include "study/reference_formulas.hpp"
#include "unresolved/drag_law.hpp"

namespace isphdem::coupled_test {
namespace {

constexpr double kD = 1e-3, kRhoS = 2600, kRho = 1000, kNu = 1e-6, kG = 9.81;

// The analytic reference [reference] metrics use (study/reference_formulas.hpp), written
// independently of the drag law under test.
double schiller_naumann_terminal_velocity() {
  return schiller_naumann_velocity(kD, kRhoS, kRho, kNu, kG);
}

// What the seed's law itself gives for a grain falling at v through still water of porosity
// eps: its share of the reaction is eps rho K v V_k / (1 - eps) (the grain's volume spread over
// the fluid as 1 - eps), balanced against the buoyant weight.
double law_terminal_velocity(double eps) {
  SeedResistanceParameters p;
  p.blend = true;
  const SeedResistance law(p);
  double lo = 1e-4, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double v = 0.5 * (lo + hi);
    const double force = eps * kRho * law.coefficients(eps, v).total(v) * v / (1 - eps);
    (force > (kRhoS - kRho) * kG ? hi : lo) = v;
  }
  return 0.5 * (lo + hi);
}

struct Fall {
  std::vector<double> t, v;  // the grain's downward speed after each fluid step
  double y_end = 0;
};

Fall fall(double dx, const std::string& tag, double t_end, const std::string& exchange) {
  const CaseFile c = load_coupled_example(
      "settling_grain", {"particles.spacing=" + std::to_string(dx),
                         "time.end=" + std::to_string(t_end), "dem.exchange=\"" + exchange + "\""});
  auto cc = make_coupled_case<2>(c, std::string(ISPHDEM_BINARY_DIR) + "/tests/settling_" + tag);
  auto& run = *cc.run;
  Fall f;
  run.run_until(t_end, [&](const isph::StepStats&) {
    const auto& a = cc.backend->state().atoms.at(0);
    f.y_end = a.x[1];
    f.t.push_back(run.solver().time());
    f.v.push_back(-a.v[1]);
  });
  return f;
}

double terminal_velocity(double dx, const std::string& tag, double t_end,
                         const std::string& exchange = "sequential") {
  const Fall f = fall(dx, tag, t_end, exchange);
  // Average over the last third of the run, where the grain has long reached steady fall.
  double sum = 0, n = 0;
  for (std::size_t k = 0; k < f.t.size(); ++k)
    if (f.t[k] > 2.0 / 3.0 * t_end) sum += f.v[k], n += 1;
  const double v = sum / n;
  std::printf(
      "dx = %.1f d, %s exchange: terminal velocity %.4f m/s (grain at y = %.1f mm at t = "
      "%.2f s)\n",
      dx / kD, exchange.c_str(), v, 1e3 * f.y_end, f.t.back());
  EXPECT_GT(f.y_end, 0.01) << "the grain reached the floor: the measured velocity is not terminal";
  return v;
}

TEST(SettlingGrain, TerminalVelocityWithinFivePercentAtTwoDiameters) {
  const double v_sn = schiller_naumann_terminal_velocity();
  std::printf("Schiller-Naumann terminal velocity (Re = d v / nu): %.4f m/s (table 0.152)\n", v_sn);
  EXPECT_NEAR(v_sn, 0.152, 0.002);
  // The law tends to Schiller-Naumann as eps -> 1; at the porosities the grain makes around
  // itself (about 0.975 at dx = 2d, 0.87 at dx = d) it is slower.
  for (double eps : {1 - 1e-9, 0.975, 0.87})
    std::printf("seed law (blend) terminal velocity at eps = %.3f: %.4f m/s\n", eps,
                law_terminal_velocity(eps));
  EXPECT_NEAR(law_terminal_velocity(1 - 1e-9), v_sn, 1e-3 * v_sn);
  const double v = terminal_velocity(2 * kD, "dx2d", 0.3);
  const double err = std::abs(v / 0.152 - 1);
  std::printf("dx = 2 d: error against 0.152 m/s: %.1f%%\n", 100 * err);
  EXPECT_LT(err, 0.05);
  // At dx = d the fluid near the grain went unstable after about 0.15-0.2 s (open issue,
  // docs/unresolved.md); the grain's velocity has levelled off by 0.08 s, so 0.12 s suffice.
  const double v1 = terminal_velocity(1 * kD, "dx1d", 0.12);
  std::printf("dx = d (not asserted): error against 0.152 m/s: %.1f%%\n",
              100 * std::abs(v1 / 0.152 - 1));
}

// The DEM beside the fluid (dem.exchange = "staggered") takes each fluid step's drag one fluid
// step late: with a step of 1e-4 s against the grain's response time of about 0.02 s the fall
// must follow the sequential one within half a percent of the terminal velocity all the way,
// while it accelerates too, and end at the same speed (measured: 0.15% at t = 0.026 s, a lag
// of k steps gives about k times that). A drag not handed on or handed on twice would part them
// by far more.
TEST(SettlingGrain, StaggeredExchangeFallsAsTheSequentialOne) {
  const Fall seq = fall(2 * kD, "seq", 0.15, "sequential");
  const Fall stag = fall(2 * kD, "staggered", 0.15, "staggered");
  ASSERT_EQ(seq.t.size(), stag.t.size());
  double worst = 0, t_worst = 0;
  for (std::size_t k = 0; k < seq.t.size(); ++k) {
    ASSERT_NEAR(seq.t[k], stag.t[k], 1e-12);
    const double d = std::abs(stag.v[k] - seq.v[k]);
    if (d > worst) worst = d, t_worst = seq.t[k];
  }
  const double v_end = seq.v.back();
  std::printf(
      "sequential and staggered falls, dx = 2 d, 0.15 s: speeds %.4f / %.4f m/s at the "
      "end; largest difference %.2e m/s (%.2f%% of the end speed) at t = %.4f s\n",
      v_end, stag.v.back(), worst, 100 * worst / v_end, t_worst);
  EXPECT_GT(v_end, 0.9 * 0.152);  // it has fallen to terminal speed
  EXPECT_LT(worst, 0.005 * v_end);
  EXPECT_NEAR(stag.v.back(), v_end, 0.005 * v_end);
}

}  // namespace
}  // namespace isphdem::coupled_test
