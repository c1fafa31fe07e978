// MeanFlowDrive with a fixed bed, without LIGGGHTS: a column periodic in x and y driven upward
// at a mean Darcy velocity U through a bed of frozen grains (porosity 0.4) in its middle. The
// drive is a uniform body force g_d on the fluid standing for a mean pressure gradient -rho g_d;
// in steady state nothing but the grains holds the column, so the loads handed to the grains
// must add up to rho g_d times the whole column's volume (fluid and grains). Without the
// drive's share on the grains (rho g_d V per grain) the sum falls short by (1 - n) L / H of it
// (26% here): the periodic pressure carries only the rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "isph_solver.hpp"
#include "periodic_column.hpp"
#include "unresolved/drag_law.hpp"
#include "unresolved/mean_flow_drive.hpp"
#include "unresolved/unresolved_coupling.hpp"

namespace isphdem {
namespace {

using column::kBedHi;
using column::kBedLo;
using column::kDx;
using column::kHeight;
using column::kWidth;

TEST(MeanFlowDrive, GrainsOfAFixedBedCarryTheWholeDrive) {
  const double U = 0.02, rho = column::kRho, dt = 1e-4;
  isph::Vec<2> gravity{0.0, 0.0};
  auto solver = column::make_solver(U, 0.0);

  // Square lattice of 1 mm grains at 1 mm (8 across), slab T such that
  // eps = 1 - (pi/6) d^3 / (s^2 T) = 0.4; their velocities stay zero (a fixed bed).
  const double d = 1e-3, T = M_PI / 6 * d * d * d / (0.6 * kDx * kDx);
  DemState dem;
  for (int iy = 0; kBedLo + (iy + 0.5) * kDx < kBedHi; ++iy)
    for (int ix = 0; (ix + 0.5) * kDx < kWidth; ++ix) {
      DemAtom a;
      a.tag = static_cast<int>(dem.atoms.size()) + 1;
      a.x = {(ix + 0.5) * kDx, kBedLo + (iy + 0.5) * kDx, 0.5 * T};
      a.radius = 0.5 * d;
      dem.atoms.push_back(a);
    }
  UnresolvedSettings s;
  s.map.smoothing_length = 2.0 * kDx;
  s.map.slab_thickness = T;
  UnresolvedCoupling<2> bed(s, std::make_shared<SeedResistance>(SeedResistanceParameters{}));
  MeanFlowDrive<2> drive({0.0, U}, gravity, dt, rho);
  bed.initialize(dem, solver);
  drive.initialize(dem, solver);

  const double grain_volume = M_PI / 6 * d * d * d;
  const double solids = grain_volume * static_cast<double>(dem.atoms.size());
  double handed = 0.0, without_drive = 0.0, mean_v = 0.0;
  std::printf("  t [s]   mean v_D [m/s]  g_d [m/s2]  sum of grain loads / (rho g_d H W T)\n");
  for (int step = 1; step <= 1500; ++step) {
    bed.before_fluid_step(dem, solver);
    drive.before_fluid_step(dem, solver);
    solver.step(dt);
    DemLoads loads;
    bed.after_fluid_step(dem, solver, dt, loads);
    without_drive = 0.0;
    for (const auto& f : loads.atom_force) without_drive += f[1];
    drive.after_fluid_step(dem, solver, dt, loads);
    handed = 0.0;
    for (const auto& f : loads.atom_force) handed += f[1];
    // The drive's share is exactly rho g_d V on every grain.
    const double share = rho * drive.drive()[1] * solids;
    ASSERT_NEAR(handed - without_drive, share, 1e-12 * (std::abs(without_drive) + std::abs(share)));
    if (step % 300 == 0) {
      mean_v = 0.0;
      for (const auto& v : solver.particles().v) mean_v += v[1];
      mean_v /= static_cast<double>(solver.particles().size());
      std::printf("  %.3f   %.5f         %.4f      %.4f\n", solver.time(), mean_v, drive.drive()[1],
                  handed / (rho * drive.drive()[1] * kHeight * kWidth * T));
    }
  }
  const double column = rho * drive.drive()[1] * kHeight * kWidth * T;
  const double n = 0.4, L = kBedHi - kBedLo;
  // Ergun's seepage force on a sharp bed, rho g i L W T, for scale only: the mapped porosity has
  // smoothed edges (2 dx) whose resistance is less than the step's (-7% here); the core gradient
  // is checked against Ergun in test_porous_bed.
  const SeedResistance law{SeedResistanceParameters{}};
  const double ergun = rho * (law.a_star(n) * U + law.b_star(n) * U * U) * L * kWidth * T;
  std::printf(
      "sum of grain loads %.4e N = %.4f x rho g_d H W T (%.4f without the drive's share, "
      "1 - (1 - n) L / H = %.4f); Ergun's seepage force %.4e N: error %+.2f%%\n",
      handed, handed / column, without_drive / column, 1 - (1 - n) * L / kHeight, ergun,
      100 * (handed / ergun - 1));
  EXPECT_NEAR(mean_v, U, 0.01 * U);
  EXPECT_NEAR(handed / column, 1.0, 0.02);
}

}  // namespace
}  // namespace isphdem
