// MockDemBackend: free spheres integrate piecewise-constant loads exactly.
#include "dem/dem_mock_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using isphdem::DemAtom;
using isphdem::MockDemBackend;
using isphdem::Vec3;

TEST(MockDemBackend, ConstantLoadGivesUniformAcceleration) {
  DemAtom a;
  a.tag = 7;
  a.radius = 0.0005;
  MockDemBackend dem({a}, 1e-6, 2600.0, {0.0, -9.81, 0.0});
  dem.initialize({});
  const Vec3 f{1e-5, 2e-5, -3e-5}, t{1e-9, 0.0, 0.0};
  dem.set_atom_loads({7}, {f}, {t});
  for (int i = 0; i < 10; i++) dem.advance(100);
  const double m = dem.mass(7), time = 1000 * 1e-6;
  const auto& s = dem.state();
  EXPECT_NEAR(s.time, time, 1e-18);
  EXPECT_EQ(s.step, 1000);
  const Vec3 g{0.0, -9.81, 0.0};
  for (int c = 0; c < 3; c++) {
    const double acc = f[c] / m + g[c];
    EXPECT_NEAR(s.atoms[0].v[c], acc * time, 1e-12 * std::fabs(acc * time));
    EXPECT_NEAR(s.atoms[0].x[c], 0.5 * acc * time * time,
                1e-9 * std::fabs(0.5 * acc * time * time));
  }
  EXPECT_NEAR(s.atoms[0].omega[0], t[0] / dem.moment_of_inertia(7) * time, 1e-9);
}

TEST(MockDemBackend, RejectsUnknownTagsAndBodies) {
  DemAtom a;
  a.tag = 1;
  a.radius = 0.0005;
  MockDemBackend dem({a}, 1e-6);
  EXPECT_THROW(dem.set_atom_loads({2}, {Vec3{}}, {Vec3{}}), std::invalid_argument);
  EXPECT_THROW(dem.set_atom_loads({1}, {}, {Vec3{}}), std::invalid_argument);
  EXPECT_THROW(dem.set_body_loads({1}, {Vec3{}}, {Vec3{}}), std::invalid_argument);
  EXPECT_THROW(dem.advance(0), std::invalid_argument);
}

}  // namespace
