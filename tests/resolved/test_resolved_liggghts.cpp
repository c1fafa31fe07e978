// The resolved stage on bodies from real LIGGGHTS multisphere clumps (tests/dem/inputs/
// in.planar_slab: 12 planar 3-sphere clumps settling in a quasi-2D slab 1 mm thick). Checks the
// conventions the in-test integrator of the other tests cannot: LIGGGHTS's volumes, quaternions
// and principal-axis order. After the clumps have fallen, landed and turned, every PMS particle
// placed from the body pose must still lie inside its clump's member spheres (whose positions
// LIGGGHTS computes itself), and the loads must go to the bodies LIGGGHTS knows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "dem_test_support.hpp"
#include "lattice.hpp"
#include "resolved/resolved_coupling.hpp"

namespace isphdem {
namespace {

TEST(ResolvedLiggghts, PmsParticlesFollowRealClumps) {
  auto dem = test::quiet_backend("resolved");
  dem.initialize({test::dem_input("in.planar_slab"), {}});
  dem.advance(1);  // grains inserted in the script's last step are put on the plane here
  const DemState s0 = dem.state();
  ASSERT_GT(s0.bodies.size(), 5u);

  // Water filling the slab's x-y box at dx = 0.1 mm (five particles per sphere radius).
  const double dx = 1e-4, T = 1e-3;
  isph::Domain<2> domain;
  domain.lo = isph::Vec<2>(0.0, -0.001);
  domain.hi = isph::Vec<2>(0.01, 0.021);
  isph::Particles<2> P;
  P.spacing = dx;
  P.volume = dx * dx;
  isph::fill_box<2>(P, domain.lo, domain.hi, dx, isph::kFluid);
  isph::IsphConfig<2> cfg;
  isph::IsphSolver<2> solver(cfg, domain, P);
  ResolvedSettings set;
  set.spacing = dx;
  set.fluid_density = 1000;
  set.slab_thickness = T;
  ResolvedCoupling<2> stage(set);
  stage.initialize(s0, solver);
  double worst_count = 0;
  for (std::size_t b = 0; b < s0.bodies.size(); ++b) {
    const auto& info = stage.bodies()[b];
    worst_count = std::max(worst_count,
                           std::abs(double(info.particles) - s0.bodies[b].volume / (T * dx * dx)));
  }
  std::printf("%zu clumps: PMS count vs V/(T dx^2): worst difference %.2f particles\n",
              s0.bodies.size(), worst_count);
  EXPECT_LE(worst_count, 0.5 + 1e-9);

  std::map<int64_t, isph::Vec<2>> x0;  // PMS particles by id, as generated
  for (std::size_t i = 0; i < solver.particles().size(); ++i)
    if (solver.particles().kind[i] == isph::kSolid)
      x0[solver.particles().id[i]] = solver.particles().x[i];
  std::map<int, Vec3> atom0;
  for (const auto& a : s0.atoms) atom0[a.tag] = a.x;

  dem.advance(15000);  // 15 ms: the clumps land on the floor and on each other, and turn
  const DemState& s1 = dem.state();
  stage.move_particles(s1, solver);
  std::map<int, std::vector<const DemAtom*>> members;
  for (const auto& a : s1.atoms)
    if (a.body >= 0) members[a.body].push_back(&a);
  std::map<int, int> index;
  for (std::size_t b = 0; b < stage.bodies().size(); ++b) index[b] = stage.bodies()[b].id;
  double worst_depth = 1e9, max_turn = 0;
  for (std::size_t b = 0; b < s1.bodies.size(); ++b) {
    const auto& q0 = s0.bodies[b].quat;
    const auto& q1 = s1.bodies[b].quat;
    const double dot = std::abs(q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3]);
    max_turn = std::max(max_turn, 2 * std::acos(std::min(1.0, dot)));
  }
  const auto& Q = solver.particles();
  for (std::size_t i = 0; i < Q.size(); ++i) {
    if (Q.kind[i] != isph::kSolid) continue;
    const int id = index[Q.body[i]];
    double depth = -1e9;
    for (const DemAtom* a : members[id])
      depth = std::max(depth, a->radius - std::hypot(Q.x[i][0] - a->x[0], Q.x[i][1] - a->x[1]));
    worst_depth = std::min(worst_depth, depth);
  }
  // The rigid motion of each clump as LIGGGHTS moved its member spheres (2D Kabsch fit about
  // the members' centroid) must carry the PMS particles to where the stage put them.
  std::map<int, std::pair<isph::Vec<2>, isph::Vec<2>>> centroid;  // body id -> (before, after)
  std::map<int, double> angle;
  for (auto& [id, ms] : members) {
    isph::Vec<2> c0 = isph::Vec<2>::Zero(), c1 = isph::Vec<2>::Zero();
    for (const DemAtom* a : ms) {
      c0 += isph::Vec<2>(atom0[a->tag][0], atom0[a->tag][1]) / double(ms.size());
      c1 += isph::Vec<2>(a->x[0], a->x[1]) / double(ms.size());
    }
    double sc = 0, sd = 0;
    for (const DemAtom* a : ms) {
      const isph::Vec<2> p = isph::Vec<2>(atom0[a->tag][0], atom0[a->tag][1]) - c0;
      const isph::Vec<2> q = isph::Vec<2>(a->x[0], a->x[1]) - c1;
      sc += p[0] * q[1] - p[1] * q[0];
      sd += p.dot(q);
    }
    centroid[id] = {c0, c1};
    angle[id] = std::atan2(sc, sd);
  }
  double worst_place = 0;
  for (std::size_t i = 0; i < Q.size(); ++i) {
    if (Q.kind[i] != isph::kSolid) continue;
    const int id = index[Q.body[i]];
    const auto& [c0, c1] = centroid[id];
    const isph::Vec<2> want =
        c1 + Eigen::Rotation2Dd(angle[id]).toRotationMatrix() * (x0[Q.id[i]] - c0);
    worst_place = std::max(worst_place, (Q.x[i] - want).norm());
  }
  std::printf(
      "after 15000 DEM steps: clumps turned by up to %.3f rad; PMS particles off the "
      "members' rigid motion by at most %.2e dx; deepest PMS particle outside its "
      "clump's spheres: %.3e dx (negative = outside)\n",
      max_turn, worst_place / dx, worst_depth / dx);
  EXPECT_LT(worst_place, 1e-3 * dx);
  EXPECT_GT(max_turn, 0.01) << "the clumps did not turn: the test checks nothing";
  // The section is eroded (T = 1 mm > 4r/3), so every particle is inside the spheres.
  EXPECT_GT(worst_depth, 0.0);

  DemLoads loads;
  stage.after_fluid_step(s1, solver, 1e-4, loads);
  ASSERT_EQ(loads.body_ids.size(), s1.bodies.size());
  dem.set_body_loads(loads.body_ids, loads.body_force, loads.body_torque);  // ids LIGGGHTS knows
  dem.advance(1);
  dem.finalize();
}

}  // namespace
}  // namespace isphdem
