// The distributed PPE (sph_petsc/amg_solver.cpp on several ranks): run under mpirun. Every rank
// builds the same manufactured system (sph/manufactured_pressure.hpp), the ranks solve it as one
// MPIAIJ system, and each must get back the whole pressure: the one Eigen's ILU(0)-BiCGSTAB finds
// on its own, to solver tolerance, and bit for bit the same on every rank.
#include <gtest/gtest.h>
#include <mpi.h>

#include "linear_solver.hpp"
#include "manufactured_pressure.hpp"

namespace isph {
namespace {

LinearSolverConfig config(const std::string& preconditioner, double tolerance) {
  LinearSolverConfig c;
  c.preconditioner = preconditioner;
  c.tolerance = tolerance;
  return c;
}

int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// Largest |x - x on rank 0| over every rank and row.
double spread_over_ranks(const Eigen::VectorXd& x) {
  Eigen::VectorXd root = x;
  MPI_Bcast(root.data(), static_cast<int>(root.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  double d = (x - root).cwiseAbs().maxCoeff();
  MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return d;
}

TEST(AmgSolverMpi, RanksSolveOneSystemAndAllGetTheWholePressure) {
  ASSERT_GT(ranks(), 1) << "run under mpirun -np 2 or more";
  ManufacturedSystem m(0.02);
  const int n = static_cast<int>(m.p.size());
  Eigen::VectorXd eigen = Eigen::VectorXd::Zero(n), amg = Eigen::VectorXd::Zero(n);
  const SolveStats se = make_linear_solver(config("ilu0", 1e-10))->solve(m.sys.A, m.sys.b, eigen);
  const SolveStats sa = make_linear_solver(config("amg", 1e-10))->solve(m.sys.A, m.sys.b, amg);
  ASSERT_TRUE(se.converged);
  ASSERT_TRUE(sa.converged) << sa.reason;
  EXPECT_LE(sa.residual, 1e-10);
  const double diff = (amg - eigen).cwiseAbs().maxCoeff() / eigen.cwiseAbs().maxCoeff();
  const double spread = spread_over_ranks(amg);
  std::printf(
      "%d ranks, N = %d: amg %d iterations (ilu0 %d); max |p_amg - p_ilu0| / max |p| = "
      "%.2e; largest difference between ranks %.1e\n",
      ranks(), n, sa.iterations, se.iterations, diff, spread);
  EXPECT_LT(diff, 1e-7);
  EXPECT_EQ(spread, 0.0);
}

// Warm start and the in-place update of a distributed matrix: the second solve must solve the
// changed system, and a system of another size (particles added) must be taken as it comes.
TEST(AmgSolverMpi, ChangedValuesAndSizesAreSolvedAnew) {
  ManufacturedSystem m(0.02);
  const int n = static_cast<int>(m.p.size());
  LinearSolverConfig c = config("amg", 1e-10);
  c.setup_reuse = 3;
  auto solver = make_linear_solver(c);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  ASSERT_TRUE(solver->solve(m.sys.A, m.sys.b, x).converged);
  SparseMatrix A2 = m.sys.A;
  for (int k = 0; k < A2.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A2, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 1.05;
  Eigen::VectorXd x2 = x;
  const SolveStats second = solver->solve(A2, m.sys.b, x2);
  ASSERT_TRUE(second.converged) << second.reason;
  EXPECT_EQ(second.setup_seconds, 0.0);  // the hierarchy was kept
  EXPECT_LE((m.sys.b - A2 * x2).norm(), 1.01e-10 * m.sys.b.norm());
  EXPECT_GT((x2 - x).norm(), 1e-6 * x.norm());
  EXPECT_EQ(spread_over_ranks(x2), 0.0);

  ManufacturedSystem finer(0.015);
  Eigen::VectorXd x3 = Eigen::VectorXd::Zero(finer.p.size());
  const SolveStats third = solver->solve(finer.sys.A, finer.sys.b, x3);
  ASSERT_TRUE(third.converged) << third.reason;
  EXPECT_LE((finer.sys.b - finer.sys.A * x3).norm(), 1.01e-10 * finer.sys.b.norm());
  EXPECT_EQ(spread_over_ranks(x3), 0.0);
}

TEST(AmgSolverMpi, IterationsStayFlatUnderRefinement) {
  std::vector<int> its;
  for (double dx : {0.04, 0.02, 0.01}) {
    ManufacturedSystem m(dx);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(m.p.size());
    const SolveStats s = make_linear_solver(config("amg", 1e-8))->solve(m.sys.A, m.sys.b, x);
    ASSERT_TRUE(s.converged) << s.reason;
    std::printf("%d ranks, dx = %g: N = %zu, %d iterations\n", ranks(), dx, m.p.size(),
                s.iterations);
    its.push_back(s.iterations);
  }
  EXPECT_LE(its.back(), 1.5 * its.front() + 1);
}

}  // namespace
}  // namespace isph
