// Steady flow past a fixed circular cylinder at Re = 20 (examples/cylinder_re20_2d): the drag
// coefficient of the PMS-resolved cylinder against Dennis & Chang (1970), C_d = 2.05 in an
// unbounded stream. The example is periodic across the stream with W = 20 D, a blockage D/W of
// 5%, which raises C_d by a few percent over the unbounded value (docs/resolved.md).
//
// The cylinder is one sphere held fixed (a clump built as LIGGGHTS reports it), resolved by
// lattice PMS particles; the slab thickness T = 4R/3 makes the sphere's volume V = pi R^2 T, so
// the PMS disc has the cylinder's cross-section. C_d = F_x / (T rho U^2 D / 2).
//
// The cylinder sits 13 D downstream of the forcing zone's edge: at 8 D (before) the zone, which
// imposes a uniform stream, acted as an inlet too close and C_d read 6% higher (2.378 against
// 2.232 at D/dx = 6); 18 D with a 60 D period gave 2.210 (docs/resolved.md).
//
// CYLINDER_FULL runs the example as shipped (D/dx = 10, 30 D x 20 D, t U/D = 30) against the
// issue's 10%: not met (C_d = 2.279, +11.2%), so it is labelled work_in_progress and slow. The
// default suite runs D/dx = 6 in the same domain (in units of D) to t U/D = 25 and allows 15%
// at that coarse resolution (measured +8.5%; +8.9% before the net-source removal).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case_keys.hpp"
#include "case_path.hpp"
#include "fluid_run.hpp"
#include "resolved_coupling.hpp"
#include "resolved_support.hpp"
#include "unresolved_case.hpp"

namespace isphdem::validation {
namespace {

#ifdef CYLINDER_FULL
constexpr double kDOverDx = 10.0, kEndOverDU = 30.0, kTolerance = 0.10;
#else
constexpr double kDOverDx = 6.0, kEndOverDU = 25.0, kTolerance = 0.15;
#endif
constexpr double kCdDennisChang = 2.05;

struct DragResult {
  double cd = 0.0, cd_drift = 0.0, lift = 0.0;
};

DragResult cylinder_drag() {
  // The example's geometry with the spacing set for D / dx.
  const double D = 0.01, R = 0.5 * D, dx = D / kDOverDx;
  char spacing[64];
  std::snprintf(spacing, sizeof spacing, "particles.spacing=%.17g", dx);
  const CaseFile c = CaseFile::load(example("cylinder_re20_2d"), {spacing}, case_keys());
  const auto scene = build_fluid_scene<2>(c);
  isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
  const double U = scene.config.forcing.at(0).velocity.norm(), rho = scene.config.density;
  std::printf("D/dx = %.0f, %zu particles, Re = %.2f\n", kDOverDx, solver.particles().size(),
              U * D / scene.config.viscosity);

  // The example's sphere, held by inertia as in its in.liggghts (density 1e9 kg/m3).
  const DemState dem = resolved_test::clump({Vec3{0.15, 0.1, 0.0}}, R, 1e9);

  // The stage the example's [coupling] table gives (resolved, lattice PMS, pms_volume =
  // "particles", T = 4R/3 so that V = pi R^2 T and the PMS disc is the cylinder's section).
  auto stages = make_coupling_stages<2>(c, scene, 0.0);
  auto& stage = dynamic_cast<ResolvedCoupling<2>&>(*stages.at(0));
  stage.initialize(dem, solver);
  const double T = stage.bodies()[0].scale, q = 0.5 * rho * U * U * D * T;
  std::printf("cylinder: %zu PMS particles (pi R^2 / dx^2 = %.1f)\n", stage.bodies()[0].particles,
              M_PI * R * R / (dx * dx));

  // The example's dt (0.005 s at D/dx = 10) scaled with dx. At 0.2 dx / U C_d comes out 6%
  // higher (a splitting error of order dt, docs/resolved.md).
  const double dt = 0.1 * dx / U, end = kEndOverDU * D / U;
  const int steps = static_cast<int>(std::lround(end / dt));
  std::vector<double> cd(steps), cl(steps);
  std::printf("  t U/D    C_d     C_l    PPE it\n");
  for (int n = 0; n < steps; ++n) {
    stage.before_fluid_step(dem, solver);
    const auto st = solver.step(dt);
    DemLoads loads;
    stage.after_fluid_step(dem, solver, dt, loads);
    cd[n] = loads.body_force[0][0] / q;
    cl[n] = loads.body_force[0][1] / q;
    if ((n + 1) % (steps / 20) == 0)
      std::printf("  %5.1f  %6.3f  %6.3f  %d\n", solver.time() * U / D, cd[n], cl[n],
                  st.ppe_iterations);
  }
  // Mean over the last 4 D/U, and its change from the 4 D/U before (still settling?).
  const int w = static_cast<int>(std::lround(4.0 * D / U / dt));
  auto mean = [&](const std::vector<double>& f, int from, int to) {
    double s = 0;
    for (int k = from; k < to; ++k) s += f[k];
    return s / (to - from);
  };
  DragResult r;
  r.cd = mean(cd, steps - w, steps);
  r.cd_drift = r.cd - mean(cd, steps - 2 * w, steps - w);
  r.lift = mean(cl, steps - w, steps);
  return r;
}

TEST(Cylinder, DragAtRe20AgainstDennisChang) {
  const DragResult r = cylinder_drag();
  std::printf(
      "C_d = %.4f (mean over the last 4 D/U; change from the 4 D/U before %+.4f), C_l = %+.4f;\n"
      "Dennis & Chang 2.05: error %+.2f%% (blockage D/W = 5%% included; allowed %.0f%% at D/dx = "
      "%.0f)\n",
      r.cd, r.cd_drift, r.lift, 100 * (r.cd - kCdDennisChang) / kCdDennisChang, 100 * kTolerance,
      kDOverDx);
  EXPECT_NEAR(r.cd, kCdDennisChang, kTolerance * kCdDennisChang);
  EXPECT_LT(std::abs(r.cd_drift), 0.01 * r.cd);  // steady
  EXPECT_LT(std::abs(r.lift), 0.05);             // symmetric wake
}

}  // namespace
}  // namespace isphdem::validation
