// Surface exchange: a gap in the top row is filled from the row below, a void under a squeezed
// top row from the row itself; an intact surface is left alone; the particle count never changes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "kernel.hpp"
#include "neighbors.hpp"
#include "surface_exchange.hpp"

namespace isph {
namespace {

constexpr double kDx = 0.01;
const Vec<2> kUp(0.0, 1.0);

struct Water {
  Particles<2> p;
  Neighbors<2> nb;
  Domain<2> dom;
};

// 20 columns x 10 rows on a floor, periodic in x; the top row (j = 9) is flagged as surface.
// `skip(i, j)` leaves a lattice site empty, `move(i, j, x)` places the particle elsewhere.
Water make_water(const std::function<bool(int, int)>& skip,
                 const std::function<void(int, int, Vec<2>&)>& move) {
  Water w;
  w.p.spacing = kDx;
  w.p.volume = kDx * kDx;
  for (int j = -3; j < 10; ++j)
    for (int i = 0; i < 20; ++i) {
      if (j >= 0 && skip(i, j)) continue;
      Vec<2> x((i + 0.5) * kDx, (j + 0.5) * kDx);
      if (j >= 0) move(i, j, x);
      w.p.add(x, Vec<2>(0.001 * i, 0.0), j < 0 ? kWall : kFluid);
      w.p.surface.back() = j == 9;
    }
  w.dom.lo = Vec<2>(0.0, -0.05);
  w.dom.hi = Vec<2>(0.2, 0.2);
  w.dom.periodic[0] = true;
  Kernel<2> W(KernelType::WendlandC2, 1.3 * kDx);
  NeighborSearch<2> search(w.dom, W.support());
  search.sort(w.p);
  search.build(w.p, W, w.nb);
  return w;
}

bool none(int, int) { return false; }
void stay(int, int, Vec<2>&) {}

int count_near(const Particles<2>& p, const Vec<2>& x, double r) {
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) n += (p.x[i] - x).norm() < r;
  return n;
}

TEST(SurfaceExchange, IntactSurfaceIsLeftAlone) {
  Water w = make_water(none, stay);
  const auto before = w.p.x;
  const auto c = exchange_surface_particles(w.p, w.nb, w.dom, kUp, SurfaceExchangeParams{});
  EXPECT_EQ(c.gaps_filled + c.voids_filled, 0);
  EXPECT_EQ(w.p.x, before);
}

TEST(SurfaceExchange, GapInTopRowIsFilledFromBelow) {
  // Site 10 of the top row is empty: its neighbours are 2 dx apart.
  Water w = make_water([](int i, int j) { return j == 9 && i == 10; }, stay);
  const std::size_t n = w.p.size();
  const Vec<2> gap(10.5 * kDx, 9.5 * kDx), below(10.5 * kDx, 8.5 * kDx);
  const auto c = exchange_surface_particles(w.p, w.nb, w.dom, kUp, SurfaceExchangeParams{});
  EXPECT_EQ(c.gaps_filled, 1);
  EXPECT_EQ(c.voids_filled, 0);
  EXPECT_EQ(w.p.size(), n);
  EXPECT_EQ(count_near(w.p, gap, 1e-9), 1) << "the gap's midpoint holds a particle";
  EXPECT_EQ(count_near(w.p, below, 1e-9), 0) << "taken from the site right below it";
  // It carries the mean velocity of the two surface particles beside the gap (0.009, 0.011).
  for (std::size_t i = 0; i < w.p.size(); ++i)
    if ((w.p.x[i] - gap).norm() < 1e-9) {
      EXPECT_NEAR(w.p.v[i][0], 0.010, 1e-12);
    }
}

TEST(SurfaceExchange, StaggeredSecondRowParticleIsLiftedIntoAStretchedGap) {
  // Top row 1.5 dx apart over columns 8-12 (two sites removed, the rest moved sideways); the
  // second-row particle under the gap sits half a spacing below the row.
  Water w = make_water([](int i, int j) { return j == 9 && (i == 9 || i == 11); },
                       [](int i, int j, Vec<2>& x) {
                         if (j == 9 && i == 10) x[0] += 0.25 * kDx;
                         if (j == 8 && i == 9) x += Vec<2>(0.5 * kDx, 0.5 * kDx);
                       });
  const std::size_t n = w.p.size();
  SurfaceExchangeParams params;
  params.gap = 1.3;
  const auto c = exchange_surface_particles(w.p, w.nb, w.dom, kUp, params);
  EXPECT_GE(c.gaps_filled, 1);
  EXPECT_EQ(w.p.size(), n);
  // The lifted particle now lies on the row (y = 9.5 dx) between 8.5 and 10.75 dx.
  EXPECT_EQ(count_near(w.p, Vec<2>(9.5 * kDx, 9.0 * kDx), 1e-9), 0);
  EXPECT_EQ(count_near(w.p, Vec<2>(9.625 * kDx, 9.5 * kDx), 1e-9), 1);
}

TEST(SurfaceExchange, SqueezedTopRowFillsAVoidUnderIt) {
  // Site (5, 8) under the surface is empty and the top-row particle above it has a neighbour
  // 0.4 spacings away (moved in from the left, over a full second row): it moves down one
  // spacing into the void. The 1.6-spacing gap the squeeze leaves is not filled here.
  Water w = make_water([](int i, int j) { return j == 8 && i == 5; },
                       [](int i, int j, Vec<2>& x) {
                         if (j == 9 && i == 4) x[0] += 0.6 * kDx;
                       });
  const std::size_t n = w.p.size();
  SurfaceExchangeParams params;
  params.gap = 2.0;
  const auto c = exchange_surface_particles(w.p, w.nb, w.dom, kUp, params);
  EXPECT_EQ(c.voids_filled, 1);
  EXPECT_EQ(w.p.size(), n);
  EXPECT_EQ(count_near(w.p, Vec<2>(5.5 * kDx, 8.5 * kDx), 1e-9), 1);
  EXPECT_EQ(count_near(w.p, Vec<2>(5.5 * kDx, 9.5 * kDx), 1e-9), 0);
}

}  // namespace
}  // namespace isph
