#pragma once
// The pressure equation is non-symmetric (corrected Laplacian, wall extrapolation rows), so the
// default is BiCGSTAB. Backends that need MPI (PETSc + hypre AMG, sph_petsc/) live outside sph/
// and register a factory under their preconditioner name; sph/ itself never sees MPI.
#include <Eigen/Sparse>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace isph {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct SolveStats {
  int iterations = 0;
  // |b - A x| / max(|b|, reference): converged when <= tolerance. The reference keeps a
  // right-hand side that is zero up to round-off (a flow already divergence-free) solvable.
  double residual = 0.0;
  bool converged = false;
  double setup_seconds = 0.0;  // preconditioner setup (AMG hierarchy, factorisation) in this call
  // Why the backend stopped when it did not converge (PETSc's KSPConvergedReason), else empty.
  std::string reason;
  // The backend met NaN or infinity: stop the run whatever the residual says.
  bool broke_down = false;
};

struct LinearSolverConfig {
  std::string method = "bicgstab";
  // Jacobi: many cheap iterations beat Eigen's ILUT, whose per-step factorisation dominates
  // (2500-particle Taylor-Green: 20x faster overall). "ilut" stays available.
  std::string preconditioner = "jacobi";
  double tolerance = 1e-8;
  int max_iterations = 2000;
  // For a registered backend: its own options, passed as they are ([solver.petsc] options).
  std::string backend_options;
  // How many solves may reuse one preconditioner setup while the size stays the same; it is
  // rebuilt earlier once the iterations grow past 1.5x those right after the last setup.
  // 1: a new setup every solve. Used by the AMG backend, where the setup is the costly part.
  int setup_reuse = 1;
};

// How the rows of a decomposed system (issue 26: each process holds the particles it owns, then a
// halo of copies of other processes' particles) make one system over all processes. Rows
// [0, owned) of A, b and x are this process's; A's columns are local indices, owned then halo,
// and global[j] is column j's number in the whole system, where every process's owned rows are
// numbered after those of the processes before it (global[i] = global[0] + i for i < owned).
struct GlobalNumbering {
  int owned = 0;
  int64_t total = 0;            // rows of the whole system, over all processes
  std::vector<int64_t> global;  // per local column: owned, then halo
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // x holds the initial guess on entry (warm start) and the solution on exit. `reference` is the
  // norm of a right-hand side of physical size (0: |b| alone).
  virtual SolveStats solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                           double reference = 0.0) = 0;
  // True when this process solves only its block of rows (block_start of sph/row_share.hpp) and
  // reads no other rows of A and b; x is still returned whole.
  virtual bool distributed_rows() const { return false; }
  // From now on solve() takes decomposed systems numbered this way (null: back to whole
  // systems). Only x's owned rows are solved; its halo rows are left as they were, for the caller
  // to refresh from their owners. Backends that cannot solve across processes say so.
  virtual void number_globally(std::shared_ptr<const GlobalNumbering> /*numbering*/) {
    throw std::invalid_argument(
        "this pressure solver cannot solve a decomposed system: use solver.preconditioner = "
        "\"amg\"");
  }
};

using LinearSolverFactory = std::function<std::unique_ptr<LinearSolver>(const LinearSolverConfig&)>;

// The built-in preconditioners (jacobi, ilu0, ilut) and any registered one, by
// config.preconditioner.
std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverConfig& config);

// Makes `preconditioner` available to make_linear_solver (replacing an earlier registration); an
// empty factory removes it again, e.g. once the library behind it is finalised.
void register_linear_solver(const std::string& preconditioner, LinearSolverFactory factory);

}  // namespace isph
