// The self-induced velocity's table (self_induced_velocity.hpp) against real-space integrals
// that share nothing with its Fourier route: by Newton's shell theorem, the mean of 1/|x - y|
// over two independent draws from a radial kernel is int int p(r1) p(r2) / max(r1, r2), and of
// the screened exp(-|x - y| / L) / |x - y| it is int int p p exp(-r> / L) sinh(r< / L) L / (r1 r2),
// with p(r) = 4 pi r^2 W(r).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kernel.hpp"
#include "unresolved/self_induced_velocity.hpp"

namespace isphdem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// <g(|x - y|)>_{W W}, with shell(r1, r2) the shell average of g, by the midpoint rule in r1, r2.
template <class Shell>
double real_space_mean(isph::KernelType type, double h, Shell shell) {
  const isph::Kernel<3> W(type, h);
  constexpr int n = 1200;
  const double dr = 2.0 * h / n;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r1 = (i + 0.5) * dr, p1 = 4.0 * M_PI * r1 * r1 * W.value(r1);
    for (int j = 0; j < n; ++j) {
      const double r2 = (j + 0.5) * dr;
      s += p1 * 4.0 * M_PI * r2 * r2 * W.value(r2) * shell(r1, r2);
    }
  }
  return s * dr * dr;
}

TEST(SelfInducedVelocity, StokesLimitIsTheKernelsMeanInverseDistance) {
  for (const auto type : {isph::KernelType::WendlandC2, isph::KernelType::CubicSpline}) {
    const double h = 1.3e-3;
    const SelfInducedVelocity si(type, 1e-6);
    const double expected =
        real_space_mean(type, h, [](double a, double b) { return 1.0 / std::max(a, b); });
    std::printf("%s: I h = %.5f, real space %.5f\n", isph::kernel_name(type).c_str(),
                si.stokes_inverse_radius(h) * h, expected * h);
    EXPECT_NEAR(si.stokes_inverse_radius(h) / expected, 1.0, 1e-3);
    EXPECT_NEAR(si.inverse_radius(0.0, kInf, h) / expected, 1.0, 1e-3);
  }
  // 0.826 / dx at h = 1.3 dx for the Wendland kernel (docs/unresolved.md).
  const SelfInducedVelocity w(isph::KernelType::WendlandC2, 1.0);
  EXPECT_NEAR(w.stokes_inverse_radius(1.3), 0.826, 0.001);
}

TEST(SelfInducedVelocity, ScreenedByTheOthersResistanceAsABrinkmanFluid) {
  const double h = 2e-3;
  const SelfInducedVelocity si(isph::KernelType::WendlandC2, 1e-4);
  // Screening lengths off the table's nodes, from far above h to well below it.
  for (const double L : {37.0 * h, 3.3 * h, 0.71 * h, 0.13 * h}) {
    const double expected =
        real_space_mean(isph::KernelType::WendlandC2, h, [L](double a, double b) {
          const double lo = std::min(a, b), hi = std::max(a, b);
          return std::exp(-hi / L) * std::sinh(lo / L) * L / (a * b);
        });
    const double got = si.inverse_radius(0.0, L, h);
    std::printf("L/h = %5.2f: I h = %.5f, real space %.5f\n", L / h, got * h, expected * h);
    EXPECT_NEAR(got / expected, 1.0, 0.01) << "L/h = " << L / h;
  }
}

// The velocity along the slip of the regularised Oseenlet, u = F/(2 pi)^3 int w(k)^2 (1 - c^2)
// Re[1 / (mu k^2 + i rho U k c)] d^3k, by brute force over k and c = cos(k, U) here, with the
// kernel's transform by the trapezoid rule: nothing shared with the table's closed forms.
double oseen_brute_force(double h, double nu, double U) {
  const isph::Kernel<3> W(isph::KernelType::WendlandC2, h);
  auto what = [&](double k) {
    constexpr int n = 400;
    const double dr = 2.0 * h / n;
    double s = 0.0;
    for (int i = 1; i < n; ++i) {
      const double r = i * dr;
      s += W.value(r) * std::sin(k * r) / (k * r) * 4.0 * M_PI * r * r;
    }
    return s * dr;
  };
  constexpr int nk = 1500, nc = 400;
  const double dk = 40.0 / h / nk, dc = 2.0 / nc;
  double u = 0.0;  // times mu, over F
  for (int i = 0; i < nk; ++i) {
    const double k = (i + 0.5) * dk, w2 = std::pow(what(k), 2);
    double ang = 0.0;
    for (int j = 0; j < nc; ++j) {
      const double c = -1.0 + (j + 0.5) * dc, im = U * k * c / nu;
      ang += (1.0 - c * c) * k * k / (k * k * k * k + im * im);
    }
    u += w2 * 2.0 * M_PI * k * k * ang * dc;
  }
  return 6.0 * M_PI * u * dk / std::pow(2.0 * M_PI, 3);  // I = 6 pi mu u / F
}

TEST(SelfInducedVelocity, SweptDownstreamByTheSlipAsAnOseenFluid) {
  const double h = 1e-3, nu = 1e-6;
  const SelfInducedVelocity si(isph::KernelType::WendlandC2, nu);
  for (const double re : {0.37, 3.1, 27.0}) {  // U h / nu off the table's nodes
    const double got = si.inverse_radius(re * nu / h, kInf, h);
    const double expected = oseen_brute_force(h, nu, re * nu / h);
    std::printf("U h / nu = %5.2f: I h = %.5f, brute force %.5f (Stokes %.5f)\n", re, got * h,
                expected * h, si.stokes_inverse_radius(h) * h);
    EXPECT_NEAR(got / expected, 1.0, 0.01) << "U h / nu = " << re;
  }
  // Far downstream of Stokes the regularised Oseenlet's mean falls as nu / (U h): g(a) -> pi / a.
  const double a = si.inverse_radius(200.0 * nu / h, kInf, h),
               b = si.inverse_radius(800.0 * nu / h, kInf, h);
  EXPECT_NEAR(a / b, 4.0, 0.2);
  // Screening and slip together weaken it further than either.
  EXPECT_LT(si.inverse_radius(10.0 * nu / h, h, h), si.inverse_radius(10.0 * nu / h, kInf, h));
  EXPECT_LT(si.inverse_radius(10.0 * nu / h, h, h), si.inverse_radius(0.0, h, h));
}

TEST(SelfInducedVelocity, RejectsANonPositiveLengthOrViscosity) {
  EXPECT_THROW(SelfInducedVelocity(isph::KernelType::WendlandC2, 0.0), std::invalid_argument);
  const SelfInducedVelocity si(isph::KernelType::WendlandC2, 1e-6);
  EXPECT_THROW(si.inverse_radius(0.0, kInf, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace isphdem
