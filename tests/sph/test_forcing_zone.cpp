// The forcing zone's start-up ramp: (1 - cos(pi t / ramp)) / 2 of the velocity, full from
// t = ramp on, and the velocity at once without a ramp.
#include <gtest/gtest.h>

#include "isph_solver.hpp"

namespace isph {
namespace {

TEST(ForcingZone, RampEasesInToTheFullVelocity) {
  ForcingZone<2> z;
  z.velocity = Vec<2>(0.0, 0.02);
  z.ramp = 0.5;
  EXPECT_DOUBLE_EQ(z.velocity_at(0.0)[1], 0.0);
  EXPECT_NEAR(z.velocity_at(0.25)[1], 0.01, 1e-15);
  EXPECT_NEAR(z.velocity_at(0.125)[1], 0.02 * (1.0 - std::sqrt(0.5)) / 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(z.velocity_at(0.5)[1], 0.02);
  EXPECT_DOUBLE_EQ(z.velocity_at(3.0)[1], 0.02);
  double last = -1.0;
  for (int k = 0; k <= 100; ++k) {  // monotone: no overshoot to ring the tank
    const double v = z.velocity_at(0.006 * k)[1];
    EXPECT_GE(v, last);
    EXPECT_LE(v, 0.02);
    last = v;
  }
}

TEST(ForcingZone, NoRampMeansFullVelocityAtOnce) {
  ForcingZone<3> z;
  z.velocity = Vec<3>(0.0, 0.0, 0.005);
  EXPECT_DOUBLE_EQ(z.velocity_at(0.0)[2], 0.005);
  EXPECT_DOUBLE_EQ(z.velocity_at(1e-4)[2], 0.005);
}

}  // namespace
}  // namespace isph
