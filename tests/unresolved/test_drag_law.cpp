// Seed resistance law (coupling/drag_law): the validation-table coefficients, Ergun's hydraulic
// gradients, the sign on both branches, the jump at eps = 0.8 and the optional blend.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "unresolved/drag_law.hpp"

namespace isphdem {
namespace {

SeedResistanceParameters table_parameters() {
  SeedResistanceParameters p;
  p.grain_diameter = 1e-3;
  p.kinematic_viscosity = 1e-6;
  p.alpha = 150.0;
  p.beta = 1.75;
  return p;
}

TEST(SeedResistance, CoefficientsOfTheValidationTable) {
  const SeedResistance law(table_parameters());
  EXPECT_NEAR(law.a_star(0.4) / 843.75, 1.0, 1e-12);
  EXPECT_NEAR(law.b_star(0.4) / 16406.25, 1.0, 1e-12);
  // Below the switch the law is a* eps v_r + b* eps^2 |v_r| v_r.
  const ResistanceCoefficients c = law.coefficients(0.4, 0.0125);
  EXPECT_NEAR(c.linear / (843.75 * 0.4), 1.0, 1e-12);
  EXPECT_NEAR(c.quadratic / (16406.25 * 0.16), 1.0, 1e-12);
}

// Fixed bed, Darcy velocity U upward, grains at rest: v_r = U / eps (interstitial). Steady Eq. (2)
// gives -dp/dz = rho g + rho K |v_r|, so the hydraulic gradient is i = K |v_r| / g.
double hydraulic_gradient(const SeedResistance& law, double eps, double darcy_velocity) {
  const double vr = darcy_velocity / eps;
  return law.coefficients(eps, vr).total(vr) * vr / 9.81;
}

TEST(SeedResistance, ErgunHydraulicGradientsOfTheValidationTable) {
  for (bool blend : {false, true}) {
    SeedResistanceParameters p = table_parameters();
    p.blend = blend;
    const SeedResistance law(p);
    const double i_low = hydraulic_gradient(law, 0.4, 0.005);
    const double i_high = hydraulic_gradient(law, 0.4, 0.02);
    RecordProperty(blend ? "i_0.5cm_blend" : "i_0.5cm", std::to_string(i_low));
    EXPECT_NEAR(i_low, 0.472, 5e-4);
    EXPECT_NEAR(i_high, 2.389, 5e-4);
    // Same numbers straight from Ergun in the Darcy velocity.
    EXPECT_NEAR(i_low, (843.75 * 0.005 + 16406.25 * 0.005 * 0.005) / 9.81, 1e-12);
  }
}

TEST(SeedResistance, ForceOpposesRelativeVelocityOnBothBranches) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> eps_dist(0.26, 0.999), v(-0.5, 0.5);
  for (bool blend : {false, true}) {
    SeedResistanceParameters p = table_parameters();
    p.blend = blend;
    const SeedResistance law(p);
    int above = 0, below = 0;
    for (int n = 0; n < 2000; ++n) {
      const double eps = eps_dist(rng);
      const double vr[3] = {v(rng), v(rng), v(rng)};
      const double speed = std::sqrt(vr[0] * vr[0] + vr[1] * vr[1] + vr[2] * vr[2]);
      const ResistanceCoefficients c = law.coefficients(eps, speed);
      double power = 0.0;  // F_r* . v_r
      for (double x : vr) power += -c.total(speed) * x * x;
      ASSERT_LT(power, 0.0) << "eps " << eps << " |v_r| " << speed;
      ASSERT_GE(c.linear, 0.0);
      ASSERT_GE(c.quadratic, 0.0);
      (eps >= 0.8 ? above : below)++;
    }
    EXPECT_GT(above, 100);
    EXPECT_GT(below, 100);
  }
}

TEST(SeedResistance, WenYuSplitReproducesCStar) {
  const SeedResistance law(table_parameters());
  // Re = eps^2 d |v_r| / nu spans Stokes, intermediate and C_d = 0.44.
  for (double speed : {1e-6, 1e-3, 0.05, 0.5, 3.0}) {
    for (double eps : {0.8, 0.9, 0.99}) {
      const double k = law.wen_yu(eps, speed).total(speed);
      EXPECT_NEAR(k / (law.c_star(eps, speed) * speed), 1.0, 1e-12) << eps << " " << speed;
    }
  }
  EXPECT_NEAR(law.reynolds(0.9, 0.5), 0.81 * 1e-3 * 0.5 / 1e-6, 1e-9);
  // No resistance without grains.
  EXPECT_EQ(law.coefficients(1.0, 0.3).total(0.3), 0.0);
}

TEST(SeedResistance, DragCoefficient) {
  EXPECT_NEAR(wen_yu_drag_coefficient(1.0), 27.6, 1e-12);
  EXPECT_NEAR(wen_yu_drag_coefficient(100.0), 1.0917310910948732, 1e-12);
  EXPECT_NEAR(wen_yu_drag_coefficient(2000.0), 0.44, 1e-15);
  EXPECT_NEAR(wen_yu_drag_coefficient(1000.0), 0.43828814001999694, 1e-12);
  EXPECT_THROW(wen_yu_drag_coefficient(0.0), std::domain_error);
}

// Largest |K(eps_i+1) - K(eps_i)| / K over a sweep of eps across the switch at spacing h.
double max_relative_step(const SeedResistance& law, double speed, double h) {
  double worst = 0.0;
  double prev = law.coefficients(0.7, speed).total(speed);
  for (double eps = 0.7 + h; eps <= 0.9; eps += h) {
    const double k = law.coefficients(eps, speed).total(speed);
    worst = std::max(worst, std::abs(k - prev) / prev);
    prev = k;
  }
  return worst;
}

TEST(SeedResistance, HardSwitchJumpsBlendIsContinuous) {
  SeedResistanceParameters p = table_parameters();
  const SeedResistance hard(p);
  p.blend = true;
  const SeedResistance blended(p);
  for (double speed : {1e-7, 1e-3, 0.05}) {
    const double hard_coarse = max_relative_step(hard, speed, 1e-3);
    const double hard_fine = max_relative_step(hard, speed, 1e-5);
    const double blend_coarse = max_relative_step(blended, speed, 1e-3);
    const double blend_fine = max_relative_step(blended, speed, 1e-5);
    std::printf("|v_r| %g: max step hard %.3e -> %.3e, blend %.3e -> %.3e\n", speed, hard_coarse,
                hard_fine, blend_coarse, blend_fine);
    EXPECT_GT(hard_fine, 0.05);  // the jump stays whatever the spacing
    EXPECT_GT(hard_fine, 0.5 * hard_coarse);
    EXPECT_LT(blend_fine, 0.02 * blend_coarse);  // 100x finer sampling: ~100x smaller steps
    EXPECT_LT(blend_fine, 1e-3);
  }
  // Stokes limit: Wen-Yu / Ergun at eps = 0.8 with the seed's Re is
  // 18 (1 - eps) eps^-4.7 / (150 (1 - eps)^2 eps^-2) = 1.096
  // (the linear parts are the Stokes limits of both branches).
  const double ratio = hard.wen_yu(0.8, 1e-3).linear / hard.ergun(0.8).linear;
  std::printf("Stokes-limit jump at eps = 0.8: Wen-Yu / Ergun = %.6f\n", ratio);
  EXPECT_NEAR(ratio, 1.095994274792134, 1e-12);
  // The blend leaves both branches untouched outside the ramp.
  EXPECT_EQ(blended.coefficients(0.74, 0.01).total(0.01),
            hard.coefficients(0.74, 0.01).total(0.01));
  EXPECT_EQ(blended.coefficients(0.86, 0.01).total(0.01),
            hard.coefficients(0.86, 0.01).total(0.01));
}

TEST(SeedResistance, RejectsBadInput) {
  SeedResistanceParameters p = table_parameters();
  p.grain_diameter = 0.0;
  EXPECT_THROW(SeedResistance{p}, std::invalid_argument);
  const SeedResistance law(table_parameters());
  EXPECT_THROW(law.coefficients(0.0, 1.0), std::domain_error);
  EXPECT_THROW(law.coefficients(1.2, 1.0), std::domain_error);
  EXPECT_THROW(law.coefficients(0.5, -1.0), std::domain_error);
  EXPECT_THROW(law.coefficients(0.5, 1.0, 0.0), std::domain_error);
  EXPECT_THROW(law.coefficients(0.9, 1.0, -1e-3), std::domain_error);
}

// The diameter argument is the law's d_s: a law built for 1 mm asked at 0.4 mm gives what a law
// built for 0.4 mm gives, on both branches and across the blend; Ergun's viscous part scales as
// 1/d^2, its inertial part as 1/d.
TEST(SeedResistance, DiameterArgumentIsTheGrainDiameter) {
  SeedResistanceParameters p = table_parameters();
  p.blend = true;
  const SeedResistance one_mm(p);
  p.grain_diameter = 0.4e-3;
  const SeedResistance small(p);
  for (double eps : {0.3, 0.5, 0.78, 0.8, 0.83, 0.95})
    for (double v : {0.0, 1e-3, 0.05, 2.0}) {
      const ResistanceCoefficients a = one_mm.coefficients(eps, v, 0.4e-3);
      const ResistanceCoefficients b = small.coefficients(eps, v);
      EXPECT_EQ(a.linear, b.linear) << eps << " " << v;
      EXPECT_EQ(a.quadratic, b.quadratic) << eps << " " << v;
    }
  EXPECT_NEAR(one_mm.ergun(0.4, 0.4e-3).linear / one_mm.ergun(0.4).linear, 6.25, 1e-12);
  EXPECT_NEAR(one_mm.ergun(0.4, 0.4e-3).quadratic / one_mm.ergun(0.4).quadratic, 2.5, 1e-12);
}

}  // namespace
}  // namespace isphdem
