#pragma once
// Second-order consistent ("SPH(2)") differential operators by a weighted least-squares fit of a
// quadratic Taylor polynomial around each particle. For particle i and neighbour j the fit gives
// per-pair weights once per step, and every operator is then a cheap sum:
//   grad f_i = sum_j a_ij (f_j - f_i),   lap f_i = sum_j b_ij (f_j - f_i).
// Exact for quadratic fields (gradient and Laplacian) on any particle cloud with enough
// neighbours. Where the quadratic fit is ill-conditioned (sparse or one-sided support) a particle
// falls back to the kernel-corrected first-order gradient and the Brookshaw Laplacian; `order`
// records which was used.
#include <cstdint>
#include <vector>

#include "neighbors.hpp"

namespace isph {

template <int Dim>
struct Operators {
  std::vector<Vec<Dim>> grad;  // a_ij per pair
  std::vector<double> lap;     // b_ij per pair
  std::vector<uint8_t> order;  // per particle: 2 quadratic fit, 1 fallback, 0 no usable neighbours
};

// Computes operator weights per particle according to mode[i] (all quadratic when mode is empty):
// 0 none (zero weights), 1 first-order forms only, 2 quadratic fit where well conditioned. Mode 1
// serves free-surface particles, whose one-sided support makes the quadratic fit extrapolate
// wildly. h scales the fit for conditioning; volume is used by the first-order forms only.
template <int Dim>
void compute_operators(const Neighbors<Dim>& nb, double h, double volume,
                       const std::vector<uint8_t>& mode, Operators<Dim>& out);

template <int Dim>
Vec<Dim> gradient(const Neighbors<Dim>& nb, const Operators<Dim>& op, const std::vector<double>& f,
                  int i) {
  Vec<Dim> g = Vec<Dim>::Zero();
  for (int k = nb.begin(i); k < nb.end(i); ++k) g += op.grad[k] * (f[nb.index[k]] - f[i]);
  return g;
}

template <int Dim>
double divergence(const Neighbors<Dim>& nb, const Operators<Dim>& op,
                  const std::vector<Vec<Dim>>& u, int i) {
  double d = 0.0;
  for (int k = nb.begin(i); k < nb.end(i); ++k) d += op.grad[k].dot(u[nb.index[k]] - u[i]);
  return d;
}

template <int Dim>
double laplacian(const Neighbors<Dim>& nb, const Operators<Dim>& op, const std::vector<double>& f,
                 int i) {
  double l = 0.0;
  for (int k = nb.begin(i); k < nb.end(i); ++k) l += op.lap[k] * (f[nb.index[k]] - f[i]);
  return l;
}

template <int Dim>
Vec<Dim> laplacian(const Neighbors<Dim>& nb, const Operators<Dim>& op,
                   const std::vector<Vec<Dim>>& u, int i) {
  Vec<Dim> l = Vec<Dim>::Zero();
  for (int k = nb.begin(i); k < nb.end(i); ++k) l += op.lap[k] * (u[nb.index[k]] - u[i]);
  return l;
}

// Velocity gradient tensor (row = component, column = derivative direction).
template <int Dim>
Mat<Dim> gradient(const Neighbors<Dim>& nb, const Operators<Dim>& op,
                  const std::vector<Vec<Dim>>& u, int i) {
  Mat<Dim> g = Mat<Dim>::Zero();
  for (int k = nb.begin(i); k < nb.end(i); ++k)
    g += (u[nb.index[k]] - u[i]) * op.grad[k].transpose();
  return g;
}

}  // namespace isph
