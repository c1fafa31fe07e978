// The scan test of free-surface detection: the top row of a water block is open above, also
// when squeezed together; the rows below and a disordered interior are not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// A 20 x 10 water block of spacing dx on a floor, the top row optionally squeezed sideways to
// `squeeze` dx. Periodic in x, or between side walls that rise 5 dx above the water and with a
// submerged plate in the middle. With `hex_top` the two top rows are one staggered layer instead
// (spacing 10/7 dx, the lower row 0.66 dx down in the gaps), as diverging surface flow arranges
// them: the lower row is not surface.
Block make_block(double squeeze, double jitter, bool side_walls = false, bool hex_top = false) {
  const double dx = 0.01;
  Block b;
  b.p.spacing = dx;
  b.p.volume = dx * dx;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = -3; j < 10; ++j) {
    const bool top = j == 9;
    if (hex_top && j >= 8) {
      const double sx = 20.0 / 14.0 * dx;
      for (int i = 0; i < 14; ++i)
        b.p.add(Vec<2>((i + (top ? 0.5 : 1.0)) * sx, top ? 9.5 * dx : 8.84 * dx), Vec<2>::Zero(),
                kFluid);
      continue;
    }
    const int n = top ? static_cast<int>(20 / squeeze) : 20;
    for (int i = 0; i < n; ++i) {
      const double sx = top ? squeeze * dx : dx;
      Vec<2> x((i + 0.5) * sx, (j + 0.5) * dx);
      // With side walls, a submerged plate (two rows, 10 dx wide) whose underside is a roof.
      const bool plate = side_walls && (j == 4 || j == 5) && i >= 5 && i < 15;
      if (j >= 0 && j < 8 && !plate) x += Vec<2>(u(rng), u(rng)) * dx;
      b.p.add(x, Vec<2>::Zero(), j < 0 || plate ? kWall : kFluid);
    }
  }
  if (side_walls)
    for (int j = -3; j < 15; ++j)
      for (int i = 0; i < 3; ++i) {
        b.p.add(Vec<2>(-(i + 0.5) * dx, (j + 0.5) * dx), Vec<2>::Zero(), kWall);
        b.p.add(Vec<2>(0.2 + (i + 0.5) * dx, (j + 0.5) * dx), Vec<2>::Zero(), kWall);
      }
  b.p.surface.assign(b.p.size(), 0);
  Domain<2> dom;
  dom.lo = Vec<2>(0.0, -0.05);
  dom.hi = Vec<2>(0.2, 0.2);
  dom.periodic[0] = !side_walls;
  if (side_walls) {
    dom.lo[0] = -0.05;
    dom.hi[0] = 0.25;
  }
  Kernel<2> W(KernelType::WendlandC2, 1.3 * dx);
  NeighborSearch<2> search(dom, W.support());
  search.sort(b.p);
  search.build(b.p, W, b.nb);
  return b;
}

void check(double squeeze, double jitter, bool side_walls = false, bool hex_top = false,
           bool use_up = true) {
  Block b = make_block(squeeze, jitter, side_walls, hex_top);
  // Hydrostatic pressures (p = 0 on the top row) from which the walls' dryness is judged.
  const double rho = 1000.0, g = 9.81, y_top = 0.095;
  for (std::size_t i = 0; i < b.p.size(); ++i)
    if (b.p.kind[i] != kWall) b.p.p[i] = rho * g * std::max(y_top - b.p.x[i][1], 0.0);
  std::vector<uint8_t> dry;
  mark_dry_walls(b.p, b.nb, Vec<2>(0.0, -g), rho, dry);
  int dry_below = 0, dry_count = 0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    dry_count += dry[i];
    dry_below += dry[i] && b.p.x[i][1] < y_top;
  }
  EXPECT_EQ(dry_below, 0) << "walls beside the water must not read as dry";
  if (side_walls) {
    EXPECT_GT(dry_count, 0);
  }
  const Vec<2> up(0.0, 1.0);
  mark_open_side_as_surface(b.p, b.nb, &dry, use_up ? &up : nullptr);
  int top = 0, top_marked = 0, below_marked = 0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    if (b.p.kind[i] == kWall) {
      EXPECT_FALSE(b.p.surface[i]);
      continue;
    }
    const bool is_top = b.p.x[i][1] > 0.09;
    top += is_top;
    if (is_top && !b.p.surface[i])
      std::printf("  unmarked top-row particle at x = %.3f dx\n", b.p.x[i][0] / b.p.spacing);
    if (is_top)
      top_marked += b.p.surface[i];
    else
      below_marked += b.p.surface[i];
  }
  std::printf("squeeze %.2f, jitter %.2f dx%s%s%s: top row %d/%d marked, %d below marked\n",
              squeeze, jitter, side_walls ? ", walls above the water" : "",
              hex_top ? ", staggered top layer" : "", use_up ? "" : ", n from grad W", top_marked,
              top, below_marked);
  EXPECT_EQ(top_marked, top);
  EXPECT_EQ(below_marked, 0);
}

TEST(FreeSurfaceScan, TopRowMarkedRowsBelowNot) { check(1.0, 0.0); }
TEST(FreeSurfaceScan, TopRowMarkedWithNormalFromKernelGradient) {
  check(1.0, 0.0, false, false, false);
}
TEST(FreeSurfaceScan, SqueezedTopRowStillMarked) { check(0.75, 0.0); }
TEST(FreeSurfaceScan, DisorderedInteriorNotMarked) { check(1.0, 0.15); }
// The circulation tank's break-up: a top row squeezed to 0.65 dx against a wall that rises above
// the water, where the wall tilts n away from it.
TEST(FreeSurfaceScan, SqueezedTopRowAtDryWallMarked) { check(0.65, 0.0, true); }
TEST(FreeSurfaceScan, DisorderedInteriorBetweenDryWallsNotMarked) { check(1.0, 0.15, true); }
// Marrone's 45-degree umbrella with h = 1.3 dx marked the lower row of this layer too; two p = 0
// rows 0.66 dx apart lifted it in the circulation tank.
TEST(FreeSurfaceScan, StaggeredTopLayerOnlyUpperRowMarked) { check(1.0, 0.0, false, true); }

// surface_depth: how far a free-surface particle sits below the line its surface neighbours
// outline. A particle of the second row exposed as surface under a level top row is one spacing
// down; a top-row particle lowered by 0.3 dx is 0.3 dx down; the level row itself reads 0 (a
// neighbour below it pulls the mean down, which is clamped), and unflagged particles read 0.
TEST(SurfaceDepth, ReadsTheDepthBelowTheSurfaceRow) {
  Block b = make_block(1.0, 0.0);
  const double dx = b.p.spacing, top = 9.5 * dx;
  int exposed = -1, lowered = -1;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    if (b.p.kind[i] == kWall) continue;
    const Vec<2>& x = b.p.x[i];
    if (std::abs(x[1] - top) < 1e-9) {
      b.p.surface[i] = 1;
      if (std::abs(x[0] - 15.5 * dx) < 1e-9) lowered = static_cast<int>(i);
    }
    if (std::abs(x[1] - (top - dx)) < 1e-9 && std::abs(x[0] - 5.5 * dx) < 1e-9) {
      b.p.surface[i] = 1;
      exposed = static_cast<int>(i);
    }
  }
  ASSERT_GE(exposed, 0);
  ASSERT_GE(lowered, 0);
  b.p.x[lowered][1] -= 0.3 * dx;
  Kernel<2> W(KernelType::WendlandC2, 1.3 * dx);
  Domain<2> dom;
  dom.lo = Vec<2>(0.0, -0.05);
  dom.hi = Vec<2>(0.2, 0.2);
  dom.periodic[0] = true;
  NeighborSearch<2> search(dom, W.support());
  const int64_t exposed_id = b.p.id[exposed], lowered_id = b.p.id[lowered];
  search.sort(b.p);  // the lowered particle moved: cells and pair geometry again
  search.build(b.p, W, b.nb);
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    if (b.p.id[i] == exposed_id) exposed = static_cast<int>(i);
    if (b.p.id[i] == lowered_id) lowered = static_cast<int>(i);
  }
  std::vector<double> depth;
  surface_depth(b.p, b.nb, Vec<2>(0.0, 1.0), depth);
  EXPECT_NEAR(depth[exposed], dx, 1e-12 * dx);
  EXPECT_NEAR(depth[lowered], 0.3 * dx, 1e-12 * dx);
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    if (static_cast<int>(i) == exposed || static_cast<int>(i) == lowered) continue;
    EXPECT_EQ(depth[i], 0.0) << "particle at " << b.p.x[i].transpose();
  }
  printf("exposed second-row particle: depth %.4f dx; lowered top-row particle: %.4f dx\n",
         depth[exposed] / dx, depth[lowered] / dx);
}

}  // namespace
}  // namespace isph
