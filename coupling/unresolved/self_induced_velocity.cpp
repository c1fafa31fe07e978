#include "unresolved/self_induced_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isphdem {

namespace {

// Axes of the table: log1p-spaced, the Oseen number U h / nu up to 1e4 and h / L up to 1e3
// (beyond both the disturbance is gone to a part in 1e3 of its Stokes value).
constexpr int kOseenPoints = 64, kScreeningPoints = 48;
constexpr double kOseenMax = 1e4, kScreeningMax = 1e3;
// The kernel's transform, at h = 1, sampled up to q h = 40 (w(q)^2 is below 1e-9 of w(0)^2).
constexpr int kWaveNumbers = 800;
constexpr double kWaveNumberMax = 40.0;

// int_-1^1 (1 - c^2) / (1 + a^2 c^2) dc; its series below a = 0.01, where the closed form
// loses digits to cancellation.
double oseen_factor(double a) {
  if (a < 1e-2) {
    const double a2 = a * a;
    return 4.0 / 3.0 - a2 * (4.0 / 15.0 - a2 * 4.0 / 35.0);
  }
  const double inv2 = 1.0 / (a * a);
  return -2.0 * inv2 + 2.0 * (1.0 + inv2) * std::atan(a) / a;
}

// w(q) = 4 pi int_0^2 W(r) sin(q r)/(q r) r^2 dr at h = 1, by Simpson's rule.
std::vector<double> kernel_transform(isph::KernelType type, const std::vector<double>& q) {
  const isph::Kernel<3> W(type, 1.0);
  constexpr int n = 512;
  const double dr = 2.0 / n;
  std::vector<double> w(q.size());
  for (std::size_t k = 0; k < q.size(); ++k) {
    double s = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double r = i * dr, qr = q[k] * r;
      const double f = W.value(r) * (qr > 0.0 ? std::sin(qr) / qr : 1.0) * r * r;
      s += f * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
    }
    w[k] = 4.0 * M_PI * s * dr / 3.0;
  }
  return w;
}

double axis_value(int i, int n, double max) { return std::expm1(i * std::log1p(max) / (n - 1)); }

}  // namespace

SelfInducedVelocity::SelfInducedVelocity(isph::KernelType kernel, double kinematic_viscosity)
    : nu_(kinematic_viscosity) {
  if (!(nu_ > 0.0))
    throw std::invalid_argument("self-induced velocity: the viscosity must be positive");
  std::vector<double> q(kWaveNumbers);
  const double dq = kWaveNumberMax / kWaveNumbers;
  for (int k = 0; k < kWaveNumbers; ++k) q[k] = (k + 0.5) * dq;
  std::vector<double> w2 = kernel_transform(kernel, q);
  for (double& w : w2) w *= w;
  table_.resize(std::size_t(kOseenPoints) * kScreeningPoints);
  for (int i = 0; i < kOseenPoints; ++i) {
    const double x = axis_value(i, kOseenPoints, kOseenMax);
    for (int j = 0; j < kScreeningPoints; ++j) {
      const double y2 = std::pow(axis_value(j, kScreeningPoints, kScreeningMax), 2);
      double s = 0.0;
      for (int k = 0; k < kWaveNumbers; ++k) {
        const double d = q[k] * q[k] + y2;
        s += w2[k] * q[k] * q[k] / d * oseen_factor(x * q[k] / d);
      }
      table_[std::size_t(i) * kScreeningPoints + j] = std::log(3.0 / (2.0 * M_PI) * s * dq);
    }
  }
}

double SelfInducedVelocity::table_value(double oseen, double screening) const {
  auto locate = [](double value, int n, double max, int& i, double& t) {
    const double u = std::log1p(std::clamp(value, 0.0, max)) / std::log1p(max) * (n - 1);
    i = std::min(static_cast<int>(u), n - 2);
    t = u - i;
  };
  int i, j;
  double s, t;
  locate(oseen, kOseenPoints, kOseenMax, i, s);
  locate(screening, kScreeningPoints, kScreeningMax, j, t);
  auto at = [&](int a, int b) { return table_[std::size_t(a) * kScreeningPoints + b]; };
  return std::exp((1.0 - s) * ((1.0 - t) * at(i, j) + t * at(i, j + 1)) +
                  s * ((1.0 - t) * at(i + 1, j) + t * at(i + 1, j + 1)));
}

double SelfInducedVelocity::inverse_radius(double slip_speed, double screening_length,
                                           double h) const {
  if (!(h > 0.0))
    throw std::invalid_argument("self-induced velocity: the smoothing length must be > 0");
  const double screening = std::isfinite(screening_length) ? h / screening_length : 0.0;
  return table_value(std::abs(slip_speed) * h / nu_, screening) / h;
}

}  // namespace isphdem
