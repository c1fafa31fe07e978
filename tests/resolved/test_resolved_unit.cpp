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

// coupling.pms_surface = "spheres": the depth and normal of each particle from the member spheres.
// A lone sphere in 3D: depth r - |x - c| and the radial normal (the level that encloses the DEM
// volume is the sphere itself, to the sampling's resolution). In a 2D slab thinner than 4r/3 the
// section is the circle dilated to the area V/T: radius r sqrt(4r / 3T).
TEST(PmsGeneration, SurfaceFromSpheresIsTheSphereOrItsEquivalentSection) {
  const double dx = 0.001, r = 0.004;
  const DemState s = clump({Vec3{0.0203, 0.0197, 0.0201}}, r, 2600);
  const DemBody& b = s.bodies[0];
  PmsGenerationSettings g{dx, 0.0, PmsShape::Lattice};
  const isph::Vec<3> c3(b.x[0], b.x[1], b.x[2]);
  const auto x3 = generate_pms_particles<3>(b, s.atoms, g, isph::Vec<3>(0.0005, 0.0005, 0.0005));
  const auto p3 = pms_surface_from_spheres<3>(b, s.atoms, g, isph::Domain<3>{}, x3);
  double worst_depth = 0.0, worst_normal = 0.0;
  for (std::size_t k = 0; k < x3.size(); ++k) {
    ASSERT_TRUE(p3[k].found);
    const isph::Vec<3> d = x3[k] - c3;
    worst_depth = std::max(worst_depth, std::abs(p3[k].depth - (r - d.norm())));
    if (d.norm() > 0.1 * dx)
      worst_normal = std::max(worst_normal, (p3[k].normal - d.normalized()).norm());
  }
  std::printf("3D sphere r = 4 dx, %zu particles: depth off by %.3e dx, normal by %.1e\n",
              x3.size(), worst_depth / dx, worst_normal);
  EXPECT_LT(worst_depth, 0.05 * dx);
  EXPECT_LT(worst_normal, 1e-9);

  g.slab_thickness = r;  // T = r < 4r/3: the section is dilated
  const auto x2 = generate_pms_particles<2>(b, s.atoms, g, isph::Vec<2>(0.0005, 0.0005));
  const auto p2 = pms_surface_from_spheres<2>(b, s.atoms, g, isph::Domain<2>{}, x2);
  const double r_eq = r * std::sqrt(4.0 * r / (3.0 * g.slab_thickness));
  worst_depth = 0.0;
  for (std::size_t k = 0; k < x2.size(); ++k)
    worst_depth = std::max(
        worst_depth, std::abs(p2[k].depth - (r_eq - (x2[k] - isph::Vec<2>(c3[0], c3[1])).norm())));
  std::printf("2D section, T = r: equivalent radius %.4f dx, depth off by %.3e dx\n", r_eq / dx,
              worst_depth / dx);
  EXPECT_LT(worst_depth, 0.05 * dx);

  // A slab so thin that the section dilates by more than the sphere's radius (T = r/4: 2.31 r).
  g.slab_thickness = 0.25 * r;
  const auto x4 = generate_pms_particles<2>(b, s.atoms, g, isph::Vec<2>(0.0005, 0.0005));
  const auto p4 = pms_surface_from_spheres<2>(b, s.atoms, g, isph::Domain<2>{}, x4);
  const double r_thin = r * std::sqrt(4.0 * r / (3.0 * g.slab_thickness));
  worst_depth = 0.0;
  for (std::size_t k = 0; k < x4.size(); ++k)
    worst_depth =
        std::max(worst_depth,
                 std::abs(p4[k].depth - (r_thin - (x4[k] - isph::Vec<2>(c3[0], c3[1])).norm())));
  std::printf("2D section, T = r/4: equivalent radius %.4f dx, depth off by %.3e dx\n", r_thin / dx,
              worst_depth / dx);
  EXPECT_LT(worst_depth, 0.05 * dx);

  // Spheres one spacing wide get one particle at each centre (auto): no surface points.
  const DemState fine = clump({Vec3{0.010, 0.010, 0.0}, Vec3{0.011, 0.010, 0.0}}, 0.5 * dx, 2600);
  g = {dx, dx, PmsShape::Auto};
  const auto xf = generate_pms_particles<2>(fine.bodies[0], fine.atoms, g, isph::Vec<2>(0, 0));
  for (const auto& q :
       pms_surface_from_spheres<2>(fine.bodies[0], fine.atoms, g, isph::Domain<2>{}, xf))
    EXPECT_FALSE(q.found);
}

// Two overlapping members: a particle in the neck between them has no exposed member surface
// along its radii (each is covered by the other sphere) and keeps the lattice's estimate; one
// on the far side of a member gets that member's surface.
TEST(PmsGeneration, SurfaceFromSpheresSkipsTheCoveredNeck) {
  const double dx = 0.001, r = 0.003;
  const DemState s = clump({Vec3{0.010, 0.010, 0.010}, Vec3{0.014, 0.010, 0.010}}, r, 2600);
  PmsGenerationSettings g{dx, 0.0, PmsShape::Outline};
  const std::vector<isph::Vec<3>> x{isph::Vec<3>(0.012, 0.010, 0.010),
                                    isph::Vec<3>(0.0085, 0.010, 0.010)};
  const auto p = pms_surface_from_spheres<3>(s.bodies[0], s.atoms, g, isph::Domain<3>{}, x);
  EXPECT_FALSE(p[0].found);
  ASSERT_TRUE(p[1].found);
  EXPECT_NEAR(p[1].depth, r - 0.0015, 1e-12);
  EXPECT_NEAR(p[1].normal[0], -1.0, 1e-12);
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

// Two bodies from clump(), renumbered so that ids and tags do not clash.
DemState two_bodies(const DemState& a, DemState b) {
  DemState s = a;
  b.bodies[0].id = 2;
  for (auto& t : b.bodies[0].members) t += 1000;
  for (auto& at : b.atoms) {
    at.tag += 1000;
    at.body = 2;
    s.atoms.push_back(at);
  }
  s.bodies.push_back(b.bodies[0]);
  return s;
}

std::vector<DemAtom> members_of(const DemState& s, int body) {
  std::vector<DemAtom> m;
  for (const auto& a : s.atoms)
    if (a.body == body) m.push_back(a);
  return m;
}

TEST(PmsGeneration, TouchingBodiesDoNotShareANode) {
  // Two spheres in contact at x = 10 mm; a thin slab dilates their sections to radius 4 dx, so
  // each takes the lattice nodes of a lens around the contact that the other takes too.
  const double dx = 0.001, r = 0.002, T = 0.001;
  const DemState s =
      two_bodies(clump({Vec3{0.008, 0.01, 0}}, r, 2600), clump({Vec3{0.012, 0.01, 0}}, r, 2600));
  const std::vector<std::vector<DemAtom>> members{members_of(s, 1), members_of(s, 2)};
  PmsGenerationSettings g{dx, T, PmsShape::Lattice};
  const isph::Vec<2> origin(0.0005, 0.0005);
  std::vector<std::vector<isph::Vec<2>>> x;
  for (int b = 0; b < 2; ++b)
    x.push_back(generate_pms_particles<2>(s.bodies[b], members[b], g, origin));
  auto shared = [&] {
    std::size_t n = 0;
    for (const auto& p : x[0])
      for (const auto& q : x[1])
        if ((p - q).norm() < 0.5 * dx) ++n;
    return n;
  };
  const std::size_t before = shared(), n0 = x[0].size(), n1 = x[1].size();
  ASSERT_GT(before, 0u) << "the scene should make the bodies claim common nodes";
  isph::Domain<2> domain;
  domain.lo = isph::Vec<2>(0, 0);
  domain.hi = isph::Vec<2>(0.02, 0.02);
  const std::size_t removed = remove_shared_pms_nodes<2>(x, s.bodies, members, domain, dx);
  std::printf("%zu shared nodes; removed %zu (body 1: %zu -> %zu, body 2: %zu -> %zu)\n", before,
              removed, n0, x[0].size(), n1, x[1].size());
  EXPECT_EQ(removed, before);
  EXPECT_EQ(shared(), 0u);
  EXPECT_EQ(x[0].size() + x[1].size(), n0 + n1 - before);
  // Each shared node stays with the body it lies deeper in: the one on its side of the contact
  // plane (ties on the plane itself may go either way).
  for (const auto& p : x[0]) EXPECT_LE(p[0], 0.010 + 1e-12) << p.transpose();
  for (const auto& p : x[1]) EXPECT_GE(p[0], 0.010 - 1e-12) << p.transpose();

  // A body with a single particle keeps it, even where it lies less deep than in its neighbour
  // (here 0.1 mm inside its own sphere, over 2 mm inside the other).
  const DemState t = two_bodies(clump({Vec3{0.0100, 0.0100, 0}}, 0.003, 2600),
                                clump({Vec3{0.0105, 0.0100, 0}}, 0.0006, 2600));
  const std::vector<std::vector<DemAtom>> tm{members_of(t, 1), members_of(t, 2)};
  std::vector<std::vector<isph::Vec<2>>> y{
      generate_pms_particles<2>(t.bodies[0], tm[0], g, origin),
      generate_pms_particles<2>(t.bodies[1], tm[1], g, origin)};
  ASSERT_EQ(y[1].size(), 1u);
  const std::size_t big = y[0].size();
  bool covered = false;
  for (const auto& p : y[0]) covered |= (p - y[1][0]).norm() < 0.5 * dx;
  ASSERT_TRUE(covered) << "the small body's node should lie inside the large one";
  EXPECT_EQ(remove_shared_pms_nodes<2>(y, t.bodies, tm, domain, dx), 1u);
  EXPECT_EQ(y[1].size(), 1u);
  EXPECT_EQ(y[0].size(), big - 1);
}

// The seed's coarse grain: 19 touching 1 mm spheres in a hexagon, at dx = 1 mm in a 1 mm slab.
// Its DEM volume asks for 10 particles ("lattice"), which leaves a rim of fluid inside the
// grain's outline: between two touching grains a clear channel of 1-2 spacings, where the pore
// jets of examples/internal_erosion_2d at 2 cm/s ran away. "outline" takes every node inside
// the members (interstices closed), which is about the seed's one particle per sphere (19) but
// on the lattice: at any rotation and offset no free node is left within the hexagon of the
// outer sphere centres, and none beyond the spheres' outline.
TEST(PmsGeneration, OutlineFillsTheGrain) {
  const double dx = 0.001, d = 0.001;
  int lattice_missing = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const double th = 0.13 * trial, ox = 0.01 + 0.00013 * trial, oy = 0.01 + 0.00029 * trial;
    std::vector<Vec3> c;
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 2; ++j) {
        if (std::abs(i + j) > 2) continue;  // axial hexagon coordinates
        const double x = d * (i + 0.5 * j), y = d * 0.8660254037844386 * j;
        c.push_back(Vec3{ox + std::cos(th) * x - std::sin(th) * y,
                         oy + std::sin(th) * x + std::cos(th) * y, 0.0});
      }
    ASSERT_EQ(c.size(), 19u);
    const DemState s = clump(c, 0.5 * d, 2600);
    const isph::Vec<2> origin(0.0005, 0.0005), cm(ox, oy);
    PmsGenerationSettings g{dx, 0.001, PmsShape::Outline};
    const auto x = generate_pms_particles<2>(s.bodies[0], s.atoms, g, origin);
    g.shape = PmsShape::Lattice;
    const auto lat = generate_pms_particles<2>(s.bodies[0], s.atoms, g, origin);
    auto taken = [](const std::vector<isph::Vec<2>>& v, const isph::Vec<2>& node) {
      for (const auto& p : v)
        if ((p - node).norm() < 1e-9) return true;
      return false;
    };
    // Nodes within the circle inscribed in the hexagon of the outer centres (radius sqrt(3) d).
    int inner = 0, missing = 0, lat_missing = 0;
    for (int a = 0; a < 40; ++a)
      for (int b = 0; b < 40; ++b) {
        const isph::Vec<2> node(origin[0] + a * dx, origin[1] + b * dx);
        if ((node - cm).norm() > 1.7 * d) continue;
        ++inner;
        missing += !taken(x, node);
        lat_missing += !taken(lat, node);
      }
    lattice_missing += lat_missing;
    double outside = 0.0;  // farthest particle beyond every member sphere
    for (const auto& p : x) {
      double depth = -1.0;
      for (const auto& ci : c)
        depth = std::max(depth, 0.5 * d - (p - isph::Vec<2>(ci[0], ci[1])).norm());
      outside = std::max(outside, -depth);
    }
    std::printf(
        "rotation %.2f rad: outline %zu particles (lattice %zu); %d nodes within the inner "
        "hexagon, outline leaves %d free (lattice %d); farthest %.3f dx outside a sphere\n",
        th, x.size(), lat.size(), inner, missing, lat_missing, outside / dx);
    EXPECT_EQ(missing, 0);
    EXPECT_GE(x.size(), 14u);
    EXPECT_LE(x.size(), 22u);
    EXPECT_LE(outside, 0.15 * dx + 1e-12);
  }
  std::printf("lattice: %d inner nodes left to the fluid over all rotations\n", lattice_missing);
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
    stage.move_particles(dem, solver);
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
      stage.move_particles(dem, solver);
      FAIL() << "no error for a tilted clump";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("planar z"), std::string::npos) << e.what();
    }
    dem.bodies[0].id = 7;
    EXPECT_THROW(stage.move_particles(dem, solver), std::runtime_error);
  }
}

}  // namespace
}  // namespace isphdem::resolved_test
