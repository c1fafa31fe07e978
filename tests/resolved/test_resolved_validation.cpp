// Resolved coupling (PMS) against analytic expectations: Archimedes on a held clump (2D
// quasi-2D and 3D), a neutral clump that must stay put, a heavy one that sinks to a steady
// velocity, and a light box that floats at draft (rho_s / rho_f) H.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "resolved_support.hpp"

namespace isphdem::resolved_test {
namespace {

constexpr double kRho = 1000.0, kG = 9.81;

struct HeldResult {
  double force_error = 0, lateral = 0, torque = 0, raw_volume_ratio = 0;
};

// Holds the clump fixed in the 2D tank for `steps` fluid steps; returns the worst relative
// errors over the last half.
HeldResult held_clump_2d(bool dem_volume, int steps) {
  auto scene = tank<2>({});
  isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
  const double dx = solver.particles().spacing, r = 0.02, T = 0.03;
  // An L of three spheres: its centre of mass is off every lattice symmetry line, so a PMS
  // centroid that missed it would show as a torque.
  DemState dem =
      clump({Vec3{0.083, 0.081, 0}, Vec3{0.123, 0.081, 0}, Vec3{0.083, 0.121, 0}}, r, 2600.0);
  ResolvedSettings set;
  set.spacing = dx;
  set.fluid_density = kRho;
  set.slab_thickness = T;
  set.dem_volume = dem_volume;
  ResolvedCoupling<2> stage(set);
  stage.initialize(dem, solver);
  const double V = dem.bodies[0].volume, buoyancy = kRho * kG * V;
  HeldResult res;
  res.raw_volume_ratio = stage.bodies()[0].fluid_volume / V;
  for (int n = 0; n < steps; ++n) {
    stage.before_fluid_step(dem, solver);
    solver.step(5e-4);
    DemLoads loads;
    stage.after_fluid_step(dem, solver, 5e-4, loads);
    if (n < steps / 2) continue;
    const Vec3& f = loads.body_force[0];
    res.force_error = std::max(res.force_error, std::abs(f[1] - buoyancy) / buoyancy);
    res.lateral = std::max(res.lateral, std::abs(f[0]) / buoyancy);
    res.torque = std::max(res.torque, std::abs(loads.body_torque[0][2]) / (buoyancy * r));
  }
  return res;
}

TEST(ResolvedArchimedes, HeldClumpIn2DTankFeelsRhoGV) {
  const HeldResult w = held_clump_2d(true, 200);
  const HeldResult raw = held_clump_2d(false, 20);
  std::printf(
      "2D held clump, 200 steps: buoyancy error %.3e (DEM volume weighting), lateral force "
      "%.3e rho g V, torque %.3e rho g V r\n"
      "  without weighting (each particle dx^2 T): PMS volume / DEM volume = %.4f, buoyancy error "
      "%.3e\n",
      w.force_error, w.lateral, w.torque, raw.raw_volume_ratio, raw.force_error);
  EXPECT_LT(w.force_error, 0.02);
  EXPECT_LT(w.lateral, 0.005);
  EXPECT_LT(w.torque, 0.005);
  EXPECT_LT(raw.force_error, 0.02);  // the lattice matches V to half a particle (N ~ 130)
}

}  // namespace
}  // namespace isphdem::resolved_test
