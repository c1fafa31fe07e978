// The corrected (second-order consistent) operators are exact for the gradient of linear fields
// and the Laplacian of quadratic fields on disordered interior particles, in 2D and 3D.
#include <gtest/gtest.h>

#include <random>

#include "lattice.hpp"
#include "operators.hpp"

namespace isph {
namespace {

template <int Dim>
struct Cloud {
  Particles<Dim> p;
  Neighbors<Dim> nb;
  Operators<Dim> op;
  std::vector<int> interior;
};

// A lattice in the unit box, every particle displaced randomly by up to 0.3 dx.
template <int Dim>
Cloud<Dim> disordered_cloud(double dx) {
  Cloud<Dim> c;
  c.p.spacing = dx;
  c.p.volume = std::pow(dx, Dim);
  fill_box<Dim>(c.p, Vec<Dim>::Zero(), Vec<Dim>::Ones(), dx, kFluid);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-0.3 * dx, 0.3 * dx);
  for (auto& x : c.p.x)
    for (int a = 0; a < Dim; ++a) x[a] += u(rng);
  Kernel<Dim> W(KernelType::WendlandC2, 1.3 * dx);
  Domain<Dim> dom;
  NeighborSearch<Dim> search(dom, W.support());
  search.sort(c.p);
  search.build(c.p, W, c.nb);
  compute_operators(c.nb, W.h(), c.p.volume, {}, c.op);
  for (std::size_t i = 0; i < c.p.size(); ++i)
    if ((c.p.x[i].array() > W.support()).all() && (c.p.x[i].array() < 1.0 - W.support()).all())
      c.interior.push_back(static_cast<int>(i));
  return c;
}

template <int Dim>
void check_exactness(double dx) {
  Cloud<Dim> c = disordered_cloud<Dim>(dx);
  ASSERT_GT(c.interior.size(), 50u);
  const int n = static_cast<int>(c.p.size());
  Vec<Dim> G;
  Mat<Dim> H;
  for (int a = 0; a < Dim; ++a) G[a] = 1.5 - 0.7 * a;
  H.setZero();
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) H(a, b) = (a == b) ? 2.0 + a : 0.6 - 0.1 * (a + b);
  std::vector<double> lin(n), quad(n);
  std::vector<Vec<Dim>> vec(n);
  for (int i = 0; i < n; ++i) {
    const Vec<Dim>& x = c.p.x[i];
    lin[i] = 3.0 + G.dot(x);
    quad[i] = lin[i] + 0.5 * x.dot(H * x);
    vec[i] = Vec<Dim>::Constant(-1.0) + H * x;  // linear vector field: div = trace(H)
  }
  double max_grad_err = 0, max_quad_grad_err = 0, max_lap_err = 0, max_div_err = 0;
  for (int i : c.interior) {
    EXPECT_EQ(c.op.order[i], 2) << "interior particle fell back to first order";
    max_grad_err = std::max(max_grad_err, (gradient(c.nb, c.op, lin, i) - G).norm() / G.norm());
    const Vec<Dim> gq = G + H * c.p.x[i];
    max_quad_grad_err =
        std::max(max_quad_grad_err, (gradient(c.nb, c.op, quad, i) - gq).norm() / gq.norm());
    max_lap_err =
        std::max(max_lap_err, std::abs(laplacian(c.nb, c.op, quad, i) - H.trace()) / H.trace());
    max_div_err =
        std::max(max_div_err, std::abs(divergence(c.nb, c.op, vec, i) - H.trace()) / H.trace());
  }
  std::printf(
      "[%dD dx=%g] relative errors: grad(linear) %.2e, grad(quadratic) %.2e, "
      "lap(quadratic) %.2e, div(linear) %.2e\n",
      Dim, dx, max_grad_err, max_quad_grad_err, max_lap_err, max_div_err);
  EXPECT_LT(max_grad_err, 1e-8);
  EXPECT_LT(max_quad_grad_err, 1e-8);
  EXPECT_LT(max_lap_err, 1e-8);
  EXPECT_LT(max_div_err, 1e-8);
}

TEST(Operators, ExactOnDisorderedParticles2D) { check_exactness<2>(0.02); }
TEST(Operators, ExactOnDisorderedParticles3D) { check_exactness<3>(0.08); }

// A smooth non-polynomial field: the Laplacian error falls under refinement. On a disordered
// cloud the quadratic fit leaves cubic terms, so the Laplacian is first-order there (RMS error
// ratio about 1/2 per halving); this asserts at least that.
TEST(Operators, LaplacianConvergesForSmoothField2D) {
  double prev = 0.0;
  for (double dx : {0.04, 0.02, 0.01}) {
    Cloud<2> c = disordered_cloud<2>(dx);
    std::vector<double> f(c.p.size());
    for (std::size_t i = 0; i < f.size(); ++i)
      f[i] = std::sin(2.0 * c.p.x[i][0]) * std::cos(3.0 * c.p.x[i][1]);
    double sum = 0.0;
    for (int i : c.interior) {
      const double e = laplacian(c.nb, c.op, f, i) + 13.0 * f[i];
      sum += e * e;
    }
    const double rms = std::sqrt(sum / c.interior.size());
    std::printf("dx=%g  RMS |lap f - exact| = %.3e%s\n", dx, rms,
                prev > 0 ? (" (ratio " + std::to_string(rms / prev) + ")").c_str() : "");
    if (prev > 0) {
      EXPECT_LT(rms, 0.65 * prev);
    }
    prev = rms;
  }
}

}  // namespace
}  // namespace isph
