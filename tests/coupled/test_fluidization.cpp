// Fluidization of a quasi-2D bed of 1 mm grains (examples/fluidization_2d) through the coupled
// driver: below the Ergun minimum-fluidization velocity (0.94 cm/s at eps = 0.4) the bed holds,
// above it the bed expands. Bed height = 95th percentile of the grain centres' heights above
// the sieve (the diagnostics' bed_height minus the sieve height).
//   0.5 cm/s: |change| < 3%;   2 cm/s: change > 10%.
// The default-suite variant runs 0.3 s of each; FLUIDIZATION_END (slow label) the full 1 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "coupled_case.hpp"

#ifndef FLUIDIZATION_END
#define FLUIDIZATION_END 0.3
#endif

namespace isphdem::coupled_test {
namespace {

constexpr double kSieve = 0.006;  // in.liggghts: wall/gran yplane

double bed_height(const DemState& s) {
  std::vector<double> h;
  for (const auto& a : s.atoms)
    if (a.body == -1) h.push_back(a.x[1] - kSieve);
  std::sort(h.begin(), h.end());
  return h.at(static_cast<std::size_t>(0.95 * double(h.size() - 1)));
}

double relative_expansion(double velocity) {
  char v[32];
  std::snprintf(v, sizeof v, "%g", velocity);
  const CaseFile c = load_coupled_example(
      "fluidization_2d",
      {std::string("inflow.velocity=") + v, "time.end=" + std::to_string(FLUIDIZATION_END)});
  auto cc = make_coupled_case<2>(
      c, std::string(ISPHDEM_BINARY_DIR) + "/tests/fluidization_" + std::string(v));
  const double h0 = bed_height(cc.backend->state());
  double h_max = h0;
  cc.run->run_until(c.number("time.end"), [&](const isph::StepStats&) {
    if (cc.run->solver().steps() % 100 == 0)
      h_max = std::max(h_max, bed_height(cc.backend->state()));
  });
  const double h = bed_height(cc.backend->state());
  // The mean-flow drive holds the mean Darcy velocity at the inflow velocity.
  double mean_v = 0;
  const auto& P = cc.run->solver().particles();
  for (const auto& u : P.v) mean_v += u[1];
  mean_v /= static_cast<double>(P.size());
  std::printf("U = %s m/s: mean Darcy velocity %.5f m/s (error %.2f%%)\n", v, mean_v,
              100 * std::abs(mean_v / velocity - 1));
  EXPECT_NEAR(mean_v, velocity, 0.01 * velocity);
  const auto& t = cc.run->timings();
  std::printf(
      "U = %s m/s: bed height %.3f mm -> %.3f mm (%+.1f%%, largest %.3f mm) at t = %.2f s; "
      "wall time DEM %.1f s, coupling %.1f s, ISPH %.1f s\n",
      v, 1e3 * h0, 1e3 * h, 100 * (h / h0 - 1), 1e3 * h_max, cc.run->solver().time(), t.dem,
      t.coupling, t.fluid);
  return h / h0 - 1;
}

TEST(Fluidization, BedHoldsBelowAndExpandsAboveMinimumFluidization) {
  const double slow = relative_expansion(0.005);
  const double fast = relative_expansion(0.02);
  EXPECT_LT(std::abs(slow), 0.03);
  EXPECT_GT(fast, 0.10);
}

}  // namespace
}  // namespace isphdem::coupled_test
