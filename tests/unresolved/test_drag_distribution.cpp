// Conservative drag distribution (coupling/drag_distribution): what the fluid loses the grains
// gain, exactly; and a fixed bed carries the whole Ergun pressure drop (drag + buoyancy).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "unresolved/drag_distribution.hpp"

namespace isphdem {
namespace {

using isph::Vec;

template <int Dim>
void momentum_is_conserved(double depth) {
  std::mt19937 rng(42 + Dim);
  std::uniform_real_distribution<double> u(0.0, 10e-3), r(0.2e-3, 0.6e-3), f(-1.0, 1.0);
  std::vector<Grain<Dim>> grains(250);
  for (std::size_t k = 0; k < grains.size(); ++k) {
    grains[k].tag = static_cast<int>(7 * k + 2);
    for (int d = 0; d < Dim; ++d) grains[k].x[d] = u(rng);
    grains[k].radius = r(rng);
  }
  std::uniform_real_distribution<double> ux(-3e-3, 13e-3);
  std::vector<Vec<Dim>> x(3000);
  for (auto& p : x)
    for (int d = 0; d < Dim; ++d) p[d] = ux(rng);
  PorosityMapSettings set;
  set.smoothing_length = 1e-3;
  set.slab_thickness = 1e-3;
  const auto field = PorosityMap<Dim>(set).compute(x, grains);

  std::vector<Vec<Dim>> reaction(x.size());
  Vec<Dim> with_grain = Vec<Dim>::Zero(), without = Vec<Dim>::Zero();
  std::size_t orphans = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    for (int d = 0; d < Dim; ++d) reaction[a][d] = f(rng) * 1e-4;
    if (field.weights.offset[a + 1] > field.weights.offset[a]) {
      with_grain += reaction[a];
    } else {
      without += reaction[a];
      ++orphans;
    }
  }
  ASSERT_GT(orphans, 100u);  // the sample must contain particles with no grain in range
  const GrainLoads<Dim> loads = distribute_reactions(field.weights, grains, reaction, depth);
  Vec<Dim> total = Vec<Dim>::Zero();
  for (const auto& fk : loads.force) total += fk;
  const double rel = (total - depth * with_grain).norm() / (depth * with_grain).norm();
  std::printf("%dD: |sum f_k - depth sum f_a| / |depth sum f_a| = %.2e over %zu pairs\n", Dim, rel,
              field.weights.grain.size());
  EXPECT_LT(rel, 1e-12);
  EXPECT_LT((loads.unassigned - depth * without).norm(), 1e-12 * (depth * without).norm());
  for (std::size_t k = 0; k < grains.size(); ++k) EXPECT_EQ(loads.tag[k], grains[k].tag);
}

TEST(DragDistribution, MomentumIsConserved) {
  momentum_is_conserved<3>(1.0);
  momentum_is_conserved<2>(1e-3);
}

TEST(DragDistribution, ReactionsComeOnlyFromParticlesWithGrains) {
  std::vector<Grain<3>> grains(1);
  grains[0].radius = 0.5e-3;
  grains[0].tag = 9;
  PorosityMapSettings set;
  set.smoothing_length = 1e-3;
  const std::vector<Vec<3>> x = {Vec<3>(0.5e-3, 0, 0), Vec<3>(5e-3, 0, 0)};
  const auto field = PorosityMap<3>(set).compute(x, grains);
  SeedResistanceParameters p;
  const SeedResistance law(p);
  const std::vector<Vec<3>> vd = {Vec<3>(0, 0, 0.01), Vec<3>(0, 0, 0.01)};
  const auto f = resistance_reactions(field, vd, law, 1000.0, 1e-9);
  EXPECT_GT(f[0][2], 0.0);  // the grain is dragged along the flow
  EXPECT_EQ(f[1], Vec<3>::Zero());
  const auto loads = distribute_reactions(field.weights, grains, f);
  EXPECT_EQ(loads.force[0], f[0]);
  EXPECT_EQ(loads.unassigned, Vec<3>::Zero());
}

// Grains on a simple-cubic lattice of spacing s = 1 mm (eps = 0.4 by construction), at rest,
// fluid particles on a lattice at dx = s/2 with Darcy velocity U upward, grad p = -rho g i
// (dynamic part) from Ergun at the bed's Sauter mean diameter. In a cell of two neighbouring
// grains (volume 2 s^3) the fluid's drag is rho g i (2 s^3 - V_1 - V_2), shared by the grains'
// surfaces V_k / d_k; each grain adds its pressure-gradient force rho g i V_k. With equal grains
// f_k = rho g i s^3; with grains alternating in size (checkerboard, diameter ratio `ratio`) each
// size carries its own share (to the porosity's and the local mixture's kernel error).
void fixed_bed_carries_the_ergun_pressure_drop(double ratio, double tolerance) {
  const double s = 1e-3, eps0 = 0.4;
  // r_small^3 (1 + ratio^3) = 2 (1 - eps0) s^3 3 / (4 pi)
  const double r_small =
      std::cbrt(2.0 * (1.0 - eps0) * 3.0 / (4.0 * M_PI) / (1.0 + ratio * ratio * ratio)) * s;
  const double r_big = ratio * r_small;
  const int n = 12;
  std::vector<Grain<3>> grains;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        Grain<3> g;
        g.tag = static_cast<int>(grains.size()) + 1;
        g.x = Vec<3>(i, j, k) * s;
        g.radius = (i + j + k) % 2 ? r_big : r_small;
        grains.push_back(g);
      }
  const double dx = s / 2;
  std::vector<Vec<3>> x;
  for (int i = -4; i < 2 * n + 4; ++i)
    for (int j = -4; j < 2 * n + 4; ++j)
      for (int k = -4; k < 2 * n + 4; ++k) x.push_back(Vec<3>(i + 0.5, j + 0.5, k + 0.5) * dx);
  PorosityMapSettings set;
  set.smoothing_length = 1.3 * s;
  const auto field = PorosityMap<3>(set).compute(x, grains);
  SeedResistanceParameters p;  // nu 1e-6, Ergun 150 / 1.75
  const SeedResistance law(p);
  const double rho = 1000.0, g = 9.81, U = 0.005;
  const std::vector<Vec<3>> vd(x.size(), Vec<3>(0, 0, U));
  auto loads = distribute_reactions(field.weights, grains,
                                    resistance_reactions(field, vd, law, rho, dx * dx * dx));
  // Ergun at the Sauter mean of the grains' own diameters, not at the law's default 1 mm.
  const double d32 =
      2.0 * (std::pow(r_small, 3) + std::pow(r_big, 3)) / (r_small * r_small + r_big * r_big);
  const double i_ergun = (law.a_star(eps0, d32) * U + law.b_star(eps0, d32) * U * U) / g;
  add_pressure_gradient_forces(
      loads, grains, std::vector<Vec<3>>(grains.size(), Vec<3>(0, 0, -rho * g * i_ergun)));
  const double v_small = 4.0 / 3.0 * M_PI * std::pow(r_small, 3),
               v_big = v_small * std::pow(ratio, 3);
  const double surface = v_small / r_small + v_big / r_big, drag = 2 * s * s * s - v_small - v_big;
  double worst[2] = {0.0, 0.0}, mean[2] = {0.0, 0.0};
  int interior[2] = {0, 0};
  for (std::size_t k = 0; k < grains.size(); ++k) {
    const Vec<3>& c = grains[k].x;
    if ((c.array() < 4 * s).any() || (c.array() > (n - 5) * s).any()) continue;
    const int big = grains[k].radius == r_big && ratio != 1.0;
    const double v = big ? v_big : v_small, r = big ? r_big : r_small;
    const double expected = rho * g * i_ergun * (drag * (v / r) / surface + v);
    ++interior[big];
    mean[big] += loads.force[k][2] / expected;
    worst[big] = std::max(worst[big], std::abs(loads.force[k][2] - expected) / expected);
    EXPECT_LT(std::abs(loads.force[k][0]) + std::abs(loads.force[k][1]), 1e-9 * expected);
  }
  for (int b = 0; b < (ratio != 1.0 ? 2 : 1); ++b) {
    std::printf(
        "fixed bed, diameters %.3f / %.3f mm (d_32 %.4f mm): i = %.4f; %d interior %s grains, "
        "mean f_k / expected %.5f, largest error %.2e\n",
        2e3 * r_small, 2e3 * r_big, 1e3 * d32, i_ergun, interior[b], b ? "large" : "small",
        mean[b] / interior[b], worst[b]);
    EXPECT_GT(interior[b], 20);
    EXPECT_LT(worst[b], tolerance);
  }
}

TEST(DragDistribution, FixedBedCarriesTheErgunPressureDrop) {
  fixed_bed_carries_the_ergun_pressure_drop(1.0, 0.01);
}

// Grains of 1 : 2 in diameter, half of each (Beetstra et al. 2007's bidisperse beds): the small
// grains carry twice the drag per unit volume of the large.
TEST(DragDistribution, BidisperseFixedBedCarriesTheErgunPressureDropOfItsSauterMean) {
  fixed_bed_carries_the_ergun_pressure_drop(2.0, 0.01);  // volume shares: small -24%
}

// Grains moving with the interstitial fluid velocity v_D / eps feel no drag: the reaction uses
// v_r = v_D / eps - v_s, not v_D - v_s.
TEST(DragDistribution, NoDragWhenGrainsMoveWithTheInterstitialFluid) {
  const Vec<2> v(0.03, -0.01);
  std::vector<Grain<2>> grains;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      Grain<2> g;
      g.tag = 8 * i + j + 1;
      g.x = Vec<2>(i, j) * 1e-3;
      g.v = v;
      g.radius = 0.45e-3;
      grains.push_back(g);
    }
  std::vector<Vec<2>> x;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) x.push_back(Vec<2>(i + 0.25, j + 0.25) * 0.5e-3);
  PorosityMapSettings set;
  set.smoothing_length = 1.3e-3;
  set.slab_thickness = 1e-3;
  const auto field = PorosityMap<2>(set).compute(x, grains);
  std::vector<Vec<2>> vd(x.size());
  for (std::size_t a = 0; a < x.size(); ++a) vd[a] = field.porosity[a] * v;
  const SeedResistance law(SeedResistanceParameters{});
  const auto f = resistance_reactions(field, vd, law, 1000.0, 0.25e-6);
  // Against the reaction the same flow gives on grains at rest.
  for (auto& g : grains) g.v = Vec<2>::Zero();
  const auto still = PorosityMap<2>(set).compute(x, grains);
  const auto f_still = resistance_reactions(still, vd, law, 1000.0, 0.25e-6);
  for (std::size_t a = 0; a < x.size(); ++a) {
    ASSERT_GT(f_still[a].norm(), 0.0);
    EXPECT_LT(f[a].norm(), 1e-12 * f_still[a].norm());
  }
}

TEST(DragDistribution, PressureGradientForce) {
  const Vec<2> f = pressure_gradient_force<2>(Vec<2>(0.0, -9810.0), 1e-9);
  EXPECT_DOUBLE_EQ(f[1], 9.81e-6);  // buoyancy of 1 mm^3 in water, hydrostatic grad p
  EXPECT_EQ(f[0], 0.0);
}

// A graded mixture (Beetstra, van der Hoef & Kuipers 2007, in the form for a pressure-gradient
// force on the grains): one fluid point between a 0.5 mm and a 1 mm grain at equal distance
// gives them shares in the ratio of their surfaces V/d (1 : 4), adding up to the reaction; the
// reaction itself is the law's at the Sauter mean (V1 + V2) / (V1/d1 + V2/d2) = 0.9 mm.
TEST(DragDistribution, GradedGrainsShareByTheirSurface) {
  std::vector<Grain<3>> grains(2);
  grains[0].tag = 5, grains[0].x = Vec<3>(-0.5e-3, 0, 0), grains[0].radius = 0.25e-3;
  grains[1].tag = 9, grains[1].x = Vec<3>(0.5e-3, 0, 0), grains[1].radius = 0.5e-3;
  PorosityMapSettings set;
  set.smoothing_length = 1e-3;
  const std::vector<Vec<3>> x = {Vec<3>::Zero()};
  const auto field = PorosityMap<3>(set).compute(x, grains);
  EXPECT_NEAR(field.diameter[0] / 0.9e-3, 1.0, 1e-14);
  const SeedResistance law{SeedResistanceParameters{}};
  const std::vector<Vec<3>> vd = {Vec<3>(0, 0, 0.01)};
  const auto f = resistance_reactions(field, vd, law, 1000.0, 1e-9);
  const double eps = field.porosity[0], vr = 0.01 / eps;
  EXPECT_NEAR(f[0][2] / (eps * 1000.0 * 1e-9 * law.coefficients(eps, vr, 0.9e-3).total(vr) * vr),
              1.0, 1e-14);
  const auto loads = distribute_reactions(field.weights, grains, f);
  std::printf("shares of the 0.5 / 1 mm grains: %.6f / %.6f\n", loads.force[0][2] / f[0][2],
              loads.force[1][2] / f[0][2]);
  EXPECT_NEAR(loads.force[1][2] / loads.force[0][2], 4.0, 1e-12);
  EXPECT_NEAR((loads.force[0][2] + loads.force[1][2]) / f[0][2], 1.0, 1e-14);
}

// Equal grains keep the volume shares of the code before graded grains, to the last bit: every
// grain's load is exactly depth f_a w_ak / sum_k' w_ak' summed over the fluid points, in order.
TEST(DragDistribution, EqualGrainsKeepTheirVolumeSharesExactly) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 6e-3), f(-1.0, 1.0);
  std::vector<Grain<3>> grains(40);
  for (std::size_t k = 0; k < grains.size(); ++k) {
    grains[k].tag = static_cast<int>(k) + 1;
    grains[k].x = Vec<3>(u(rng), u(rng), u(rng));
    grains[k].radius = 0.37e-3;
  }
  std::vector<Vec<3>> x(500), reaction(500);
  for (std::size_t a = 0; a < x.size(); ++a) {
    x[a] = Vec<3>(u(rng), u(rng), u(rng));
    reaction[a] = Vec<3>(f(rng), f(rng), f(rng)) * 1e-5;
  }
  PorosityMapSettings set;
  set.smoothing_length = 1.2e-3;
  const auto field = PorosityMap<3>(set).compute(x, grains);
  const double depth = 2e-3;
  const GrainLoads<3> loads = distribute_reactions(field.weights, grains, reaction, depth);
  std::vector<Vec<3>> volume_shares(grains.size(), Vec<3>::Zero());
  for (std::size_t a = 0; a < x.size(); ++a) {
    const std::size_t b = field.weights.offset[a], e = field.weights.offset[a + 1];
    double sum = 0.0;
    for (std::size_t i = b; i < e; ++i) sum += field.weights.weight[i];
    if (!(sum > 0.0)) continue;
    const Vec<3> fa = depth * reaction[a] / sum;
    for (std::size_t i = b; i < e; ++i)
      volume_shares[field.weights.grain[i]] += field.weights.weight[i] * fa;
  }
  for (std::size_t k = 0; k < grains.size(); ++k) EXPECT_EQ(loads.force[k], volume_shares[k]);
}

}  // namespace
}  // namespace isphdem
