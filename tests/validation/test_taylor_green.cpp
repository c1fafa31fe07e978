// Taylor-Green vortex, Re = 100: the velocity amplitude follows exp(-8 pi^2 t / Re) within 2% up
// to t = 1, and the error falls with resolution (the observed order is printed).
#include <gtest/gtest.h>

#include <cmath>

#include "case_path.hpp"
#include "fluid_run.hpp"
#include "taylor_green_amplitude.hpp"

namespace isphdem::validation {
namespace {

struct TaylorGreenResult {
  double max_error;  // max over sampled times of |A - A_exact| / A_exact
  double final_amplitude;
  long steps;
};

TaylorGreenResult run_taylor_green(double dx, double t_end) {
  const CaseFile c = load_example("taylor_green_2d", {"particles.spacing=" + std::to_string(dx)});
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

double min_pair_distance(const isph::IsphSolver<2>& s) {
  const auto& nb = s.neighbors();
  double m = 1e300;
  for (double r : nb.r) m = std::min(m, r);
  return m / s.particles().spacing;
}

// Shifting matters: without it the particle distribution degrades at the hyperbolic points of
// the vortex and the run breaks down (t = 1.1-1.6 s at dx = 0.04; before the pinned pressure row's
// excess was spread, already before t = 0.5); with it the run goes on to t = 3 (its accuracy is
// asserted above). The closest pair is printed for information only: shifting does not keep it
// larger (0.31 dx with, 0.43 dx without at t = 0.15), it keeps the distribution usable.
TEST(TaylorGreen, ShiftingKeepsTheRunAlive) {
  double gap[2] = {0, 0};
  double reached[2] = {0, 0};
  for (int shifting = 0; shifting < 2; ++shifting) {
    const CaseFile c = load_example(
        "taylor_green_2d", {"particles.spacing=0.04",
                            std::string("solver.shifting=") + (shifting ? "true" : "false")});
    FluidRun<2> run(build_fluid_scene<2>(c), parse_run_settings(c));
    run.run_until(0.15);
    gap[shifting] = min_pair_distance(run.solver());
    try {
      run.run_until(3.0);
    } catch (const isph::SimulationError& e) {
      std::printf("without shifting: %s\n", e.what());
    }
    reached[shifting] = run.solver().time();
  }
  std::printf(
      "closest pair at t = 0.15: %.3f dx without shifting, %.3f dx with; run reached t = %.3f "
      "without, %.3f with\n",
      gap[0], gap[1], reached[0], reached[1]);
  EXPECT_LT(reached[0], 2.5);
  EXPECT_GE(reached[1], 3.0 - 1e-9);
}

}  // namespace
}  // namespace isphdem::validation
