// Remeshing the top rows of a nearly flat free surface (sph/surface_remesh.hpp): the highest
// rows x columns fluid particles go onto the surface's lattice at their mean height, and take
// the fluid's interpolated values; every other particle is left as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "kernel.hpp"
#include "surface_remesh.hpp"

namespace isph {
namespace {

constexpr double kDx = 0.01;
constexpr int kColumns = 20, kRows = 10;

// A water block of 20 columns and 10 rows on a wall floor; the top three rows disordered as a
// stagnation flow leaves them (the top row stretched sideways by up to 0.3 dx, rows shifted up and
// down by up to 0.3 dx), all moving at one velocity.
Particles<2> make_block(const Vec<2>& v) {
  Particles<2> p;
  p.spacing = kDx;
  p.volume = kDx * kDx;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int j = -3; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      Vec<2> x((i + 0.5) * kDx, (j + 0.5) * kDx);
      if (j >= kRows - 3) x += Vec<2>(u(rng), u(rng)) * kDx;
      p.add(x, j < 0 ? Vec<2>::Zero() : v, j < 0 ? kWall : kFluid);
    }
  return p;
}

TEST(SurfaceRemesh, ColumnsAreTheTopRowsLattice) {
  Particles<2> p;
  p.spacing = kDx;
  p.volume = kDx * kDx;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < kColumns; ++i)
      p.add(Vec<2>((i + 0.5) * kDx, (j + 0.5) * kDx), Vec<2>::Zero(), kFluid);
  const auto c = surface_columns(p, Vec<2>(0.0, 1.0));
  ASSERT_EQ(c.size(), static_cast<std::size_t>(kColumns));
  for (const auto& x : c) EXPECT_NEAR(std::remainder(x[0] / kDx - 0.5, 1.0), 0.0, 1e-12);
}

TEST(SurfaceRemesh, TopRowsGoOntoTheLatticeAtTheirMeanHeight) {
  const Vec<2> v(0.004, -0.002);
  Particles<2> p = make_block(v);
  std::vector<Vec<2>> columns;
  for (int i = 0; i < kColumns; ++i) columns.emplace_back((i + 0.5) * kDx, 0.0);
  const Particles<2> before = p;
  // The 4 x 20 highest fluid particles and their mean height.
  std::vector<double> h;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == kFluid) h.push_back(p.x[i][1]);
  std::sort(h.rbegin(), h.rend());
  const int zone = 4 * kColumns;
  double mean = 0.0;
  for (int k = 0; k < zone; ++k) mean += h[k] / zone;
  const double cut = h[zone - 1];

  const Kernel<2> W(KernelType::WendlandC2, 1.3 * kDx);
  const double top = remesh_surface_rows(p, W, Vec<2>(0.0, 1.0), columns, 4);
  EXPECT_NEAR(top - 1.5 * kDx, mean, 1e-12);

  ASSERT_EQ(p.size(), before.size());
  std::map<std::pair<int, int>, int> sites;  // (column, row) -> count
  int moved = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (before.kind[i] != kFluid || before.x[i][1] < cut) {
      EXPECT_EQ(p.x[i], before.x[i]) << "particle " << i << " is not in the zone";
      EXPECT_EQ(p.v[i], before.v[i]);
      continue;
    }
    ++moved;
    const double col = p.x[i][0] / kDx - 0.5, row = (top - p.x[i][1]) / kDx;
    EXPECT_NEAR(col, std::round(col), 1e-9);
    EXPECT_NEAR(row, std::round(row), 1e-9);
    ++sites[{static_cast<int>(std::lround(col)), static_cast<int>(std::lround(row))}];
    EXPECT_NEAR((p.v[i] - v).norm(), 0.0, 1e-15) << "a uniform flow is interpolated exactly";
  }
  EXPECT_EQ(moved, zone);
  EXPECT_EQ(sites.size(), static_cast<std::size_t>(zone)) << "one particle per site";
}

}  // namespace
}  // namespace isph
