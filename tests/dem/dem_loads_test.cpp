// Loads handed to LIGGGHTS through fix couple/isph give the exact rigid-body response.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dem_test_support.hpp"

namespace {

using isphdem::DemBody;
using isphdem::Mat3;
using isphdem::Vec3;
using isphdem::test::dem_input;
using isphdem::test::quiet_backend;

constexpr double kDt = 1e-6;

Vec3 solve(const Mat3& a, const Vec3& b) {  // Cramer's rule, fine for a 3x3 SPD tensor
  auto det = [](const Mat3& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  Vec3 x{};
  for (int c = 0; c < 3; c++) {
    Mat3 m = a;
    for (int r = 0; r < 3; r++) m[r][c] = b[r];
    x[c] = det(m) / d;
  }
  return x;
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double rel(const Vec3& got, const Vec3& want) { return norm(sub(got, want)) / norm(want); }

// Free spheres: v(t) = impulse / m and omega(t) = angular impulse / I, with loads that change
// between chunks (each load must act on exactly the steps of its chunk).
TEST(DemLoads, FreeSphereVelocityIsImpulseOverMass) {
  auto dem = quiet_backend("free");
  dem.initialize({dem_input("in.free_spheres"), {}});
  const auto atoms = dem.state().atoms;
  ASSERT_EQ(atoms.size(), 128u);
  const double r = 0.0005, m = 2600.0 * 4.0 / 3.0 * M_PI * r * r * r, inertia = 0.4 * m * r * r;

  std::vector<int> tags;
  for (const auto& a : atoms) tags.push_back(a.tag);
  std::vector<Vec3> impulse(tags.size(), Vec3{}), ang_impulse(tags.size(), Vec3{});
  const int chunks = 10, n_sub = 100;
  for (int c = 0; c < chunks; c++) {
    std::vector<Vec3> f(tags.size()), t(tags.size());
    for (size_t k = 0; k < tags.size(); k++) {
      const double s = (c % 3 == 0) ? 1.0 : (c % 3 == 1 ? -0.5 : 2.0);
      f[k] = {s * 1e-5 * (1 + k % 3), -2e-5 + 1e-6 * c, 3e-6 * (k % 5 + 1)};
      t[k] = {1e-11 * s, -2e-11, 5e-12 * (k % 4 + 1)};
      for (int d = 0; d < 3; d++) {
        impulse[k][d] += f[k][d] * n_sub * kDt;
        ang_impulse[k][d] += t[k][d] * n_sub * kDt;
      }
    }
    dem.set_atom_loads(tags, f, t);
    dem.advance(n_sub);
  }
  double worst_v = 0, worst_w = 0;
  const auto& s = dem.state();
  EXPECT_EQ(s.step, chunks * n_sub + 0);
  EXPECT_NEAR(s.time, chunks * n_sub * kDt, 1e-15);
  for (size_t k = 0; k < tags.size(); k++) {
    ASSERT_EQ(s.atoms[k].tag, tags[k]);
    worst_v = std::max(worst_v, rel(s.atoms[k].v, scale(impulse[k], 1 / m)));
    worst_w = std::max(worst_w, rel(s.atoms[k].omega, scale(ang_impulse[k], 1 / inertia)));
  }
  std::printf("free spheres: max relative error v %.3e, omega %.3e\n", worst_v, worst_w);
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_w, 1e-9);
}

// One clump under body loads, then under a load on one member sphere: centre acceleration F/M,
// angular acceleration I^-1 tau from the clump's inertia tensor. Angular accelerations are kept
// small (alpha t^2 ~ 1e-8) so the gyroscopic term and the rotation of I stay below 1e-6.
class ClumpLoads : public ::testing::Test {
 protected:
  void SetUp() override {
    dem_.initialize({dem_input("in.one_clump"), {}});
    ASSERT_EQ(dem_.state().bodies.size(), 1u);
    b0_ = dem_.state().bodies[0];
    ASSERT_EQ(b0_.members.size(), 3u);
    std::printf("clump: mass %.6e kg, principal inertia %.6e %.6e %.6e kg m2\n", b0_.mass,
                b0_.inertia[0], b0_.inertia[1], b0_.inertia[2]);
  }
  void check(const Vec3& impulse, const Vec3& ang_impulse_about_cm) {
    const DemBody& b = dem_.state().bodies[0];
    const double ev = rel(sub(b.v, b0_.v), scale(impulse, 1 / b0_.mass));
    const double ew =
        rel(sub(b.omega, b0_.omega), solve(b0_.inertia_tensor(), ang_impulse_about_cm));
    std::printf("clump: relative error centre velocity %.3e, omega %.3e\n", ev, ew);
    EXPECT_LT(ev, 1e-6);
    EXPECT_LT(ew, 1e-6);
  }
  isphdem::LiggghtsBackend dem_ = quiet_backend("clump");
  DemBody b0_;
};

TEST_F(ClumpLoads, BodyForceAndTorque) {
  const Vec3 f1{2e-6, -1e-6, 5e-7}, t1{3e-14, 1e-14, -2e-14};
  const Vec3 f2{-1e-6, 3e-6, 1e-6}, t2{-1e-14, 2e-14, 4e-14};
  const int n = 500;
  dem_.set_body_loads({b0_.id}, {f1}, {t1});
  dem_.advance(n);
  dem_.set_body_loads({b0_.id}, {f2}, {t2});
  dem_.advance(n);
  const double t = n * kDt;
  check({(f1[0] + f2[0]) * t, (f1[1] + f2[1]) * t, (f1[2] + f2[2]) * t},
        {(t1[0] + t2[0]) * t, (t1[1] + t2[1]) * t, (t1[2] + t2[2]) * t});
}

TEST_F(ClumpLoads, MemberSphereLoadActsOnItsBody) {
  const int member = b0_.members[2];
  Vec3 xm{};
  for (const auto& a : dem_.state().atoms)
    if (a.tag == member) xm = a.x;
  const Vec3 f{1e-10, 2e-10, -1.5e-10}, tq{1e-17, 0.0, 0.0};
  const int n = 1000;
  dem_.set_atom_loads({member}, {f}, {tq});
  dem_.advance(n);
  const double t = n * kDt;
  const Vec3 torque = cross(sub(xm, b0_.x), f);
  check(scale(f, t), scale({torque[0] + tq[0], torque[1], torque[2]}, t));
}

TEST(DemLoads, UnknownTagsAreRejected) {
  auto dem = quiet_backend("unknown");
  dem.initialize({dem_input("in.free_spheres"), {}});
  EXPECT_THROW(dem.set_atom_loads({100000}, {Vec3{}}, {Vec3{}}), std::invalid_argument);
  EXPECT_THROW(dem.set_atom_loads({1, 1}, {Vec3{}, Vec3{}}, {Vec3{}, Vec3{}}),
               std::invalid_argument);
  EXPECT_THROW(dem.set_atom_loads({1}, {}, {}), std::invalid_argument);
  EXPECT_THROW(dem.set_body_loads({1}, {Vec3{}}, {Vec3{}}), std::invalid_argument);
}

}  // namespace
