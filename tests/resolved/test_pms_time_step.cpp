// The held PMS array's permeability does not depend on the fluid time step (issue 46): steady
// Stokes flow through a periodic square array of cylinders, driven by a body force, at two solid
// fractions and at time steps from the viscous limit 0.125 dx^2/nu down by 16x. The drag per
// cylinder F/(mu U) is compared across the steps and with Sangani & Acrivos (1982),
//   F/(mu U) = 4 pi / (-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.039 c^3).
// With the PMS rows projected as fluid (solver.pms_projection = "fluid") the body leaked by
// dt (g - grad p/rho) a step and the array carried 5.6% more flow at the viscous step than at
// 1/16 of it; with the pressure increment the spread is 1%. The remaining -11% against the
// reference at c = 0.4 (gaps of 4 dx) is the resolution's (issue 49), not the step's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "resolved_support.hpp"

namespace isphdem::resolved_test {
namespace {

struct ArrayResult {
  double U = 0, F = 0, c = 0, ratio = 0, exact = 0;
};

ArrayResult cylinder_array(double L, double dx, double a, double nu, double g, double dt,
                           double t_end, const std::vector<std::string>& extra = {}) {
  constexpr int Dim = 2;
  const double rho = 1000.0, mu = rho * nu;
  std::vector<std::string> o = periodic_box_2d(L, L, dx, nu, g);
  for (const auto& e : extra) o.push_back(e);
  auto scene = example_scene<Dim>("taylor_green_2d", o);
  isph::IsphSolver<Dim> solver(scene.config, scene.domain, scene.particles);
  const double c0 = dx * std::floor(0.5 * L / dx) + 0.5 * dx;
  DemState dem = clump({Vec3{c0, c0, 0.0}}, a, 1e9);
  const ResolvedSettings set = held_body_settings(dx, rho, a);
  ResolvedCoupling<Dim> stage(set);
  stage.initialize(dem, solver);
  const int steps = static_cast<int>(std::lround(t_end / dt));
  const auto& P = solver.particles();
  const int window = std::max(1, steps / 10);
  double f = 0, u = 0;
  for (int n = 0; n < steps; ++n) {
    stage.move_particles(dem, solver);
    solver.step(dt);
    DemLoads loads;
    stage.after_fluid_step(dem, solver, dt, loads);
    if (n < steps - window) continue;
    f += loads.body_force[0][0] / set.slab_thickness / window;
    double m = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == isph::kFluid) m += P.volume * P.v[i][0];
    u += m / (L * L) / window;
  }
  ArrayResult r;
  r.U = u;
  r.F = f;
  r.c = stage.bodies()[0].fluid_volume / set.slab_thickness / (L * L);
  r.ratio = f / (mu * u);
  const double c = r.c;
  r.exact = 4 * M_PI / (-0.5 * std::log(c) - 0.738 + c - 0.887 * c * c + 2.039 * c * c * c);
  return r;
}

// Drag per cylinder F/(mu U) at dt0, dt0/4 and dt0/16 (dt0 the viscous limit; the first `steps` of
// them), and the exact one.
struct StepSweep {
  std::vector<double> ratio;
  double exact = 0, c = 0;
  double spread() const {  // largest deviation from the smallest step's value
    double s = 0;
    for (double r : ratio) s = std::max(s, std::abs(r / ratio.back() - 1));
    return s;
  }
};

StepSweep sweep(double L, double a, const std::string& projection, int steps = 3,
                const std::string& ghosts = "linear") {
  const double dx = 0.001, nu = 1e-3, g = 2e-3;
  const double dt0 = 0.125 * dx * dx / nu;
  StepSweep s;
  for (double f : {1.0, 0.25, 0.0625}) {
    if (steps-- == 0) break;
    // 0.05 s: ten of the array's viscous time constants L^2/(4 pi^2 nu) at L = 14 mm, and the
    // drag steady to 0.1% (0.1 s gives the same ratios to 0.2%).
    const ArrayResult r = cylinder_array(
        L, dx, a, nu, g, dt0 * f, 0.05,
        {"solver.pms_projection=\"" + projection + "\"", "solver.wall_ghosts=\"" + ghosts + "\""});
    s.ratio.push_back(r.ratio);
    s.exact = r.exact;
    s.c = r.c;
    std::printf("%s: c %.4f, dt %.4e s: U %.4e m/s, F/(mu U) %.3f, exact %.3f (%+.2f%%)\n",
                projection.c_str(), r.c, dt0 * f, r.U, r.ratio, r.exact,
                100 * (r.ratio / r.exact - 1));
  }
  std::printf("%s: c %.4f: spread over the steps %.2f%%\n", projection.c_str(), s.c,
              100 * s.spread());
  return s;
}

TEST(PmsTimeStep, DenseArrayPermeabilityHoldsFromTheViscousLimitDown16x) {
  const StepSweep s = sweep(0.014, 0.005, "increment");  // c = 0.40, gaps of 4 dx
  EXPECT_LT(s.spread(), 0.015);
  for (double r : s.ratio) EXPECT_NEAR(r, s.exact, 0.15 * s.exact);
}

TEST(PmsTimeStep, DiluteArrayPermeabilityHoldsFromTheViscousLimitDown16x) {
  const StepSweep s = sweep(0.020, 0.005, "increment");  // c = 0.20, gaps of 10 dx
  EXPECT_LT(s.spread(), 0.015);
  for (double r : s.ratio) EXPECT_NEAR(r, s.exact, 0.15 * s.exact);
}

// With the no-slip ghosts fitted as a parabola along the normal (solver.wall_ghosts =
// "quadratic", issue 49) the flow in the 4-spacing gaps loses the slip of the linear ghosts:
// -6.4% against Sangani & Acrivos where the linear ghosts give -11.4%, as steady across the steps.
TEST(PmsTimeStep, DenseArrayWithQuadraticGhostsHoldsAcrossStepsAndSlipsLess) {
  const StepSweep s = sweep(0.014, 0.005, "increment", 3, "quadratic");
  EXPECT_LT(s.spread(), 0.015);
  for (double r : s.ratio) EXPECT_NEAR(r, s.exact, 0.08 * s.exact);
}

// The cause, kept measurable: projected as fluid, the body's rows leak by dt (g - grad p/rho).
TEST(PmsTimeStep, BodyProjectedAsFluidLeaksInProportionToTheStep) {
  const StepSweep s = sweep(0.014, 0.005, "fluid", 2);  // dt0 and dt0/4
  EXPECT_GT(s.spread(), 0.04);
  EXPECT_LT(s.ratio[0], s.ratio[1]);  // more flow (less drag per U) at the larger step
}

}  // namespace
}  // namespace isphdem::resolved_test
