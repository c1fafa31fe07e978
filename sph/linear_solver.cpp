#include "linear_solver.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <stdexcept>

namespace isph {

namespace {

template <class Preconditioner>
class EigenBiCGSTAB : public LinearSolver {
 public:
  explicit EigenBiCGSTAB(const LinearSolverConfig& c) : config_(c) {}

  SolveStats solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    // Eigen's ILUT wants column-major input; the row-major matrix keeps the SpMV parallel.
    solver_.setTolerance(config_.tolerance);
    solver_.setMaxIterations(config_.max_iterations);
    solver_.compute(A);
    if (solver_.info() != Eigen::Success)
      throw std::runtime_error("pressure solver: preconditioner setup failed");
    x = solver_.solveWithGuess(b, x);
    SolveStats s;
    s.iterations = static_cast<int>(solver_.iterations());
    const double bn = b.norm();
    s.residual = bn > 0.0 ? (b - A * x).norm() / bn : (A * x).norm();
    s.converged = solver_.info() == Eigen::Success || s.residual <= config_.tolerance;
    return s;
  }

 private:
  LinearSolverConfig config_;
  Eigen::BiCGSTAB<SparseMatrix, Preconditioner> solver_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverConfig& config) {
  if (config.method != "bicgstab")
    throw std::invalid_argument("unknown linear solver '" + config.method + "': use \"bicgstab\"");
  if (config.preconditioner == "jacobi")
    return std::make_unique<EigenBiCGSTAB<Eigen::DiagonalPreconditioner<double>>>(config);
  if (config.preconditioner == "ilut")
    return std::make_unique<EigenBiCGSTAB<Eigen::IncompleteLUT<double>>>(config);
  throw std::invalid_argument("unknown preconditioner '" + config.preconditioner +
                              "': use \"jacobi\" or \"ilut\"");
}

}  // namespace isph
