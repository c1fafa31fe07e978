#pragma once
// Smoothing kernels with compact support 2h. Values and gradients are evaluated once per pair and
// step (see Neighbors) and then reused by every operator.
#include <string>

#include "vec.hpp"

namespace isph {

enum class KernelType { WendlandC2, CubicSpline };

KernelType kernel_type_from_name(const std::string& name);  // throws with the valid names
std::string kernel_name(KernelType type);

template <int Dim>
class Kernel {
 public:
  Kernel(KernelType type, double h);

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  KernelType type() const { return type_; }

  double value(double r) const;
  // dW/dr; the gradient with respect to x_i is dW/dr * r_ij / r with r_ij = x_i - x_j.
  double derivative(double r) const;

 private:
  KernelType type_;
  double h_;
  double norm_;  // dimension-dependent normalisation divided by h^Dim
};

}  // namespace isph
