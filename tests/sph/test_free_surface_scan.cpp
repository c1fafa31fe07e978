// The scan test of free-surface detection: the top row of a water block is open above, also
// when squeezed together; the rows below and a disordered interior are not.
#include <gtest/gtest.h>

#include <random>

#include "free_surface.hpp"
#include "kernel.hpp"
#include "lattice.hpp"
#include "neighbors.hpp"

namespace isph {
namespace {

struct Block {
  Particles<2> p;
  Neighbors<2> nb;
};

// A 20 x 10 water block of spacing dx on a floor and between side walls (periodic in x), the
// top row optionally squeezed sideways to `squeeze` dx.
Block make_block(double squeeze, double jitter) {
  const double dx = 0.01;
  Block b;
  b.p.spacing = dx;
  b.p.volume = dx * dx;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = -3; j < 10; ++j) {
    const bool top = j == 9;
    const int n = top ? static_cast<int>(20 / squeeze) : 20;
    for (int i = 0; i < n; ++i) {
      const double sx = top ? squeeze * dx : dx;
      Vec<2> x((i + 0.5) * sx, (j + 0.5) * dx);
      if (j >= 0 && j < 8) x += Vec<2>(u(rng), u(rng)) * dx;
      b.p.add(x, Vec<2>::Zero(), j < 0 ? kWall : kFluid);
    }
  }
  b.p.surface.assign(b.p.size(), 0);
  Domain<2> dom;
  dom.lo = Vec<2>(0.0, -0.05);
  dom.hi = Vec<2>(0.2, 0.2);
  dom.periodic[0] = true;
  Kernel<2> W(KernelType::WendlandC2, 1.3 * dx);
  NeighborSearch<2> search(dom, W.support());
  search.sort(b.p);
  search.build(b.p, W, b.nb);
  return b;
}

void check(double squeeze, double jitter) {
  Block b = make_block(squeeze, jitter);
  mark_open_side_as_surface(b.p, b.nb);
  int top = 0, top_marked = 0, below_marked = 0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    if (b.p.kind[i] == kWall) {
      EXPECT_FALSE(b.p.surface[i]);
      continue;
    }
    const bool is_top = b.p.x[i][1] > 0.09;
    top += is_top;
    if (is_top)
      top_marked += b.p.surface[i];
    else
      below_marked += b.p.surface[i];
  }
  std::printf("squeeze %.2f, jitter %.2f dx: top row %d/%d marked, %d below marked\n", squeeze,
              jitter, top_marked, top, below_marked);
  EXPECT_EQ(top_marked, top);
  EXPECT_EQ(below_marked, 0);
}

TEST(FreeSurfaceScan, TopRowMarkedRowsBelowNot) { check(1.0, 0.0); }
TEST(FreeSurfaceScan, SqueezedTopRowStillMarked) { check(0.75, 0.0); }
TEST(FreeSurfaceScan, DisorderedInteriorNotMarked) { check(1.0, 0.15); }

}  // namespace
}  // namespace isph
