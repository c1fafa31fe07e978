// ILU(0): exact where the pattern admits no fill-in, and a far better preconditioner than Jacobi
// on a Laplacian.
#include <gtest/gtest.h>

#include <random>

#include "ilu0_preconditioner.hpp"
#include "linear_solver.hpp"

namespace isph {
namespace {

SparseMatrix tridiagonal(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0 + u(rng));
    if (i > 0) t.emplace_back(i, i - 1, u(rng));
    if (i + 1 < n) t.emplace_back(i, i + 1, u(rng));
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// Non-symmetric 5-point convection-diffusion operator on an m x m grid, Dirichlet rows around.
SparseMatrix laplacian_2d(int m) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int r = id(i, j);
      if (i == 0 || j == 0 || i == m - 1 || j == m - 1) {
        t.emplace_back(r, r, 1.0);
        continue;
      }
      t.emplace_back(r, r, -4.0);
      t.emplace_back(r, id(i - 1, j), 1.1);
      t.emplace_back(r, id(i + 1, j), 0.9);
      t.emplace_back(r, id(i, j - 1), 1.0);
      t.emplace_back(r, id(i, j + 1), 1.0);
    }
  SparseMatrix A(m * m, m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(Ilu0, ExactLuWithoutFillIn) {
  const SparseMatrix A = tridiagonal(200, 7);
  Ilu0Preconditioner P(A);
  ASSERT_EQ(P.info(), Eigen::Success);
  const Eigen::VectorXd x_true = Eigen::VectorXd::LinSpaced(200, -1.0, 2.0);
  const Eigen::VectorXd b = A * x_true;
  const double err = (P.solve(b) - x_true).lpNorm<Eigen::Infinity>();
  std::printf("tridiagonal 200: max |LU^-1 b - x| = %.2e\n", err);
  EXPECT_LT(err, 1e-12);
}

TEST(Ilu0, FactorsKeepThePattern) {
  const SparseMatrix A = laplacian_2d(12);
  Ilu0Preconditioner P(A);
  EXPECT_EQ(P.factors().nonZeros(), A.nonZeros());
}

TEST(Ilu0, NeedsFarFewerIterationsThanJacobi) {
  const SparseMatrix A = laplacian_2d(60);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  int iterations[2];
  const char* names[2] = {"jacobi", "ilu0"};
  for (int k = 0; k < 2; ++k) {
    LinearSolverConfig c;
    c.preconditioner = names[k];
    c.tolerance = 1e-10;
    auto solver = make_linear_solver(c);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows());
    const SolveStats s = solver->solve(A, b, x);
    ASSERT_TRUE(s.converged) << names[k];
    EXPECT_LT((A * x - b).norm() / b.norm(), 1e-9);
    iterations[k] = s.iterations;
  }
  std::printf("60x60 convection-diffusion: BiCGSTAB iterations jacobi %d, ilu0 %d\n", iterations[0],
              iterations[1]);
  EXPECT_LT(2 * iterations[1], iterations[0]);
}

TEST(Ilu0, MissingDiagonalIsReported) {
  SparseMatrix A(2, 2);
  A.insert(0, 1) = 1.0;
  A.insert(1, 0) = 1.0;
  A.makeCompressed();
  Ilu0Preconditioner P(A);
  EXPECT_EQ(P.info(), Eigen::NumericalIssue);
}

}  // namespace
}  // namespace isph
