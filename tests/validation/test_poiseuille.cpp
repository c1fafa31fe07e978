// Poiseuille flow between plates, driven by a body force: the steady velocity profile
// u(y) = g/(2 nu) y (L - y) is reached with an L2 error below 1% at 40 particles across.
#include <gtest/gtest.h>

#include <cmath>

#include "case_path.hpp"
#include "run/fluid_run.hpp"

namespace isphdem::validation {
namespace {

double profile_l2_error(const isph::IsphSolver<2>& s, double L) {
  const auto& P = s.particles();
  const double g = s.config().gravity[0], nu = s.config().viscosity;
  double num = 0, den = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != isph::kFluid) continue;
    const double y = P.x[i][1];
    const double exact = g / (2 * nu) * y * (L - y);
    num += std::pow(P.v[i][0] - exact, 2) + std::pow(P.v[i][1], 2);
    den += exact * exact;
  }
  return std::sqrt(num / den);
}

double run_poiseuille(int across) {
  const double L = 1e-3;
  const CaseFile c =
      load_example("poiseuille_2d", {"particles.spacing=" + std::to_string(L / across)});
  FluidRun<2> run(build_fluid_scene<2>(c), parse_run_settings(c));
  const double t_end = c.number("time.end");
  std::printf("%d particles across:\n", across);
  double err = 0;
  for (int k = 1; k <= 5; ++k) {
    run.run_until(t_end * k / 5);
    err = profile_l2_error(run.solver(), L);
    std::printf("  t = %.2f s  L2 error %.3e\n", run.solver().time(), err);
  }
  return err;
}

TEST(Poiseuille, SteadyProfileWithinOnePercentAt40Across) {
  const double coarse = run_poiseuille(20);
  const double fine = run_poiseuille(40);
  std::printf("steady L2 error: 20 across %.3e, 40 across %.3e (observed order %.2f)\n", coarse,
              fine, std::log2(coarse / fine));
  EXPECT_LT(fine, 0.01);
  EXPECT_LT(fine, coarse);
}

}  // namespace
}  // namespace isphdem::validation
