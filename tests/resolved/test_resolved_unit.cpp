// PMS particles and the resolved stage: generation (count from the DEM volume, on the fluid
// lattice, centroid on the centre of mass), placement at a pose, the load handover (exact), and
// bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "resolved_support.hpp"

namespace isphdem::resolved_test {
namespace {

// Distance of x from the lattice through `origin` with spacing dx (largest per-axis offset).
template <int Dim>
double off_lattice(const isph::Vec<Dim>& x, const isph::Vec<Dim>& origin, double dx) {
  double m = 0;
  for (int a = 0; a < Dim; ++a) {
    const double q = (x[a] - origin[a]) / dx;
    m = std::max(m, std::abs(q - std::round(q)));
  }
  return m;
}

TEST(PmsGeneration, LatticeCountMatchesDemVolumeIn2DAnd3D) {
  const DemState s = clump({Vec3{0.0131, 0.0207, 0}, Vec3{0.0331, 0.0207, 0}}, 0.011, 2600);
  const DemBody& b = s.bodies[0];
  const double dx = 0.002, T = 0.012;
  PmsGenerationSettings g{dx, T, PmsShape::Auto};
  const isph::Vec<2> o2(0.001, 0.001);
  const auto x2 = generate_pms_particles<2>(b, s.atoms, g, o2);
  const double n2 = b.volume / (dx * dx * T);
  isph::Vec<2> c2 = isph::Vec<2>::Zero();
  double worst = 0;
  for (const auto& x : x2) {
    c2 += x / x2.size();
    worst = std::max(worst, off_lattice<2>(x, o2, dx));
  }
  std::printf(
      "2D: %zu particles for V/(T dx^2) = %.2f; centroid off the centre of mass by %.2e dx\n",
      x2.size(), n2, (c2 - isph::Vec<2>(b.x[0], b.x[1])).norm() / dx);
  EXPECT_LE(std::abs(double(x2.size()) - n2), 0.5);
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT((c2 - isph::Vec<2>(b.x[0], b.x[1])).norm(), 0.02 * dx);
  std::set<std::pair<long, long>> nodes;
  for (const auto& x : x2) nodes.insert({std::lround(x[0] / dx * 2), std::lround(x[1] / dx * 2)});
  EXPECT_EQ(nodes.size(), x2.size()) << "two particles on one node";

  const isph::Vec<3> o3(0.0005, 0.0005, 0.0005);
  const auto x3 = generate_pms_particles<3>(b, s.atoms, g, o3);
  const double n3 = b.volume / (dx * dx * dx);
  isph::Vec<3> c3 = isph::Vec<3>::Zero();
  for (const auto& x : x3) c3 += x / x3.size();
  std::printf("3D: %zu particles for V/dx^3 = %.2f; centroid off by %.2e dx\n", x3.size(), n3,
              (c3 - isph::Vec<3>(b.x[0], b.x[1], b.x[2])).norm() / dx);
  EXPECT_LE(std::abs(double(x3.size()) - n3), 0.5);
  EXPECT_LT((c3 - isph::Vec<3>(b.x[0], b.x[1], b.x[2])).norm(), 0.02 * dx);
}

TEST(PmsGeneration, DxWideSpheresGiveOneParticleEach) {
  std::vector<Vec3> c;
  for (int i = 0; i < 5; ++i) c.push_back(Vec3{0.01 + 0.001 * i, 0.02, 0});
  const DemState s = clump(c, 0.0005, 2600);
  PmsGenerationSettings g{0.001, 0.001, PmsShape::Auto};
  const auto x = generate_pms_particles<2>(s.bodies[0], s.atoms, g, isph::Vec<2>(0.0005, 0.0005));
  ASSERT_EQ(x.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(x[i][0], c[i][0]);
}

TEST(PmsGeneration, BadInputNamesCauseAndFix) {
  DemState s = clump({Vec3{0.01, 0.01, 0}}, 0.003, 2600);
  PmsGenerationSettings g{0.001, 0.0, PmsShape::Lattice};
  try {
    generate_pms_particles<2>(s.bodies[0], s.atoms, g, isph::Vec<2>::Zero());
    FAIL() << "no error for a zero slab thickness";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("slab_thickness"), std::string::npos) << e.what();
  }
  g.slab_thickness = 0.001;
  g.spacing = 0.05;
  try {
    generate_pms_particles<2>(s.bodies[0], s.atoms, g, isph::Vec<2>::Zero());
    FAIL() << "no error for a body smaller than one particle";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("refine particles.spacing"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(pms_shape_from_name("cubes"), std::invalid_argument);
}

TEST(RigidSolids, PlacementFollowsPoseAndRigidVelocity) {
  isph::Particles<2> P;
  P.spacing = 0.01;
  P.volume = 1e-4;
  P.add(isph::Vec<2>(0.5, 0.5), isph::Vec<2>::Zero(), isph::kFluid);
  isph::RigidPose<2> pose;
  pose.x = isph::Vec<2>(0.2, 0.3);
  isph::add_rigid_body<2>(P, 0, {isph::Vec<2>(0.25, 0.3), isph::Vec<2>(0.2, 0.32)}, pose);
  isph::Domain<2> d;
  pose.x = isph::Vec<2>(0.4, 0.4);
  pose.rotation = Eigen::Rotation2Dd(M_PI / 2).toRotationMatrix();
  pose.v = isph::Vec<2>(1.0, 0.0);
  pose.omega[0] = 2.0;
  isph::place_rigid_solids<2>(P, d, {pose});
  // (0.05, 0) turned by 90 degrees is (0, 0.05): v = (1, 0) + 2 z x (0, 0.05) = (0.9, 0).
  EXPECT_NEAR((P.x[1] - isph::Vec<2>(0.4, 0.45)).norm(), 0, 1e-15);
  EXPECT_NEAR((P.v[1] - isph::Vec<2>(0.9, 0.0)).norm(), 0, 1e-15);
  EXPECT_NEAR((P.x[2] - isph::Vec<2>(0.38, 0.4)).norm(), 0, 1e-15);
  EXPECT_EQ(P.x[0], isph::Vec<2>(0.5, 0.5));  // fluid untouched
}

// One step of a moving, turning clump in the tank: the loads the stage hands over are the
// particles' forces times T x V/(N dx^2 T) and their moments, to round-off -- what the fluid
// gives the bodies receive -- and nothing goes to fluid particles.
TEST(ResolvedStage, LoadHandoverIsExact) {
  auto scene = tank<2>({});
  isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
  const double dx = solver.particles().spacing, T = 0.03;
  DemState dem = clump({Vec3{0.083, 0.081, 0}, Vec3{0.123, 0.081, 0}}, 0.02, 2600);
  dem.bodies[0].v = {0.01, -0.02, 0};
  dem.bodies[0].omega = {0, 0, 0.5};
  ResolvedSettings set;
  set.spacing = dx;
  set.fluid_density = 1000;
  set.slab_thickness = T;
  ResolvedCoupling<2> stage(set);
  const std::size_t fluid_before = solver.particles().count(isph::kFluid);
  stage.initialize(dem, solver);
  const auto& info = stage.bodies()[0];
  EXPECT_EQ(fluid_before - solver.particles().count(isph::kFluid), stage.removed_fluid());
  EXPECT_EQ(stage.removed_fluid(), info.particles);  // on the lattice: one fluid node each
  DemLoads loads;
  for (int n = 0; n < 3; ++n) {
    stage.before_fluid_step(dem, solver);
    solver.step(5e-4);
    loads = {};
    stage.after_fluid_step(dem, solver, 5e-4, loads);
  }
  const auto& P = solver.particles();
  isph::Vec<2> f = isph::Vec<2>::Zero(), c = isph::Vec<2>::Zero();
  std::size_t ns = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == isph::kSolid) {
      f += P.solid_force[i];
      c += P.x[i];
      ++ns;
    }
  c /= double(ns);
  double t = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == isph::kSolid) t += isph::moment<2>(P.x[i] - c, P.solid_force[i])[0];
  const double scale = dem.bodies[0].volume / (ns * dx * dx);
  ASSERT_EQ(loads.body_ids.size(), 1u);
  const double ef =
      std::hypot(loads.body_force[0][0] - scale * f[0], loads.body_force[0][1] - scale * f[1]) /
      (scale * f.norm());
  const double et = std::abs(loads.body_torque[0][2] - scale * t) / (scale * f.norm() * 0.02);
  std::printf(
      "handover: |F_body - sum f_i V/(N dx^2)| / |F| = %.2e, torque %.2e; N = %zu, "
      "scale/T = %.5f\n",
      ef, et, ns, info.scale / T);
  EXPECT_LT(ef, 1e-12);
  EXPECT_LT(et, 1e-12);
  EXPECT_EQ(loads.body_force[0][2], 0.0);
  EXPECT_TRUE(loads.atom_tags.empty());
  EXPECT_NEAR(info.scale, dem.bodies[0].volume / (ns * dx * dx), 1e-15);
}

TEST(ResolvedStage, BadSceneNamesCauseAndFix) {
  auto scene = tank<2>({});
  const double dx = scene.particles.spacing;
  ResolvedSettings set;
  set.spacing = dx;
  set.fluid_density = 1000;
  set.slab_thickness = 0.03;
  {
    isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
    ResolvedCoupling<2> stage(set);
    // Touching the floor (y = 0): shares nodes with the wall.
    const DemState dem = clump({Vec3{0.1, 0.01, 0}}, 0.02, 2600);
    try {
      stage.initialize(dem, solver);
      FAIL() << "no error for a clump in the wall";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("from walls"), std::string::npos) << e.what();
    }
  }
  set.slab_thickness = 0.0;
  EXPECT_THROW(ResolvedCoupling<2>{set}, std::invalid_argument);
  set.slab_thickness = 0.03;
  set.spacing = 2 * dx;
  {
    isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
    ResolvedCoupling<2> stage(set);
    EXPECT_THROW(stage.initialize(clump({Vec3{0.1, 0.1, 0}}, 0.02, 2600), solver),
                 std::invalid_argument);
  }
  set.spacing = dx;
  {
    isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
    ResolvedCoupling<2> stage(set);
    DemState dem = clump({Vec3{0.1, 0.1, 0}}, 0.02, 2600);
    stage.initialize(dem, solver);
    // A clump tilted out of the plane cannot be a 2D section.
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
    dem.bodies[0].quat = {q.w(), q.x(), q.y(), q.z()};
    try {
      stage.before_fluid_step(dem, solver);
      FAIL() << "no error for a tilted clump";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("planar z"), std::string::npos) << e.what();
    }
    dem.bodies[0].id = 7;
    EXPECT_THROW(stage.before_fluid_step(dem, solver), std::runtime_error);
  }
}

}  // namespace
}  // namespace isphdem::resolved_test
