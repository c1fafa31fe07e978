// The PETSc + BoomerAMG backend solves the same pressure system as the Eigen path: the same
// pressures to solver tolerance, on the manufactured-solution problem of
// test_pressure_equation.cpp (disordered particles, fitted Laplacian, Dirichlet band), with
// flat iteration counts under refinement; a bad PETSc option stops with PETSc's message.
// The same tests run on one rank and under mpirun -np 2 (amg_solver_np2): there every rank
// passes the same system, the ranks solve it as one distributed MPIAIJ system, and each must get
// back the whole pressure, bit for bit the same on every rank.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdlib>

#include "linear_solver.hpp"
#include "manufactured_pressure.hpp"
#include "petsc_error.hpp"
#include "pressure_equation.hpp"

namespace isph {
namespace {

LinearSolverConfig config(const std::string& preconditioner, double tolerance = 1e-10) {
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

// Largest |x - x on rank 0| over every rank and row (0 on one rank).
double spread_over_ranks(const Eigen::VectorXd& x) {
  Eigen::VectorXd root = x;
  MPI_Bcast(root.data(), static_cast<int>(root.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  double d = (x - root).cwiseAbs().maxCoeff();
  MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return d;
}

TEST(AmgSolver, SamePressureAsEigenToSolverTolerance) {
  ManufacturedSystem m(0.02);
  const int n = static_cast<int>(m.p.size());
  Eigen::VectorXd eigen = Eigen::VectorXd::Zero(n), amg = Eigen::VectorXd::Zero(n);
  const SolveStats se = make_linear_solver(config("ilu0"))->solve(m.sys.A, m.sys.b, eigen);
  const SolveStats sa = make_linear_solver(config("amg"))->solve(m.sys.A, m.sys.b, amg);
  ASSERT_TRUE(se.converged);
  ASSERT_TRUE(sa.converged) << sa.reason;
  EXPECT_LE(sa.residual, 1e-10);
  EXPECT_GT(sa.setup_seconds, 0.0);
  // Both solve A p = b to |r| <= 1e-10 |b|; their difference is bounded by cond(A) times that.
  const double diff = (amg - eigen).cwiseAbs().maxCoeff() / eigen.cwiseAbs().maxCoeff();
  double err = 0;
  for (int i = 0; i < n; ++i) err = std::max(err, std::abs(amg[i] - exact_p(m.p.x[i])));
  const double spread = spread_over_ranks(amg);
  std::printf(
      "%d rank(s), N = %d: ilu0 %d iterations, amg %d; max |p_amg - p_ilu0| / max |p| = %.2e, "
      "amg error against the exact solution %.3e; largest difference between ranks %.1e\n",
      ranks(), n, se.iterations, sa.iterations, diff, err, spread);
  EXPECT_LT(diff, 1e-7);
  EXPECT_EQ(spread, 0.0);
  EXPECT_LT(sa.iterations, se.iterations);
}

TEST(AmgSolver, IterationsStayFlatUnderRefinement) {
  std::vector<int> its;
  for (double dx : {0.04, 0.02, 0.01}) {
    ManufacturedSystem m(dx);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(m.p.size());
    const SolveStats s = make_linear_solver(config("amg", 1e-8))->solve(m.sys.A, m.sys.b, x);
    ASSERT_TRUE(s.converged) << s.reason;
    std::printf("%d rank(s), dx = %g: N = %zu, %d BiCGSTAB + BoomerAMG iterations\n", ranks(), dx,
                m.p.size(), s.iterations);
    its.push_back(s.iterations);
  }
  // 16x the unknowns; Jacobi-BiCGSTAB needs about 4x the iterations over that range.
  EXPECT_LE(its.back(), 1.5 * its.front() + 1);
}

TEST(AmgSolver, ReusedSetupAndChangedValuesGiveTheNewSolution) {
  ManufacturedSystem m(0.02);
  const int n = static_cast<int>(m.p.size());
  LinearSolverConfig c = config("amg");
  c.setup_reuse = 3;
  auto solver = make_linear_solver(c);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const SolveStats first = solver->solve(m.sys.A, m.sys.b, x);
  ASSERT_TRUE(first.converged);
  // Same pattern, other values: the matrix is updated in place and the old hierarchy kept.
  SparseMatrix A2 = m.sys.A;
  for (int k = 0; k < A2.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A2, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 1.05;
  Eigen::VectorXd x2 = x;
  const SolveStats second = solver->solve(A2, m.sys.b, x2);
  ASSERT_TRUE(second.converged) << second.reason;
  EXPECT_EQ(second.setup_seconds, 0.0);  // no new setup
  EXPECT_LE((m.sys.b - A2 * x2).norm(), 1.01e-10 * m.sys.b.norm());
  EXPECT_GT((x2 - x).norm(), 1e-6 * x.norm());  // it did solve the changed system
  EXPECT_EQ(spread_over_ranks(x2), 0.0);
  // Another size (particles added or removed): a new matrix and hierarchy.
  ManufacturedSystem finer(0.015);
  Eigen::VectorXd x3 = Eigen::VectorXd::Zero(finer.p.size());
  const SolveStats third = solver->solve(finer.sys.A, finer.sys.b, x3);
  ASSERT_TRUE(third.converged) << third.reason;
  EXPECT_GT(third.setup_seconds, 0.0);
  EXPECT_LE((finer.sys.b - finer.sys.A * x3).norm(), 1.01e-10 * finer.sys.b.norm());
  EXPECT_EQ(spread_over_ranks(x3), 0.0);
}

TEST(AmgSolver, TooFewIterationsReportPetscsReason) {
  ManufacturedSystem m(0.02);
  LinearSolverConfig c = config("amg", 1e-14);
  c.max_iterations = 1;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m.p.size());
  const SolveStats s = make_linear_solver(c)->solve(m.sys.A, m.sys.b, x);
  EXPECT_FALSE(s.converged);
  EXPECT_FALSE(s.broke_down);  // more iterations would help: not a breakdown
  EXPECT_EQ(s.reason, "PETSc: DIVERGED_ITS");
}

TEST(AmgSolver, BadOptionStopsWithPetscsMessage) {
  LinearSolverConfig c = config("amg");
  c.backend_options = "-ksp_type nonsense";
  try {
    make_linear_solver(c);
    FAIL() << "a solver was made with -ksp_type nonsense";
  } catch (const PetscError& e) {
    const std::string m = e.what();
    std::printf("%s\n", m.c_str());
    EXPECT_NE(m.find("nonsense"), std::string::npos);
    EXPECT_NE(m.find("[solver.petsc] options"), std::string::npos);
  }
  // Take the bad value out again for the tests after this one.
  c.backend_options = "-ksp_type bcgs";
  EXPECT_NO_THROW(make_linear_solver(c));
}

}  // namespace
}  // namespace isph
