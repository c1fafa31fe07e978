// Fluidization of a graded bed in 3D (examples/fluidization_3d): about 500 grains from 0.49 to
// 1.64 mm (lognormal, sigma_ln = 0.3, five classes) on a sieve, each dragged at its own size.
// The onset must be Ergun's at the bed's Sauter mean diameter d_32 = sum d^3 / sum d^2 and its
// porosity, U_mf, both measured on the settled bed before the water flows: porosity
// n = 1 - (grain volume) / (area x (h + mean radius)), h the 95th percentile of the grain
// centres' heights above the sieve.
//
// Velocities are set as multiples of that U_mf. Below the onset the bed holds (it ends no more
// than 0.5% above its settled height); above it, the bed expands to a new height, and the
// expansion grows with the velocity. The onset is where the expansion at two velocities above
// it, extrapolated linearly, falls to zero.
//   default suite (GRADED_FULL unset): 0.9 U_mf holds, 1.2 U_mf expands by more than 1%, 0.15 s
//   each: the onset lies within -10% / +20% of U_mf;
//   slow (GRADED_FULL): 0.95 U_mf holds, 1.10 and 1.20 U_mf expand, 0.4 s each; the onset
//   extrapolated from the two expansions lies within 5% of U_mf (issue 50).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "coupled_case.hpp"
#include "unresolved/drag_law.hpp"

namespace isphdem::coupled_test {
namespace {

constexpr double kSieve = 0.006;  // in.liggghts: wall/gran zplane
constexpr double kArea = 0.008 * 0.008;

double bed_height(const DemState& s) {
  std::vector<double> h;
  for (const auto& a : s.atoms) h.push_back(a.x[2] - kSieve);
  std::sort(h.begin(), h.end());
  return h.at(static_cast<std::size_t>(0.95 * double(h.size() - 1)));
}

struct Bed {
  double height = 0.0, porosity = 0.0, sauter = 0.0, smallest = 0.0, largest = 0.0;
};

Bed settled_bed(const DemState& s) {
  Bed b;
  b.height = bed_height(s);
  double volume = 0.0, d3 = 0.0, d2 = 0.0, r_sum = 0.0;
  b.smallest = 1.0;
  for (const auto& a : s.atoms) {
    const double d = 2.0 * a.radius;
    volume += M_PI / 6.0 * d * d * d;
    d3 += d * d * d;
    d2 += d * d;
    r_sum += a.radius;
    b.smallest = std::min(b.smallest, d);
    b.largest = std::max(b.largest, d);
  }
  b.sauter = d3 / d2;
  b.porosity = 1.0 - volume / (kArea * (b.height + r_sum / double(s.atoms.size())));
  return b;
}

// Ergun at the bed's Sauter mean diameter: rho (a* U + b* U^2) = (rho_s - rho)(1 - n) g.
double ergun_minimum_fluidization(const Bed& b) {
  const double rho = 1000.0, rho_s = 2600.0, g = 9.81;
  SeedResistanceParameters p;
  p.kinematic_viscosity = 1e-6;  // case.toml
  const SeedResistance law{p};
  const double a = law.a_star(b.porosity, b.sauter), c = law.b_star(b.porosity, b.sauter);
  const double rhs = (rho_s - rho) / rho * (1 - b.porosity) * g;
  return (-a + std::sqrt(a * a + 4 * c * rhs)) / (2 * c);
}

CoupledCase<3> make_case(double velocity, double end, const std::string& tag) {
  char v[32];
  std::snprintf(v, sizeof v, "%.6g", velocity);
  const CaseFile c = load_coupled_example(
      "fluidization_3d", {std::string("inflow.velocity=") + v, "time.end=" + std::to_string(end)});
  return make_coupled_case<3>(
      c, std::string(ISPHDEM_BINARY_DIR) + "/tests/fluidization_graded_" + tag);
}

// The bed height at the end of `end` seconds at `velocity`, relative to the settled bed's.
double expansion(double velocity, double end, const Bed& settled) {
  auto cc = make_case(velocity, end, std::to_string(velocity));
  const Bed start = settled_bed(cc.backend->state());
  // Same script, same seeds: the same settled bed for every velocity.
  EXPECT_NEAR(start.height, settled.height, 1e-12);
  cc.run->run_until(end, [](const isph::StepStats&) {});
  const double h = bed_height(cc.backend->state());
  const auto& t = cc.run->timings();
  std::printf(
      "U = %.4f cm/s: bed %.3f -> %.3f mm (%+.2f%%) at t = %.2f s; wall time DEM %.0f s, "
      "coupling %.0f s, ISPH %.0f s\n",
      100 * velocity, 1e3 * start.height, 1e3 * h, 100 * (h / start.height - 1),
      cc.run->solver().time(), t.dem, t.coupling, t.fluid);
  return h / start.height - 1;
}

TEST(FluidizationGraded, OnsetAtErgunOfTheSauterMeanDiameter) {
  Bed bed;
  {
    auto cc = make_case(0.005, 1e-3, "settled");  // not run: the bed as LIGGGHTS settled it
    bed = settled_bed(cc.backend->state());
  }
  const double u_mf = ergun_minimum_fluidization(bed);
  std::printf(
      "settled bed: %.3f mm, porosity %.4f, grains %.3f-%.3f mm, Sauter mean %.4f mm; Ergun "
      "U_mf %.4f cm/s (Re %.1f)\n",
      1e3 * bed.height, bed.porosity, 1e3 * bed.smallest, 1e3 * bed.largest, 1e3 * bed.sauter,
      100 * u_mf, u_mf * bed.sauter / 1e-6);
  ASSERT_GT(bed.largest / bed.smallest, 3.0) << "the bed must be graded";
#ifdef GRADED_FULL
  const double end = 0.4, below = 0.95, above[2] = {1.10, 1.20};
#else
  const double end = 0.15, below = 0.9, above[2] = {1.20, 0.0};
#endif
  EXPECT_LT(expansion(below * u_mf, end, bed), 0.005);
  const double e1 = expansion(above[0] * u_mf, end, bed);
#ifdef GRADED_FULL
  const double e2 = expansion(above[1] * u_mf, end, bed);
  EXPECT_GT(e1, 0.005);
  ASSERT_GT(e2, e1) << "the expansion must grow with the velocity";
  const double onset = above[0] + (above[1] - above[0]) * (0.0 - e1) / (e2 - e1);
  std::printf("onset, the expansions extrapolated to none: %.4f cm/s, %+.1f%% against Ergun\n",
              100 * onset * u_mf, 100 * (onset - 1));
  EXPECT_NEAR(onset, 1.0, 0.05);
#else
  EXPECT_GT(e1, 0.01);
  std::printf("onset between %.2f and %.2f U_mf\n", below, above[0]);
#endif
}

}  // namespace
}  // namespace isphdem::coupled_test
