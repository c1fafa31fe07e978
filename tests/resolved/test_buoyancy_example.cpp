// examples/buoyancy_clump through `isphdem run` as a user runs it (coupled driver, resolved
// stage, LIGGGHTS clump, /bodies output): the held clump's hydrodynamic force is its buoyancy
// rho_f g V with V the DEM volume written next to it, and the torque vanishes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../cli/cli_support.hpp"
#include "../output/h5_read.hpp"

namespace isphdem {
namespace {

TEST(BuoyancyClumpExample, HydrodynamicForceIsArchimedes) {
  const auto out = cli::scratch("buoyancy_clump");
  const auto r = cli::run(cli::example("buoyancy_clump") + " --out " + out.string() +
                          " --quiet --set time.end=0.1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const h5_read::File f((out / "snap_00001000.h5").string());
  const auto force = f.read("/bodies/force_hydro").f64;
  const auto torque = f.read("/bodies/torque_hydro").f64;
  const auto volume = f.read("/bodies/volume").f64;
  ASSERT_EQ(volume.size(), 1u);
  const double buoyancy = 1000.0 * 9.81 * volume[0];
  const double err = force[1] / buoyancy - 1.0;
  std::printf(
      "held clump at t = 0.1 s: F = (%.4e, %.6e) N, rho g V = %.6e N, error %.2e, "
      "torque %.2e N m\n",
      force[0], force[1], buoyancy, err, torque[2]);
  EXPECT_LT(std::abs(err), 0.02);                  // issue 6: within 2%
  EXPECT_LT(std::abs(force[0]), 1e-3 * buoyancy);  // no sideways force
  // torque small against buoyancy x the clump's radius (2.5 mm)
  EXPECT_LT(std::abs(torque[2]), 1e-3 * buoyancy * 2.5e-3);
}

}  // namespace
}  // namespace isphdem
