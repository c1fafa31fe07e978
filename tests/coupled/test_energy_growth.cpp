// The energy-growth stop (run/energy_growth.hpp): growth at a steady rate faster than the
// stated e-folding time stops, growth just slower does not, and neither a start from rest, a
// stable oscillation nor a motion below the speed floor does.
#include <gtest/gtest.h>

#include <cmath>

#include "run/energy_growth.hpp"

namespace isphdem {
namespace {

// The step (counted from 0) at which the monitor stops a series q(k), or -1 within n steps.
template <class Q>
int stop_step(EnergyGrowthMonitor m, Q q, int n = 2000) {
  for (int k = 0; k < n; ++k)
    if (m.observe(q(k))) return k;
  return -1;
}

TEST(EnergyGrowth, SteadyGrowthFasterThanTheThresholdStopsAfterTwoWindowsAndOneMore) {
  // Energy x1.3 per step (e-folding 3.8 steps): window maxima 1.3^20 = 190 > 100 apart from the
  // first full history (k = 39) on, so the 20th growing step in a row is k = 58.
  const double W = kEnergyGrowthWindow;
  EXPECT_EQ(stop_step(EnergyGrowthMonitor(1e-3), [](int k) { return 1e-2 * std::pow(1.3, k); }),
            3 * W - 2);
}

TEST(EnergyGrowth, SteadyGrowthJustBelowTheThresholdNeverStops) {
  // 100^(1/20) = 1.2589 per step is the threshold; 1.25 stays below it however long it grows.
  EXPECT_EQ(stop_step(
                EnergyGrowthMonitor(1e-3), [](int k) { return 1e-2 * std::pow(1.25, k); }, 300),
            -1);
  EXPECT_EQ(stop_step(
                EnergyGrowthMonitor(1e-3), [](int k) { return 1e-2 * std::pow(1.27, k); }, 300),
            58);
}

TEST(EnergyGrowth, NothingBelowTheSpeedFloorCounts) {
  // Growing at 1.3 per step but stopped at a mean speed of 0.09 m/s, under a floor of 0.1.
  auto q = [](int k) { return std::min(1e-12 * std::pow(1.3, k), 0.0081); };
  EXPECT_EQ(stop_step(EnergyGrowthMonitor(0.1), q), -1);
  // The same growth carried on past the floor stops.
  EXPECT_GT(stop_step(EnergyGrowthMonitor(0.1), [](int k) { return 1e-12 * std::pow(1.3, k); }), 0);
}

TEST(EnergyGrowth, AStartFromRestIsNotGrowth) {
  // Grains at rest for 100 steps, then speeds rising as t, t^2 and t^3 (energy t^2, t^4, t^6)
  // far above the floor: the ratio against the earlier window is huge at first and falls.
  for (int p = 1; p <= 3; ++p) {
    auto q = [p](int k) { return k < 100 ? 0.0 : std::pow(double(k - 100), 2.0 * p); };
    EXPECT_EQ(stop_step(EnergyGrowthMonitor(1e-6), q), -1) << "speed ~ t^" << p;
  }
}

TEST(EnergyGrowth, AStableOscillationIsNotGrowth) {
  // A body ringing with a period of 7 steps: the energy passes through zero every half period.
  auto q = [](int k) {
    const double v = std::sin(2 * M_PI * k / 7.0);
    return v * v;
  };
  EXPECT_EQ(stop_step(EnergyGrowthMonitor(1e-3), q), -1);
  // The same oscillation with an amplitude growing 1.15x per step (energy 1.32x) stops.
  auto g = [&](int k) { return q(k) * std::pow(1.15, 2 * k) + 1e-300; };
  EXPECT_GT(stop_step(EnergyGrowthMonitor(1e-3), g), 0);
}

TEST(EnergyGrowth, MeanSquareSpeedWeighsBodiesAndFreeSpheresByVolume) {
  DemState s;
  DemBody b;
  b.volume = 3.0;
  b.v = {1.0, 0.0, 0.0};
  s.bodies.push_back(b);
  DemAtom member;  // a sphere of the body: counted through the body only
  member.body = 0;
  member.radius = 10.0;
  member.v = {100.0, 0.0, 0.0};
  s.atoms.push_back(member);
  DemAtom free;
  free.radius = std::cbrt(3.0 / (4.0 * M_PI));  // volume 1
  free.v = {0.0, 2.0, 2.0};                     // v^2 = 8
  s.atoms.push_back(free);
  EXPECT_NEAR(grain_mean_square_speed(s), (3.0 * 1.0 + 1.0 * 8.0) / 4.0, 1e-12);
  EXPECT_EQ(grain_mean_square_speed(DemState{}), 0.0);
}

}  // namespace
}  // namespace isphdem
