#include "operators.hpp"

#include <cmath>

namespace isph {

namespace {

// Monomials of the quadratic fit in scaled coordinates s = (x_j - x_i)/h: first the Dim linear
// ones, then the Dim pure second-order ones s_a^2/2 (their coefficients are d2f/dx_a^2 h^2), then
// the mixed ones.
template <int Dim>
constexpr int kTerms = Dim + Dim*(Dim + 1) / 2;

template <int Dim>
Eigen::Matrix<double, kTerms<Dim>, 1> basis(const Vec<Dim>& s) {
  Eigen::Matrix<double, kTerms<Dim>, 1> P;
  int t = 0;
  for (int a = 0; a < Dim; ++a) P[t++] = s[a];
  for (int a = 0; a < Dim; ++a) P[t++] = 0.5 * s[a] * s[a];
  for (int a = 0; a < Dim; ++a)
    for (int b = a + 1; b < Dim; ++b) P[t++] = s[a] * s[b];
  return P;
}

// Below this reciprocal condition number the quadratic fit is not trusted.
constexpr double kMinRcond = 1e-7;

// A well-conditioned fit can still give a Laplacian stencil with large negative neighbour
// weights when the support is one-sided and sparse (near-surface particles of a dam-break toe
// that the number-density test does not flag). Such a PPE row is far from an M-matrix, the
// discrete maximum principle is lost, and the pressure there came out at -5e5 Pa (against a
// hydrostatic scale of 2e3 Pa), launching the particle at 10 m/s within one step. On a full or
// lattice-like support every weight is positive (measured: none negative in the dam break's
// interior), so the fit is kept only while the negative weights stay a small fraction of the
// positive ones.
constexpr double kMaxNegativeLaplacian = 0.1;

}  // namespace

template <int Dim>
void compute_operators(const Neighbors<Dim>& nb, double h, double volume,
                       const std::vector<uint8_t>& mode, Operators<Dim>& out) {
  constexpr int T = kTerms<Dim>;
  using MatT = Eigen::Matrix<double, T, T>;
  using VecT = Eigen::Matrix<double, T, 1>;
  const int n = static_cast<int>(nb.size());
  out.grad.assign(nb.pairs(), Vec<Dim>::Zero());
  out.lap.assign(nb.pairs(), 0.0);
  out.order.assign(n, 0);
  const double inv_h = 1.0 / h;

#pragma omp parallel for schedule(dynamic, 256)
  for (int i = 0; i < n; ++i) {
    const uint8_t m = mode.empty() ? 2 : mode[i];
    if (m == 0) continue;
    const int b = nb.begin(i), e = nb.end(i);
    if (e - b < Dim) continue;

    bool quadratic = false;
    if (m == 2 && e - b >= T) {
      MatT M = MatT::Zero();
      for (int k = b; k < e; ++k) {
        const VecT P = basis<Dim>(-nb.rij[k] * inv_h);
        M.noalias() += nb.w[k] * P * P.transpose();
      }
      Eigen::LLT<MatT> llt(M);
      // Column by column: with the identity as one right-hand side Eigen took its general
      // blocked matrix path (packing, a GEMM kernel), which cost as much as the fit itself.
      MatT Minv;
      for (int c = 0; c < T; ++c) Minv.col(c) = llt.solve(VecT::Unit(c));
      // Exact 1-norm reciprocal condition number (the inverse is needed anyway).
      const double rcond = 1.0 / (M.cwiseAbs().colwise().sum().maxCoeff() *
                                  Minv.cwiseAbs().colwise().sum().maxCoeff());
      if (llt.info() == Eigen::Success && std::isfinite(rcond) && rcond > kMinRcond) {
        double positive = 0.0, negative = 0.0;
        for (int k = b; k < e; ++k) {
          const VecT c = Minv * (nb.w[k] * basis<Dim>(-nb.rij[k] * inv_h));
          out.grad[k] = c.template head<Dim>() * inv_h;
          out.lap[k] = c.template segment<Dim>(Dim).sum() * inv_h * inv_h;
          (out.lap[k] > 0.0 ? positive : negative) += std::abs(out.lap[k]);
        }
        quadratic = negative <= kMaxNegativeLaplacian * positive;
        if (quadratic) out.order[i] = 2;
      }
    }
    if (quadratic) continue;

    // Fallback: kernel-gradient-corrected gradient (exact for linear fields) and the Brookshaw
    // Laplacian, which keeps the pressure matrix an M-matrix where the fit is unreliable.
    Mat<Dim> L = Mat<Dim>::Zero();
    for (int k = b; k < e; ++k) L.noalias() -= volume * nb.rij[k] * nb.dw[k].transpose();
    // The correction needs a support that spans all directions: with a handful of neighbours
    // (spray, a splash tip) its inverse is huge and so is the gradient; the plain kernel
    // gradient underestimates there but cannot blow up.
    Eigen::FullPivLU<Mat<Dim>> lu(L);
    const bool corrected = e - b >= 3 * Dim && lu.isInvertible() && lu.rcond() > 0.05;
    const Mat<Dim> Linv = corrected ? Mat<Dim>(lu.inverse()) : Mat<Dim>::Identity();
    for (int k = b; k < e; ++k) {
      out.grad[k] = volume * Linv.transpose() * nb.dw[k];
      const double r2 = nb.r[k] * nb.r[k] + 0.01 * h * h;
      out.lap[k] = -2.0 * volume * nb.rij[k].dot(nb.dw[k]) / r2;
    }
    out.order[i] = 1;
  }
}

template void compute_operators<2>(const Neighbors<2>&, double, double, const std::vector<uint8_t>&,
                                   Operators<2>&);
template void compute_operators<3>(const Neighbors<3>&, double, double, const std::vector<uint8_t>&,
                                   Operators<3>&);

}  // namespace isph
