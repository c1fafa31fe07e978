#pragma once
// The pressure equation on PETSc: the matrix sph/ assembles (Eigen CSR) copied into a SeqAIJ
// Mat, a Krylov solver (BiCGSTAB unless -ksp_type says otherwise) right-preconditioned with
// hypre's BoomerAMG, so that the residual PETSc tests is the true one, |b - A x|, as on the
// Eigen path. On several MPI ranks (PETSC_COMM_WORLD larger than one) the system is one
// distributed MPIAIJ matrix: every rank passes the whole (replicated) system, enters its own
// contiguous block of rows, and gets the whole solution back; all ranks must call solve() together
// with the same system. A decomposed system (number_globally, sph/linear_solver.hpp) is entered
// the same way, each rank its owned rows with the columns renumbered globally; each rank gets its
// owned rows of x back. Reuse between solves:
//  - the Mat keeps its storage while the sparsity pattern stays the same (only the values are
//    copied), else it is made anew;
//  - x comes in as the initial guess (the previous pressure);
//  - the AMG hierarchy is kept for up to LinearSolverConfig::setup_reuse solves of the same
//    size, and rebuilt earlier once the iterations grow past 1.5x those right after a setup.
// Needs a live PetscSession.
#include <memory>
#include <string>

#include "linear_solver.hpp"

namespace isph {

std::unique_ptr<LinearSolver> make_amg_solver(const LinearSolverConfig& config);

// Whether NAME (as PETSc's options database keeps it, without the dash) is one of the BoomerAMG
// options isphdem sets itself: not the user's, so not to be reported when nothing read it (a run
// with -pc_type other than hypre).
bool is_builtin_amg_option(const std::string& name);

// How many AMG solvers this process has made (PetscSession reports unused options only then).
int amg_solvers_created();

}  // namespace isph
