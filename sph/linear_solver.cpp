#include "linear_solver.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>

#include "ilu0_preconditioner.hpp"

namespace isph {

namespace {

template <class Preconditioner>
class EigenBiCGSTAB : public LinearSolver {
 public:
  explicit EigenBiCGSTAB(const LinearSolverConfig& c) : config_(c) {}

  SolveStats solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double reference) override {
    const double scale = std::max(b.norm(), reference);
    SolveStats s;
    if (scale == 0.0) {  // nothing to solve: b = 0 and no reference
      x.setZero();
      s.converged = true;
      return s;
    }
    // Eigen's BiCGSTAB measures |r| / |b|; translate the tolerance to that measure.
    solver_.setTolerance(config_.tolerance * scale / std::max(b.norm(), 1e-300));
    solver_.setMaxIterations(config_.max_iterations);
    const auto t0 = std::chrono::steady_clock::now();
    solver_.compute(A);  // the preconditioner: a diagonal, or an incomplete factorisation
    s.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (solver_.info() != Eigen::Success)
      throw std::runtime_error("pressure solver: preconditioner setup failed");
    x = solver_.solveWithGuess(b, x);
    s.iterations = static_cast<int>(solver_.iterations());
    s.residual = (b - A * x).norm() / scale;
    s.converged = s.residual <= config_.tolerance * (1.0 + 1e-6);
    return s;
  }

 private:
  LinearSolverConfig config_;
  Eigen::BiCGSTAB<SparseMatrix, Preconditioner> solver_;
};

std::map<std::string, LinearSolverFactory>& registry() {
  static std::map<std::string, LinearSolverFactory> r;
  return r;
}

}  // namespace

void register_linear_solver(const std::string& preconditioner, LinearSolverFactory factory) {
  if (factory)
    registry()[preconditioner] = std::move(factory);
  else
    registry().erase(preconditioner);
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverConfig& config) {
  if (config.method != "bicgstab")
    throw std::invalid_argument("unknown linear solver '" + config.method + "': use \"bicgstab\"");
  if (config.preconditioner == "jacobi")
    return std::make_unique<EigenBiCGSTAB<Eigen::DiagonalPreconditioner<double>>>(config);
  if (config.preconditioner == "ilut")
    return std::make_unique<EigenBiCGSTAB<Eigen::IncompleteLUT<double>>>(config);
  if (config.preconditioner == "ilu0")
    return std::make_unique<EigenBiCGSTAB<Ilu0Preconditioner>>(config);
  if (auto f = registry().find(config.preconditioner); f != registry().end())
    return f->second(config);
  if (config.preconditioner == "amg")
    throw std::invalid_argument(
        "preconditioner \"amg\" needs the PETSc backend (sph_petsc/), which this program has "
        "not started: create an isph::PetscSession first");
  throw std::invalid_argument("unknown preconditioner '" + config.preconditioner +
                              "': use \"jacobi\", \"ilu0\" or \"ilut\"");
}

}  // namespace isph
