// UnresolvedCoupling as a stage, without LIGGGHTS: a random fluid and random grains through
// before_fluid_step -> IsphSolver::step -> after_fluid_step. Momentum is conserved by
// construction (DESIGN.md decision 3): the drag handed to the grains is minus the resistance
// the fluid received, to round-off, in 2D (quasi-2D slab) and 3D, across periodic faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "isph_solver.hpp"
#include "lattice.hpp"
#include "unresolved/unresolved_coupling.hpp"

namespace isphdem {
namespace {

template <int Dim>
void check_momentum(unsigned seed, bool self_induced = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double dx = 1e-3, L = 10 * dx;
  isph::Domain<Dim> domain;
  domain.lo.setZero();
  domain.hi.setConstant(L);
  domain.periodic.fill(true);
  isph::Particles<Dim> P;
  P.spacing = dx;
  P.volume = std::pow(dx, Dim);
  isph::fill_box<Dim>(P, domain.lo, domain.hi, dx, isph::kFluid);
  for (auto& v : P.v)
    for (int a = 0; a < Dim; ++a) v[a] = 0.02 * (u01(rng) - 0.5);
  isph::IsphConfig<Dim> cfg;
  cfg.free_surface = false;
  cfg.gravity[Dim - 1] = -9.81;
  isph::IsphSolver<Dim> solver(cfg, domain, std::move(P));

  DemState dem;
  const double T = 1e-3;
  for (int k = 0; k < 60; ++k) {
    DemAtom a;
    a.tag = 100 + 3 * k;
    for (int c = 0; c < 3; ++c) a.x[c] = L * u01(rng), a.v[c] = 0.05 * (u01(rng) - 0.5);
    if (Dim == 2) a.x[2] = 0.5 * T;
    a.radius = 0.5e-3 * (0.8 + 0.4 * u01(rng));
    dem.atoms.push_back(a);
  }
  DemAtom clump_member = dem.atoms.front();
  clump_member.tag = 7;
  clump_member.body = 1;  // belongs to a clump: not a fine grain
  dem.atoms.push_back(clump_member);

  UnresolvedSettings s;
  s.map.smoothing_length = 1.3 * dx;
  s.map.slab_thickness = T;
  SeedResistanceParameters p;
  p.blend = true;
  s.self_induced_correction = self_induced;
  s.kinematic_viscosity = cfg.viscosity;
  UnresolvedCoupling<Dim> stage(s, std::make_shared<SeedResistance>(p));
  stage.initialize(dem, solver);
  DemLoads loads;
  for (int step = 0; step < 3; ++step) {
    stage.before_fluid_step(dem, solver);
    solver.step(1e-4);
    loads = DemLoads{};
    stage.after_fluid_step(dem, solver, 1e-4, loads);
  }

  // The fluid's resistance recomputed here from the particles (all fluid in this box).
  const auto& Q = solver.particles();
  const double depth = Dim == 2 ? T : 1.0;
  isph::Vec<Dim> resistance = isph::Vec<Dim>::Zero();
  for (std::size_t i = 0; i < Q.size(); ++i)
    resistance -= depth * Q.porosity[i] * cfg.density * Q.volume * Q.resistance[i] *
                  (Q.v[i] / Q.porosity[i] - Q.solid_velocity[i]);
  isph::Vec<Dim> handed = isph::Vec<Dim>::Zero();
  for (const auto& f : loads.atom_force)
    for (int a = 0; a < Dim; ++a) handed[a] += f[a];
  const auto& b = stage.balance();
  const isph::Vec<Dim> drag = handed - b.grain_pressure;
  const double scale = resistance.norm();
  const double err = (drag + resistance).norm() / scale;
  std::printf(
      "%dD: |fluid resistance| %.3e N, |sum of grain drag + resistance| / |resistance| "
      "= %.2e (%zu grains, %zu floored)\n",
      Dim, scale, err, b.grains, b.floored);
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(err, 1e-12);
  EXPECT_LT((b.fluid_resistance - resistance).norm() / scale, 1e-12);
  // The correction raised some grain's drag, and the reaction rose with it (above).
  if (self_induced) {
    EXPECT_GT(b.max_self_induced, 0.0);
  }
  // One load per fine grain, none for the clump member, none twice (periodic images merged).
  EXPECT_EQ(loads.atom_tags.size(), 60u);
  for (int tag : loads.atom_tags) EXPECT_NE(tag, 7);
  std::vector<int> tags = loads.atom_tags;
  std::sort(tags.begin(), tags.end());
  EXPECT_EQ(std::adjacent_find(tags.begin(), tags.end()), tags.end());
  if (Dim == 2) {
    for (const auto& f : loads.atom_force) {
      EXPECT_EQ(f[2], 0.0);
    }
  }
}

TEST(UnresolvedCoupling, MomentumIsConservedIn2D) { check_momentum<2>(3); }
TEST(UnresolvedCoupling, MomentumIsConservedIn3D) { check_momentum<3>(5); }
// The self-induced correction scales each particle's resistance; the grains' drag follows it.
TEST(UnresolvedCoupling, MomentumIsConservedWithTheSelfInducedCorrection) {
  check_momentum<3>(7, true);
}

TEST(UnresolvedCoupling, SelfInducedCorrectionIsRefusedIn2D) {
  UnresolvedSettings s;
  s.map.smoothing_length = 1.3e-3;
  s.map.slab_thickness = 1e-3;
  s.self_induced_correction = true;
  s.kinematic_viscosity = 1e-6;
  try {
    UnresolvedCoupling<2> stage(s, std::make_shared<SeedResistance>(SeedResistanceParameters{}));
    FAIL() << "a 2D stage took the self-induced correction";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("self_induced_correction"), std::string::npos) << e.what();
  }
}

// A porosity kernel wider than half a periodic box needs each grain's images on both sides: a
// simple cubic lattice of touching spheres (2 per axis in an 8 mm box) seen through a kernel
// reaching the whole box has the lattice's porosity 1 - pi/6 = 0.4764 everywhere (measured
// 0.4661 ... 0.4838; with one image per grain up to 0.883). A kernel reaching farther than the
// box is refused.
TEST(UnresolvedCoupling, WideKernelSeesImagesOnBothSidesOfAPeriodicBox) {
  const double dx = 1e-3, L = 8e-3, d = 4e-3;
  isph::Domain<3> domain;
  domain.hi.setConstant(L);
  domain.periodic.fill(true);
  isph::Particles<3> P;
  P.spacing = dx;
  P.volume = dx * dx * dx;
  isph::fill_box<3>(P, domain.lo, domain.hi, dx, isph::kFluid);
  isph::IsphConfig<3> cfg;
  cfg.free_surface = false;
  isph::IsphSolver<3> solver(cfg, domain, std::move(P));
  DemState dem;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        DemAtom a;
        a.tag = 1 + i + 2 * j + 4 * k;
        a.x = {(i + 0.5) * d, (j + 0.5) * d, (k + 0.5) * d};
        a.radius = 0.5 * d;
        dem.atoms.push_back(a);
      }
  auto stage_with = [](double smoothing) {
    UnresolvedSettings s;
    s.map.smoothing_length = smoothing;
    return UnresolvedCoupling<3>(s, std::make_shared<SeedResistance>(SeedResistanceParameters{}));
  };
  auto stage = stage_with(0.5 * L);  // support 2 x 4 mm: the whole box
  stage.initialize(dem, solver);
  stage.before_fluid_step(dem, solver);
  const auto& eps = solver.particles().porosity;
  const double lo = *std::min_element(eps.begin(), eps.end());
  const double hi = *std::max_element(eps.begin(), eps.end());
  std::printf("porosity %.4f ... %.4f against 1 - pi/6 = %.4f\n", lo, hi, 1 - M_PI / 6);
  EXPECT_NEAR(lo, 1 - M_PI / 6, 0.02);
  EXPECT_NEAR(hi, 1 - M_PI / 6, 0.02);
  auto too_wide = stage_with(0.6 * L);
  EXPECT_THROW(too_wide.initialize(dem, solver), std::runtime_error);
}

// Still water in a 10 mm periodic square at dx = 1 mm, and the settings of a 1 mm slab.
std::unique_ptr<isph::IsphSolver<2>> still_square() {
  isph::Domain<2> domain;
  domain.hi = {0.01, 0.01};
  domain.periodic = {true, true};
  isph::Particles<2> P;
  P.spacing = 1e-3;
  P.volume = 1e-6;
  isph::fill_box<2>(P, domain.lo, domain.hi, 1e-3, isph::kFluid);
  isph::IsphConfig<2> cfg;
  cfg.free_surface = false;
  return std::make_unique<isph::IsphSolver<2>>(cfg, domain, std::move(P));
}

UnresolvedSettings slab_settings() {
  UnresolvedSettings s;
  s.map.smoothing_length = 1.3e-3;
  s.map.slab_thickness = 1e-3;
  return s;
}

// With no grains in range, the stage leaves the fluid exactly clear (eps = 1, K = 0).
TEST(UnresolvedCoupling, NoGrainsLeaveTheFluidClear) {
  const auto solver_ptr = still_square();
  auto& solver = *solver_ptr;
  UnresolvedCoupling<2> stage(slab_settings(),
                              std::make_shared<SeedResistance>(SeedResistanceParameters{}));
  DemState dem;
  stage.before_fluid_step(dem, solver);
  for (std::size_t i = 0; i < solver.particles().size(); ++i) {
    EXPECT_EQ(solver.particles().porosity[i], 1.0);
    EXPECT_EQ(solver.particles().resistance[i], 0.0);
  }
}

// unresolved.grain_diameter is a check: grains of that size pass, and a grain of another size
// stops the run with a message that names it and the fix.
TEST(UnresolvedCoupling, GrainDiameterKeyNamesTheGrainsThatDiffer) {
  const auto solver_ptr = still_square();
  auto& solver = *solver_ptr;
  UnresolvedSettings s = slab_settings();
  s.grain_diameter = 1e-3;
  UnresolvedCoupling<2> stage(s, std::make_shared<SeedResistance>(SeedResistanceParameters{}));
  DemState dem;
  for (int k = 0; k < 4; ++k) {
    DemAtom a;
    a.tag = 11 + k;
    a.x = {2e-3 * (k + 1), 5e-3, 0.5e-3};
    a.radius = 0.5e-3;
    dem.atoms.push_back(a);
  }
  EXPECT_NO_THROW(stage.initialize(dem, solver));
  dem.atoms[2].radius = 0.4e-3;
  try {
    stage.initialize(dem, solver);
    ADD_FAILURE() << "a 0.8 mm grain passed the 1 mm check";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    std::printf("%s\n", m.c_str());
    EXPECT_NE(m.find("1 of the 4"), std::string::npos);
    EXPECT_NE(m.find("grain 13: 0.0008 m"), std::string::npos);
    EXPECT_NE(m.find("remove unresolved.grain_diameter"), std::string::npos);
  }
}

}  // namespace
}  // namespace isphdem
