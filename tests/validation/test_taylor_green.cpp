// Taylor-Green vortex, Re = 100: the velocity amplitude follows exp(-8 pi^2 t / Re) within 2% up
// to t = 1, and the error falls with resolution (the observed order is printed).
#include <gtest/gtest.h>

#include <cmath>

#include "case_path.hpp"
#include "run/fluid_run.hpp"
#include "taylor_green_amplitude.hpp"

namespace isphdem::validation {
namespace {

struct TaylorGreenResult {
  double max_error;  // max over sampled times of |A - A_exact| / A_exact
  double final_amplitude;
  long steps;
};

TaylorGreenResult run_taylor_green(double dx, double t_end, bool shifting = true) {
  const CaseFile c = load_example(
      "taylor_green_2d", {"particles.spacing=" + std::to_string(dx),
                          std::string("solver.shifting=") + (shifting ? "true" : "false")});
  FluidRun<2> run(build_fluid_scene<2>(c), parse_run_settings(c));
  const double Re = 1.0 / c.number("fluid.viscosity");
  TaylorGreenResult r{0.0, 0.0, 0};
  std::printf("dx = %g (%zu particles)\n     t     A(t)     exact    rel.err\n", dx,
              run.solver().particles().size());
  for (int k = 1; k <= 10; ++k) {
    const double t = t_end * k / 10.0;
    run.run_until(t);
    const double tt = run.solver().time();
    const double a = taylor_green_amplitude(run.solver().particles(), 1.0);
    const double exact = std::exp(-8.0 * M_PI * M_PI * tt / Re);
    const double err = std::abs(a - exact) / exact;
    r.max_error = std::max(r.max_error, err);
    r.final_amplitude = a;
    std::printf("  %5.3f  %.5f  %.5f  %.2e\n", tt, a, exact, err);
  }
  r.steps = run.solver().steps();
  return r;
}

TEST(TaylorGreen, AmplitudeDecayWithinTwoPercentAndConverges) {
  const TaylorGreenResult coarse = run_taylor_green(1.0 / 25, 1.0);
  const TaylorGreenResult fine = run_taylor_green(1.0 / 50, 1.0);
  std::printf(
      "max relative amplitude error to t = 1: dx=1/25 %.3e, dx=1/50 %.3e; observed order %.2f\n",
      coarse.max_error, fine.max_error, std::log2(coarse.max_error / fine.max_error));
  EXPECT_LT(fine.max_error, 0.02);
  EXPECT_LT(fine.max_error, coarse.max_error);
  EXPECT_NEAR(fine.final_amplitude, 0.454, 0.02 * 0.454);
}

// Shifting matters: without it the particle distribution degrades at the hyperbolic points of
// the vortex and the decay goes wrong (dx = 0.04: amplitude error up to 6.85% by t = 1, against
// 1.12% with shifting). Whether the unshifted run also breaks down is chaotic: it stopped before
// t = 0.5 while the pinned pressure row took the whole excess of the equation as a point
// source, and at t = 1.1, 1.6 or not before 3 since that excess is spread.
TEST(TaylorGreen, ShiftingKeepsTheDecayAccurate) {
  TaylorGreenResult r[2];
  bool broke_down[2] = {false, false};
  for (int shifting = 0; shifting < 2; ++shifting) {
    try {
      r[shifting] = run_taylor_green(0.04, 1.0, shifting == 1);
    } catch (const isph::SimulationError& e) {
      std::printf("without shifting: %s\n", e.what());
      r[shifting].max_error = 1.0;  // a run that breaks down is as wrong as it gets
      broke_down[shifting] = true;
    }
  }
  std::printf("max amplitude error to t = 1 at dx = 0.04: %.2f%% without shifting%s, %.2f%% with\n",
              100 * r[0].max_error, broke_down[0] ? " (broke down)" : "", 100 * r[1].max_error);
  EXPECT_LT(r[1].max_error, 0.02);
  EXPECT_GT(r[0].max_error, 3.0 * r[1].max_error);
}

}  // namespace
}  // namespace isphdem::validation
