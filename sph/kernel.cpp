#include "kernel.hpp"

#include <cmath>
#include <stdexcept>

namespace isph {

KernelType kernel_type_from_name(const std::string& name) {
  if (name == "wendland_c2") return KernelType::WendlandC2;
  if (name == "cubic_spline") return KernelType::CubicSpline;
  throw std::invalid_argument("unknown kernel '" + name +
                              "': use \"wendland_c2\" or \"cubic_spline\"");
}

std::string kernel_name(KernelType type) {
  return type == KernelType::WendlandC2 ? "wendland_c2" : "cubic_spline";
}

namespace {
double wendland_norm(int dim) { return dim == 2 ? 7.0 / (4.0 * M_PI) : 21.0 / (16.0 * M_PI); }
double cubic_norm(int dim) { return dim == 2 ? 10.0 / (7.0 * M_PI) : 1.0 / M_PI; }
}  // namespace

template <int Dim>
Kernel<Dim>::Kernel(KernelType type, double h) : type_(type), h_(h) {
  if (!(h > 0.0)) throw std::invalid_argument("kernel smoothing length must be positive");
  const double base = type == KernelType::WendlandC2 ? wendland_norm(Dim) : cubic_norm(Dim);
  norm_ = base / std::pow(h, Dim);
}

template <int Dim>
double Kernel<Dim>::value(double r) const {
  const double q = r / h_;
  if (q >= 2.0) return 0.0;
  if (type_ == KernelType::WendlandC2) {
    const double t = 1.0 - 0.5 * q;
    const double t2 = t * t;
    return norm_ * t2 * t2 * (2.0 * q + 1.0);
  }
  if (q < 1.0) return norm_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  const double t = 2.0 - q;
  return norm_ * 0.25 * t * t * t;
}

template <int Dim>
double Kernel<Dim>::derivative(double r) const {
  const double q = r / h_;
  if (q >= 2.0) return 0.0;
  if (type_ == KernelType::WendlandC2) {
    const double t = 1.0 - 0.5 * q;
    return norm_ / h_ * (-5.0 * q * t * t * t);
  }
  if (q < 1.0) return norm_ / h_ * (-3.0 * q + 2.25 * q * q);
  const double t = 2.0 - q;
  return norm_ / h_ * (-0.75 * t * t);
}

template class Kernel<2>;
template class Kernel<3>;

}  // namespace isph
