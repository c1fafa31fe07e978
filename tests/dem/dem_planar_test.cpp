// Quasi-2D slab: `fix couple/isph planar z Z0` keeps spheres and clumps in the plane while they
// collide, settle under in-plane gravity and take loads with out-of-plane components.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dem_test_support.hpp"

namespace {

using isphdem::Vec3;
using isphdem::test::dem_input;
using isphdem::test::quiet_backend;

constexpr double kPlane = 0.0005;

TEST(DemPlanar, SpheresAndClumpsStayInPlane) {
  auto dem = quiet_backend("planar");
  dem.initialize({dem_input("in.planar_slab"), {}});
  dem.advance(1);  // grains inserted in the script's last step are put on the plane here
  const auto s0 = dem.state();
  ASSERT_GT(s0.bodies.size(), 5u);
  ASSERT_GT(s0.atoms.size(), s0.bodies.size() * 3);

  // Loads on every sphere and body, each with out-of-plane parts that must have no effect.
  std::vector<int> tags, ids;
  std::vector<Vec3> fa, ta, fb, tb;
  for (const auto& a : s0.atoms) {
    tags.push_back(a.tag);
    fa.push_back({1e-6 * (a.tag % 3 - 1), 5e-7, 2e-6});
    ta.push_back({1e-9, -1e-9, 1e-11 * (a.tag % 2 ? 1 : -1)});
  }
  for (const auto& b : s0.bodies) {
    ids.push_back(b.id);
    fb.push_back({2e-6, -1e-6, 3e-6});
    tb.push_back({1e-9, 1e-9, 1e-11});
  }
  dem.set_atom_loads(tags, fa, ta);
  dem.set_body_loads(ids, fb, tb);
  // Contacts (overlapping pairs of spheres of different bodies, spheres on the floor y = 0).
  auto contacts = [](const isphdem::DemState& st) {
    int n = 0;
    for (size_t i = 0; i < st.atoms.size(); i++) {
      const auto& a = st.atoms[i];
      n += a.x[1] < a.radius;
      for (size_t j = i + 1; j < st.atoms.size(); j++) {
        const auto& b = st.atoms[j];
        if (a.body >= 0 && a.body == b.body) continue;
        n += std::hypot(a.x[0] - b.x[0], a.x[1] - b.x[1], a.x[2] - b.x[2]) < a.radius + b.radius;
      }
    }
    return n;
  };
  long contact_samples = 0;
  for (int c = 0; c < 150; c++) {
    dem.advance(100);
    contact_samples += contacts(dem.state());
  }

  const auto& s = dem.state();
  // drift: change of the out-of-plane coordinate over the run, every sphere and body centre.
  // on_plane: distance from the plane of free spheres and body centres, which the fix puts on
  // it; clump members sit off it by the template's Monte Carlo centre-of-mass error (constant).
  double drift = 0, on_plane = 0, member_offset = 0, moved = 0, spin_out = 0, v_out = 0;
  double turned = 0;
  for (size_t k = 0; k < s.atoms.size(); k++) {
    const auto &a = s.atoms[k], &a0 = s0.atoms[k];
    drift = std::max(drift, std::fabs(a.x[2] - a0.x[2]));
    (a.body < 0 ? on_plane : member_offset) =
        std::max(a.body < 0 ? on_plane : member_offset, std::fabs(a.x[2] - kPlane));
    moved = std::max(moved, std::hypot(a.x[0] - a0.x[0], a.x[1] - a0.x[1]));
    v_out = std::max(v_out, std::fabs(a.v[2]));
    spin_out = std::max({spin_out, std::fabs(a.omega[0]), std::fabs(a.omega[1])});
  }
  for (size_t k = 0; k < s.bodies.size(); k++) {
    const auto &b = s.bodies[k], &b0 = s0.bodies[k];
    drift = std::max(drift, std::fabs(b.x[2] - b0.x[2]));
    on_plane = std::max(on_plane, std::fabs(b.x[2] - kPlane));
    v_out = std::max(v_out, std::fabs(b.v[2]));
    spin_out = std::max({spin_out, std::fabs(b.omega[0]), std::fabs(b.omega[1])});
    turned = std::max(turned, std::fabs(b.omega[2]));
  }
  std::printf(
      "planar slab: %zu atoms, %zu clumps, 15000 steps: max out-of-plane drift %.3e m, free "
      "spheres and clump centres off plane %.3e m, clump members off plane %.3e m (template "
      "centre-of-mass error), |v_z| %.3e m/s, in-plane |omega| %.3e rad/s; max in-plane "
      "displacement %.3e m, max clump |omega_z| %.3e rad/s\n",
      s.atoms.size(), s.bodies.size(), drift, on_plane, member_offset, v_out, spin_out, moved,
      turned);
  std::printf("planar slab: %ld contacts summed over the 150 chunk ends\n", contact_samples);
  EXPECT_GT(contact_samples, 10);  // contacts last ~16 steps: sampled, not counted
  EXPECT_LT(drift, 1e-12);
  EXPECT_LT(on_plane, 1e-12);
  EXPECT_LT(member_offset, 1e-5);
  EXPECT_LT(v_out, 1e-12);
  EXPECT_LT(spin_out, 1e-9);
  EXPECT_GT(moved, 1e-5);   // the grains did move in plane ...
  EXPECT_GT(turned, 1e-2);  // ... and the clumps did turn about the normal
}

}  // namespace
