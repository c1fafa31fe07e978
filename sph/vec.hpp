#pragma once
// Small fixed-size vector and matrix types shared by the whole fluid library.
#include <Eigen/Dense>

namespace isph {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Mat = Eigen::Matrix<double, Dim, Dim>;

}  // namespace isph
