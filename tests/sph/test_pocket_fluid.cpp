// Fluid in pockets between PMS solids follows them (sph/pocket_fluid.hpp): a particle enclosed by
// solids takes their velocity, and the momentum it loses goes to them; the first fluid row along a
// flat or convex body is left alone, so the single-body drag and buoyancy results stand.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "kernel.hpp"
#include "neighbors.hpp"
#include "pocket_fluid.hpp"

namespace isph {
namespace {

constexpr double kDx = 0.001, kRho = 1000.0, kDt = 1e-4;

struct Scene {
  Particles<2> p;
  Neighbors<2> nb;
};

// A 21 x 21 lattice, periodic; solid(i, j) picks the solid nodes, which move at `us`; the fluid
// moves at `uf`.
Scene make_scene(const std::function<bool(int, int)>& solid, const Vec<2>& us, const Vec<2>& uf) {
  Scene s;
  s.p.spacing = kDx;
  s.p.volume = kDx * kDx;
  for (int j = -10; j <= 10; ++j)
    for (int i = -10; i <= 10; ++i) {
      const bool sol = solid(i, j);
      s.p.add(Vec<2>((i + 10.5) * kDx, (j + 10.5) * kDx), sol ? us : uf, sol ? kSolid : kFluid);
    }
  s.p.surface.assign(s.p.size(), 0);
  Domain<2> dom;
  dom.lo = Vec<2>(0.0, 0.0);
  dom.hi = Vec<2>(21 * kDx, 21 * kDx);
  dom.periodic[0] = dom.periodic[1] = true;
  Kernel<2> W(KernelType::WendlandC2, 1.3 * kDx);
  NeighborSearch<2> search(dom, W.support());
  search.sort(s.p);
  search.build(s.p, W, s.nb);
  return s;
}

Vec<2> momentum_change(const Scene& s, const std::vector<Vec<2>>& v0) {
  Vec<2> m = Vec<2>::Zero();
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    if (s.p.kind[i] == kFluid) m += kRho * s.p.volume * (s.p.v[i] - v0[i]);
    if (s.p.kind[i] == kSolid) m += kDt * s.p.solid_force[i];
  }
  return m;
}

TEST(PocketFluid, EnclosedParticleTakesTheSolidsVelocityAndMomentumIsKept) {
  const Vec<2> us(0.01, -0.02), uf(0.8, 0.3);
  Scene s = make_scene([](int i, int j) { return i != 0 || j != 0; }, us, uf);
  const std::vector<Vec<2>> v0 = s.p.v;
  int centre = -1;
  for (std::size_t i = 0; i < s.p.size(); ++i)
    if (s.p.kind[i] == kFluid) centre = static_cast<int>(i);
  const double phi = solid_share(s.p, s.nb, centre);
  std::printf("solid share of a fluid particle enclosed by solids: %.3f\n", phi);
  EXPECT_DOUBLE_EQ(phi, 1.0);
  EXPECT_EQ(follow_enclosing_solids(s.p, s.nb, 0.5, kRho, kDt), 1);
  EXPECT_LT((s.p.v[centre] - us).norm(), 1e-12);
  const Vec<2> dm = momentum_change(s, v0);
  std::printf("momentum lost by the particle %.3e, net change %.3e kg m/s per m\n",
              kRho * s.p.volume * (uf - us).norm(), dm.norm());
  EXPECT_LT(dm.norm(), 1e-12 * kRho * s.p.volume * (uf - us).norm());
}

TEST(PocketFluid, FirstRowBesideFlatOrConvexBodyIsLeftAlone) {
  const Vec<2> us = Vec<2>::Zero(), uf(0.05, 0.0);
  // A flat body (the lower half) and a disc of radius 4 dx.
  for (const auto& [name, solid] :
       std::vector<std::pair<const char*, std::function<bool(int, int)>>>{
           {"flat", [](int, int j) { return j < 0; }},
           {"disc", [](int i, int j) { return i * i + j * j <= 16; }}}) {
    Scene s = make_scene(solid, us, uf);
    double worst = 0.0;
    for (std::size_t i = 0; i < s.p.size(); ++i)
      if (s.p.kind[i] == kFluid) worst = std::max(worst, solid_share(s.p, s.nb, int(i)));
    std::printf("%s body: largest solid share of a fluid particle %.3f\n", name, worst);
    EXPECT_LT(worst, 0.5) << name;
    EXPECT_EQ(follow_enclosing_solids(s.p, s.nb, 0.5, kRho, kDt), 0) << name;
    for (std::size_t i = 0; i < s.p.size(); ++i) {
      if (s.p.kind[i] == kFluid) {
        EXPECT_EQ(s.p.v[i], uf);
      }
    }
  }
}

TEST(PocketFluid, ChannelOneSpacingWideFollowsItsWalls) {
  // A single fluid row between two solid half-spaces: a slot below the resolution, as between
  // two touching grains. Its fluid is pulled towards the walls' velocity, not left to run.
  const Vec<2> us(0.0, 0.0), uf(0.3, 0.0);
  Scene s = make_scene([](int, int j) { return j != 0; }, us, uf);
  const std::vector<Vec<2>> v0 = s.p.v;
  int fluid = -1;
  for (std::size_t i = 0; i < s.p.size(); ++i)
    if (s.p.kind[i] == kFluid) fluid = static_cast<int>(i);
  const double phi = solid_share(s.p, s.nb, fluid);
  const int n = follow_enclosing_solids(s.p, s.nb, 0.5, kRho, kDt);
  std::printf(
      "one-spacing slot: solid share %.3f, %d of 21 particles blended, speed %.3f -> %.3f\n", phi,
      n, uf.norm(), s.p.v[fluid].norm());
  EXPECT_GT(phi, 0.5);
  EXPECT_EQ(n, 21);
  EXPECT_LT(s.p.v[fluid].norm(), 0.5 * uf.norm());
  EXPECT_LT(momentum_change(s, v0).norm(), 1e-12 * 21 * kRho * s.p.volume * uf.norm());
}

TEST(PocketFluid, OnsetOfOneTurnsItOff) {
  Scene s =
      make_scene([](int i, int j) { return i != 0 || j != 0; }, Vec<2>::Zero(), Vec<2>(1.0, 0.0));
  EXPECT_EQ(follow_enclosing_solids(s.p, s.nb, 1.0, kRho, kDt), 0);
}

}  // namespace
}  // namespace isph
