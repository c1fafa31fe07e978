// Steady flow past a fixed circular cylinder at Re = 20 (examples/cylinder_re20_2d): the drag
// coefficient of the PMS-resolved cylinder against Dennis & Chang (1970), C_d = 2.05 in an
// unbounded stream, and against the same configuration solved independently.
//
// The example is not unbounded: it is periodic across the stream (image cylinders W apart), and
// the forcing zone that re-sets the wake imposes a uniform stream 13 D ahead of the cylinder.
// scripts/cylinder_lbm_reference.py solves exactly that configuration with a lattice-Boltzmann
// method that shares no code with isphdem; its C_d (kCdSameConfiguration) is what the blockage
// and the inlet make of 2.05, and the SPH discretisation is measured against it.
//
// The cylinder is one sphere held fixed (a clump built as LIGGGHTS reports it), resolved by
// lattice PMS particles; the slab thickness T = 4R/3 makes the sphere's volume V = pi R^2 T, so
// the PMS disc has the cylinder's cross-section. C_d = F_x / (T rho U^2 D / 2).
//
// The default suite runs case.toml (W = 20 D) at D/dx = 6 to t U/D = 25 (4 min). CYLINDER_FULL
// runs the wide domain of the issue, wide.toml (W = 40 D), at D/dx = 10 to t U/D = 20 (about
// 90 min, labelled slow).
//
// Cylinder.DragConvergesInTimeStep (issue 46: the coupled step converges in dt): case.toml at
// D/dx = 5 (the README's quick command, dt = 0.1 dx/U = 0.01 s) and at smaller fluid steps; the
// spread of C_d (max - min over the mean) must stay within 1%. CYLINDER_FULL runs three steps,
// 0.1, 0.05 and 0.025 dx/U, to t U/D = 30 (slow); the default suite two, 0.1 and 0.05 dx/U, to
// t U/D = 12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "resolved/resolved_coupling.hpp"
#include "resolved_support.hpp"
#include "run/case_keys.hpp"
#include "run/coupling_stages.hpp"
#include "run/fluid_run.hpp"

namespace isphdem::validation {
namespace {

#ifdef CYLINDER_FULL
constexpr const char* kCase = "wide.toml";
constexpr double kDOverDx = 10.0, kEndOverDU = 20.0;
// cylinder_lbm_reference.py --d 16 --width 40: mean over t U/D = 15-30.
constexpr double kCdSameConfiguration = 2.146;
#else
constexpr const char* kCase = "case.toml";
constexpr double kDOverDx = 6.0, kEndOverDU = 25.0;
// cylinder_lbm_reference.py --d 24 --width 20 (2.178 at --d 16): mean over t U/D = 15-30.
constexpr double kCdSameConfiguration = 2.172;
#endif
constexpr double kCdDennisChang = 2.05;
// The 10% against the unbounded value includes the blockage (+5-6% by the reference);
// against the configuration itself the SPH discretisation is allowed 5%.
constexpr double kToleranceUnbounded = 0.10, kToleranceSameConfiguration = 0.05;

struct DragResult {
  double cd = 0.0, cd_drift = 0.0, lift = 0.0;
  double blockage = 0.0;  // D / W, W the period across the stream
};

// One run of the example: its case file, D/dx, the end and the averaging window (in D/U), and
// the fluid step dt U / dx.
struct CylinderRun {
  const char* case_name = kCase;
  double d_over_dx = kDOverDx, end_over_du = kEndOverDU, window_over_du = 4.0;
  double dt_u_over_dx = 0.1;  // the example's dt (0.005 s at D/dx = 10) scaled with dx
};

DragResult cylinder_drag(const CylinderRun& run = {}) {
  // The example's geometry with the spacing set for D / dx.
  const double D = 0.01, R = 0.5 * D, dx = D / run.d_over_dx;
  char spacing[64];
  std::snprintf(spacing, sizeof spacing, "particles.spacing=%.17g", dx);
  const std::string dir = std::string(ISPHDEM_SOURCE_DIR) + "/examples/cylinder_re20_2d/";
  const CaseFile c = CaseFile::load(dir + run.case_name, {spacing}, case_keys());
  const auto scene = build_fluid_scene<2>(c);
  isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
  const double U = scene.config.forcing.at(0).velocity.norm(), rho = scene.config.density;
  std::printf("D/dx = %.0f, %zu particles, Re = %.2f\n", run.d_over_dx, solver.particles().size(),
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

  // At 0.2 dx / U C_d comes out 2.3% higher than at 0.1 (D/dx = 5; docs/resolved.md, "Time
  // step").
  const double dt = run.dt_u_over_dx * dx / U, end = run.end_over_du * D / U;
  std::printf("dt = %.6g s (%.3g dx/U), %.0f D/U\n", dt, run.dt_u_over_dx, run.end_over_du);
  const int steps = static_cast<int>(std::lround(end / dt));
  std::vector<double> cd(steps), cl(steps);
  std::printf("  t U/D    C_d     C_l    PPE it\n");
  for (int n = 0; n < steps; ++n) {
    stage.move_particles(dem, solver);
    const auto st = solver.step(dt);
    DemLoads loads;
    stage.after_fluid_step(dem, solver, dt, loads);
    cd[n] = loads.body_force[0][0] / q;
    cl[n] = loads.body_force[0][1] / q;
    if ((n + 1) % (steps / 20) == 0)
      std::printf("  %5.1f  %6.3f  %6.3f  %d\n", solver.time() * U / D, cd[n], cl[n],
                  st.ppe_iterations);
  }
  // Mean over the last window (4 D/U), and its change from the window before (still settling?).
  const int w = static_cast<int>(std::lround(run.window_over_du * D / U / dt));
  auto mean = [&](const std::vector<double>& f, int from, int to) {
    double s = 0;
    for (int k = from; k < to; ++k) s += f[k];
    return s / (to - from);
  };
  DragResult r;
  r.blockage = D / scene.domain.length()[1];
  r.cd = mean(cd, steps - w, steps);
  r.cd_drift = r.cd - mean(cd, steps - 2 * w, steps - w);
  r.lift = mean(cl, steps - w, steps);
  return r;
}

TEST(Cylinder, DragAtRe20AgainstDennisChang) {
  const DragResult r = cylinder_drag();
  std::printf(
      "C_d = %.4f (mean over the last 4 D/U; change from the 4 D/U before %+.4f), C_l = %+.4f;\n"
      "against Dennis & Chang 2.05 (unbounded): %+.2f%% (blockage D/W = %.1f%% and the inlet 13 D "
      "ahead included; allowed %.0f%%)\n"
      "against the same configuration by lattice Boltzmann %.3f: %+.2f%% (allowed %.0f%%)\n",
      r.cd, r.cd_drift, r.lift, 100 * (r.cd - kCdDennisChang) / kCdDennisChang, 100 * r.blockage,
      100 * kToleranceUnbounded, kCdSameConfiguration,
      100 * (r.cd - kCdSameConfiguration) / kCdSameConfiguration,
      100 * kToleranceSameConfiguration);
  EXPECT_NEAR(r.cd, kCdDennisChang, kToleranceUnbounded * kCdDennisChang);
  EXPECT_NEAR(r.cd, kCdSameConfiguration, kToleranceSameConfiguration * kCdSameConfiguration);
  EXPECT_LT(std::abs(r.cd_drift), 0.01 * r.cd);  // steady
  EXPECT_LT(std::abs(r.lift), 0.05);             // symmetric wake
}

// Issue 46: C_d of the held cylinder at D/dx = 5 (case.toml, the README's quick command) at the
// case's fluid step 0.1 dx/U (0.01 s) and below. CYLINDER_FULL: three steps, to t U/D = 30, C_d
// the mean over t U/D = 22-30, where it is steady. The default suite: two steps to t U/D = 12,
// C_d over t U/D = 8-12, while it still drifts down by about 1% per 4 D/U: halving the step
// must not move that part of the approach either.
#ifdef CYLINDER_FULL
constexpr double kStepEndOverDU = 30.0, kStepWindowOverDU = 8.0;
const std::vector<double> kSteps{0.1, 0.05, 0.025};
#else
constexpr double kStepEndOverDU = 12.0, kStepWindowOverDU = 4.0;
const std::vector<double> kSteps{0.1, 0.05};
#endif
constexpr double kStepSpread = 0.01;

TEST(Cylinder, DragConvergesInTimeStep) {
  std::vector<double> cd;
  for (const double step : kSteps) {
    const DragResult r = cylinder_drag({"case.toml", 5.0, kStepEndOverDU, kStepWindowOverDU, step});
    std::printf("dt = %.3g dx/U: C_d = %.4f (change from the %.0f D/U before %+.4f)\n", step, r.cd,
                kStepWindowOverDU, r.cd_drift);
    cd.push_back(r.cd);
  }
  const auto [lo, hi] = std::minmax_element(cd.begin(), cd.end());
  double mean = 0;
  for (const double v : cd) mean += v / cd.size();
  const double spread = (*hi - *lo) / mean;
  std::printf("D/dx = 5, C_d over t U/D = %.0f-%.0f:", kStepEndOverDU - kStepWindowOverDU,
              kStepEndOverDU);
  for (std::size_t k = 0; k < cd.size(); ++k) std::printf(" %.4f (%.3g dx/U)", cd[k], kSteps[k]);
  std::printf("; spread (max - min) / mean = %.2f%% (allowed %.0f%%)\n", 100 * spread,
              100 * kStepSpread);
  EXPECT_LT(spread, kStepSpread);
}

}  // namespace
}  // namespace isphdem::validation
