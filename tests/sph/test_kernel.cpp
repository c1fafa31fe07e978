// Kernels: unit integral and antisymmetric gradient, checked by quadrature on fine lattices.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel.hpp"

namespace isph {
namespace {

template <int Dim>
void check_normalisation(KernelType type) {
  const double h = 0.37;
  Kernel<Dim> W(type, h);
  const double d = h / 40.0;  // quadrature spacing
  const int m = static_cast<int>(std::ceil(W.support() / d)) + 1;
  double integral = 0.0;
  Vec<Dim> first_moment_of_grad = Vec<Dim>::Zero();
  Eigen::Matrix<int, Dim, 1> c = Eigen::Matrix<int, Dim, 1>::Constant(-m);
  while (true) {
    const Vec<Dim> x = c.template cast<double>() * d;
    const double r = x.norm();
    integral += W.value(r) * std::pow(d, Dim);
    if (r > 0) first_moment_of_grad += W.derivative(r) * x / r * std::pow(d, Dim);
    int a = 0;
    while (a < Dim && ++c[a] > m) c[a++] = -m;
    if (a == Dim) break;
  }
  EXPECT_NEAR(integral, 1.0, 2e-4) << kernel_name(type) << " in " << Dim << "D";
  // The gradient is odd: its integral vanishes by symmetry (lattice symmetric about 0).
  EXPECT_LT(first_moment_of_grad.norm(), 1e-10) << kernel_name(type);
}

TEST(Kernel, NormalisedWendland2D) { check_normalisation<2>(KernelType::WendlandC2); }
TEST(Kernel, NormalisedWendland3D) { check_normalisation<3>(KernelType::WendlandC2); }
TEST(Kernel, NormalisedCubic2D) { check_normalisation<2>(KernelType::CubicSpline); }
TEST(Kernel, NormalisedCubic3D) { check_normalisation<3>(KernelType::CubicSpline); }

TEST(Kernel, DerivativeMatchesFiniteDifference) {
  for (auto type : {KernelType::WendlandC2, KernelType::CubicSpline}) {
    Kernel<2> W(type, 0.5);
    for (double r = 0.05; r < 1.0; r += 0.0731) {
      const double e = 1e-6;
      const double fd = (W.value(r + e) - W.value(r - e)) / (2 * e);
      EXPECT_NEAR(W.derivative(r), fd, 1e-6 * std::abs(fd) + 1e-8)
          << kernel_name(type) << " r=" << r;
    }
    EXPECT_EQ(W.value(1.0), 0.0);
    EXPECT_EQ(W.derivative(1.0), 0.0);
  }
}

TEST(Kernel, UnknownNameNamesTheValidOnes) {
  try {
    kernel_type_from_name("gaussian");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wendland_c2"), std::string::npos);
  }
}

}  // namespace
}  // namespace isph
