#include "amg_solver.hpp"

#include <petscksp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "petsc_error.hpp"
#include "row_share.hpp"

namespace isph {

namespace {

static_assert(sizeof(PetscInt) == sizeof(SparseMatrix::StorageIndex),
              "PETSc's index type must match Eigen's to copy the CSR arrays");
static_assert(sizeof(PetscScalar) == sizeof(double), "PETSc must be built with real doubles");

int created = 0;

// Owns a PETSc object. A member, so that the object is destroyed also when the constructor
// throws half-way (a bad option in KSPSetFromOptions leaked the KSP: AddressSanitizer).
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T h = nullptr;
  Owned() = default;
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  ~Owned() { reset(); }
  void reset() {
    if (h) Destroy(&h);
    h = nullptr;
  }
};

// BoomerAMG's setup, rebuilt every step as the particles move, is what amg costs. PETSc's
// PCHYPRE defaults (Falgout coarsening, classical interpolation, no truncation) build a heavy
// hierarchy on SPH stencils; HMIS coarsening with extended+i interpolation truncated to 4 entries
// per row and one level of aggressive coarsening (hypre's own advice for 3D and large stencils)
// cut the setup 2.6x on the closed erosion tank (9.9 to 3.6 ms/step), 1.4x on the 40k-particle
// Taylor-Green and 2.3x on the 351k 3D dam break, at 1-2 more iterations per step (2026-12-04,
// docs/fluid.md). Names as PETSc's options database keeps them (without the dash).
constexpr std::array<std::array<const char*, 2>, 4> kBoomerAmgDefaults{{
    {"pc_hypre_boomeramg_coarsen_type", "HMIS"},
    {"pc_hypre_boomeramg_interp_type", "ext+i"},
    {"pc_hypre_boomeramg_P_max", "4"},
    {"pc_hypre_boomeramg_agg_nl", "1"},
}};

// The built-in defaults where nobody set the option, the case file's options, then
// PETSC_OPTIONS again: the environment wins, as PETSc's command line wins over an options file.
void insert_options(const std::string& from_case) {
  for (const auto& [name, value] : kBoomerAmgDefaults) {
    const std::string option = std::string("-") + name;
    PetscBool set = PETSC_FALSE;
    check_petsc(PetscOptionsHasName(nullptr, nullptr, option.c_str(), &set),
                "looking up a BoomerAMG default");
    if (!set)
      check_petsc(PetscOptionsSetValue(nullptr, option.c_str(), value),
                  "setting a BoomerAMG default");
  }
  if (!from_case.empty())
    check_petsc(PetscOptionsInsertString(nullptr, from_case.c_str()),
                "reading [solver.petsc] options");
  if (const char* env = std::getenv("PETSC_OPTIONS"))
    check_petsc(PetscOptionsInsertString(nullptr, env), "reading PETSC_OPTIONS");
  // -log_view only collects events when logging started; PetscInitialize saw PETSC_OPTIONS but
  // not the case file.
  PetscBool log_view = PETSC_FALSE;
  PetscOptionsHasName(nullptr, nullptr, "-log_view", &log_view);
  if (log_view) PetscLogDefaultBegin();
}

class AmgSolver : public LinearSolver {
 public:
  explicit AmgSolver(const LinearSolverConfig& c) : config_(c) {
    insert_options(c.backend_options);
    MPI_Comm_size(PETSC_COMM_WORLD, &ranks_);
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
    comm_ = ranks_ > 1 ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
    check_petsc(KSPCreate(comm_, &ksp_.h), "creating the PPE solver");
    check_petsc(KSPSetType(ksp_.h, KSPBCGS), "setting BiCGSTAB");
    PC pc = nullptr;
    check_petsc(KSPGetPC(ksp_.h, &pc), "getting the preconditioner");
    check_petsc(PCSetType(pc, PCHYPRE), "setting PCHYPRE (is PETSc built with hypre?)");
    check_petsc(PCHYPRESetType(pc, "boomeramg"), "choosing BoomerAMG");
    check_petsc(KSPSetPCSide(ksp_.h, PC_RIGHT), "setting right preconditioning");
    check_petsc(KSPSetNormType(ksp_.h, KSP_NORM_UNPRECONDITIONED), "setting the residual norm");
    check_petsc(KSPSetInitialGuessNonzero(ksp_.h, PETSC_TRUE), "keeping the initial guess");
    check_petsc(KSPSetFromOptions(ksp_.h), "applying the PETSc options");
    ++created;
  }

  SolveStats solve(const SparseMatrix& A_in, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double reference) override {
    SolveStats s;
    set_layout(A_in, b, x);
    const double scale = std::max(norm_of_blocks(b), reference);
    if (scale == 0.0) {
      if (numbering_)
        x.head(rows_here_).setZero();
      else
        x.setZero();
      s.converged = true;
      return s;
    }
    SparseMatrix compressed;
    const SparseMatrix* A = &A_in;
    if (!A_in.isCompressed()) {
      compressed = A_in;
      compressed.makeCompressed();
      A = &compressed;
    }
    // A decomposed rank's own row count changes with migration while the total may not.
    bool resized = total_ != size_ || rows_.size() != static_cast<std::size_t>(rows_here_) + 1;
    if (ranks_ > 1) {
      int any = resized ? 1 : 0;
      MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, comm_);
      resized = any == 1;
    }
    load_matrix(*A);
    // This rank's rows as BoomerAMG expects them, diagonal positive (see row_sign_).
    signed_b_ = b.segment(first_, row_sign_.size()).cwiseProduct(row_sign_);

    const bool rebuild = resized || solves_since_setup_ >= std::max(config_.setup_reuse, 1) ||
                         last_iterations_ > 1.5 * iterations_after_setup_ + 2;
    // PETSc keeps the old local sizes in the preconditioner until it is reset.
    if (resized) check_petsc(KSPReset(ksp_.h), "resetting the solver for a new size");
    check_petsc(KSPSetOperators(ksp_.h, mat_.h, mat_.h), "giving the matrix to the solver");
    check_petsc(KSPSetReusePreconditioner(ksp_.h, rebuild ? PETSC_FALSE : PETSC_TRUE),
                "keeping the AMG hierarchy");
    // The test is the Eigen path's, |b - A x| <= tol max(|b|, reference), as an absolute
    // tolerance. No divergence test: the warm start (last step's pressure) can leave a residual
    // far above |b| when b is small, and PETSc's default would call that diverged.
    check_petsc(
        KSPSetTolerances(ksp_.h, 0.0, config_.tolerance * scale, 1e300, config_.max_iterations),
        "setting the tolerance");
    const auto t0 = std::chrono::steady_clock::now();
    check_petsc(KSPSetUp(ksp_.h), "setting up BoomerAMG");
    if (rebuild)
      s.setup_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // Each rank's rows of x are solved in place. A replicated system's blocks are then gathered,
    // so that every rank holds the whole pressure; a decomposed one's halo is the caller's.
    const int m = static_cast<int>(row_sign_.size());
    Vec bv = nullptr, xv = nullptr;
    if (ranks_ > 1) {
      check_petsc(VecCreateMPIWithArray(comm_, 1, m, total_, signed_b_.data(), &bv), "wrapping b");
      check_petsc(VecCreateMPIWithArray(comm_, 1, m, total_, x.data() + first_, &xv), "wrapping x");
    } else {
      check_petsc(VecCreateSeqWithArray(comm_, 1, m, signed_b_.data(), &bv), "wrapping b");
      check_petsc(VecCreateSeqWithArray(comm_, 1, m, x.data(), &xv), "wrapping x");
    }
    PetscErrorCode solved = KSPSolve(ksp_.h, bv, xv);
    // The halo's x is stale here: a decomposed system's residual is PETSc's own, the
    // unpreconditioned residual its convergence test read (right preconditioning). Computed
    // anew by a MatMult it cost 10-15 ms of a 170 ms/step solve (Taylor-Green, 160k, 2 ranks).
    double decomposed_residual = 0.0;
    if (!solved && numbering_) {
      PetscReal norm = 0.0;
      solved = KSPGetResidualNorm(ksp_.h, &norm);
      decomposed_residual = norm;
    }
    VecDestroy(&bv);
    VecDestroy(&xv);
    check_petsc(solved, "solving the PPE");
    if (ranks_ > 1 && !numbering_) gather_blocks(x);

    PetscInt its = 0;
    KSPGetIterationNumber(ksp_.h, &its);
    KSPConvergedReason why = KSP_CONVERGED_ITERATING;
    KSPGetConvergedReason(ksp_.h, &why);
    s.iterations = static_cast<int>(its);
    s.residual = (numbering_ ? decomposed_residual : residual_of_blocks(*A, b, x)) / scale;
    s.converged = why > 0 && s.residual <= config_.tolerance * (1.0 + 1e-6);
    if (why < 0) s.reason = std::string("PETSc: ") + KSPConvergedReasons[why];
    // Running out of iterations or a Krylov breakdown may still leave a usable pressure (GMRES
    // "broke down" at 5e-6 in the dam break): the caller decides by the residual. NaN cannot.
    s.broke_down = why == KSP_DIVERGED_NANORINF;

    last_iterations_ = s.iterations;
    if (rebuild) {
      iterations_after_setup_ = s.iterations;
      solves_since_setup_ = 1;
    } else {
      ++solves_since_setup_;
    }
    return s;
  }

 private:
  // This rank's rows and the whole system's size. Replicated: rows [first_, first_ + m) of A,
  // contiguous blocks of the particles' storage order, which is sorted by cell, so each rank's
  // rows are a compact region. Decomposed (number_globally): rows [0, owned), columns numbered
  // by the GlobalNumbering.
  void set_layout(const SparseMatrix& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
    const int n = static_cast<int>(A.rows());
    if (!numbering_) {
      first_ = block_start(n, rank_);
      rows_here_ = block_start(n, rank_ + 1) - first_;
      total_ = n;
      return;
    }
    const GlobalNumbering& g = *numbering_;
    if (static_cast<std::size_t>(A.cols()) != g.global.size() || n < g.owned ||
        b.size() < g.owned || x.size() < g.owned)
      throw std::invalid_argument("decomposed pressure system: " + std::to_string(A.rows()) +
                                  " x " + std::to_string(A.cols()) + " for " +
                                  std::to_string(g.owned) + " owned rows and " +
                                  std::to_string(g.global.size()) + " numbered columns");
    first_ = 0;
    rows_here_ = g.owned;
    total_ = g.total;
  }

  // Values in place while the pattern is the one the Mat holds, else a new Mat. Rows whose
  // diagonal is negative (the Laplacian rows; wall and Dirichlet rows have +1) enter negated: the
  // solution and |b - A x| stay the same, and AMG's strength of connection and its smoother see
  // one sign convention. With the mixed signs the 2D dam break stalled in the PPE.
  void load_matrix(const SparseMatrix& A) {
    const int m = rows_here_;
    const int* outer = A.outerIndexPtr() + first_;
    const int* inner = A.innerIndexPtr() + outer[0];
    const double* v = A.valuePtr() + outer[0];
    const int nnz = outer[m] - outer[0];
    row_sign_.resize(m);
    for (int i = 0; i < m; ++i) {
      double diagonal = 0.0;
      for (int k = outer[i] - outer[0]; k < outer[i + 1] - outer[0]; ++k)
        if (inner[k] == first_ + i) diagonal = v[k];
      row_sign_[i] = diagonal < 0.0 ? -1.0 : 1.0;
    }
    // The columns as the Mat numbers them: a decomposed system's local columns become global
    // numbers, which no longer ascend along a row (halo columns); each row is sorted again, and
    // `entry_` remembers where each entry's value sits in A.
    std::vector<PetscInt> columns(inner, inner + nnz);
    entry_.resize(nnz);
    for (int k = 0; k < nnz; ++k) entry_[k] = k;
    if (numbering_) {
      const auto& global = numbering_->global;
      for (int k = 0; k < nnz; ++k) columns[k] = static_cast<PetscInt>(global[inner[k]]);
      for (int i = 0; i < m; ++i) {
        const auto b = entry_.begin() + (outer[i] - outer[0]);
        const auto e = entry_.begin() + (outer[i + 1] - outer[0]);
        std::sort(b, e, [&](int p, int q) { return columns[p] < columns[q]; });
      }
      std::vector<PetscInt> sorted(nnz);
      for (int k = 0; k < nnz; ++k) sorted[k] = columns[entry_[k]];
      columns.swap(sorted);
    }
    signed_values_.resize(nnz);
    for (int i = 0; i < m; ++i)
      for (int k = outer[i] - outer[0]; k < outer[i + 1] - outer[0]; ++k)
        signed_values_[k] = row_sign_[i] * v[entry_[k]];
    bool same_pattern =
        mat_.h && total_ == size_ && static_cast<int>(rows_.size()) == m + 1 && columns == columns_;
    for (int i = 0; same_pattern && i <= m; ++i) same_pattern = outer[i] - outer[0] == rows_[i];
    // Every rank must take the same branch: a new Mat is made collectively.
    if (ranks_ > 1) {
      int same = same_pattern ? 1 : 0;
      MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPI_INT, MPI_MIN, comm_);
      same_pattern = same == 1;
    }
    if (same_pattern) {
      update_values(m);
      return;
    }
    mat_.reset();
    size_ = total_;
    rows_.resize(m + 1);
    for (int i = 0; i <= m; ++i) rows_[i] = outer[i] - outer[0];
    columns_.swap(columns);
    if (ranks_ > 1) {
      // Filled from the CSR arrays in one go (row lengths = neighbour counts).
      check_petsc(MatCreateMPIAIJWithArrays(comm_, m, m, total_, total_, rows_.data(),
                                            columns_.data(), signed_values_.data(), &mat_.h),
                  "filling the distributed matrix");
      return;
    }
    check_petsc(MatCreate(comm_, &mat_.h), "creating the matrix");
    check_petsc(MatSetSizes(mat_.h, m, m, m, m), "sizing the matrix");
    check_petsc(MatSetType(mat_.h, MATSEQAIJ), "choosing AIJ storage");
    check_petsc(
        MatSeqAIJSetPreallocationCSR(mat_.h, rows_.data(), columns_.data(), signed_values_.data()),
        "filling the matrix");
  }

  void update_values(int m) {
    if (ranks_ > 1) {
      check_petsc(MatUpdateMPIAIJWithArrays(mat_.h, m, m, total_, total_, rows_.data(),
                                            columns_.data(), signed_values_.data()),
                  "updating the distributed matrix");
      return;
    }
    PetscScalar* values = nullptr;
    check_petsc(MatSeqAIJGetArray(mat_.h, &values), "updating the matrix");
    std::memcpy(values, signed_values_.data(), sizeof(double) * signed_values_.size());
    check_petsc(MatSeqAIJRestoreArray(mat_.h, &values), "updating the matrix");
  }

  int block_start(int n, int r) const { return isph::block_start(n, r, ranks_); }

  bool distributed_rows() const override { return ranks_ > 1; }

  void number_globally(std::shared_ptr<const GlobalNumbering> numbering) override {
    numbering_ = std::move(numbering);
  }

  // |b| and |b - A x| from every rank's own rows: the rows of other blocks may not be
  // assembled here.
  double norm_of_blocks(const Eigen::VectorXd& b) const {
    if (ranks_ == 1 && !numbering_) return b.norm();
    return norm_from_squares(b.segment(first_, rows_here_).squaredNorm());
  }
  double residual_of_blocks(const SparseMatrix& A, const Eigen::VectorXd& b,
                            const Eigen::VectorXd& x) const {
    if (ranks_ == 1) return (b - A * x).norm();
    const Eigen::VectorXd r = b.segment(first_, rows_here_) - A.middleRows(first_, rows_here_) * x;
    return norm_from_squares(r.squaredNorm());
  }
  // sqrt of the sum over the ranks of their squared norms.
  double norm_from_squares(double squares) const {
    MPI_Allreduce(MPI_IN_PLACE, &squares, 1, MPI_DOUBLE, MPI_SUM, comm_);
    return std::sqrt(squares);
  }

  // Every rank's block of x to every rank.
  void gather_blocks(Eigen::VectorXd& x) const {
    const int n = static_cast<int>(x.size());
    std::vector<int> counts(ranks_), starts(ranks_);
    for (int r = 0; r < ranks_; ++r) {
      starts[r] = block_start(n, r);
      counts[r] = block_start(n, r + 1) - starts[r];
    }
    // MPI's default error handler aborts every rank on failure: nothing to check here.
    MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, x.data(), counts.data(), starts.data(),
                   MPI_DOUBLE, comm_);
  }

  LinearSolverConfig config_;
  Owned<KSP, KSPDestroy> ksp_;
  Owned<Mat, MatDestroy> mat_;
  MPI_Comm comm_ = PETSC_COMM_SELF;  // PETSC_COMM_WORLD when the run has several ranks
  int ranks_ = 1, rank_ = 0;
  std::shared_ptr<const GlobalNumbering> numbering_;  // set: decomposed systems
  PetscInt size_ = -1;                    // rows of the whole system the Mat holds (-1: none yet)
  PetscInt total_ = 0;                    // rows of the whole system being solved
  int first_ = 0;                         // this rank's first row of A (local index)
  int rows_here_ = 0;                     // this rank's rows
  std::vector<PetscInt> rows_, columns_;  // this rank's rows of the Mat (local row pointers)
  std::vector<int> entry_;                // per Mat entry of this rank: its position in A's row
  Eigen::VectorXd row_sign_, signed_b_;
  std::vector<double> signed_values_;
  int solves_since_setup_ = 0;
  int iterations_after_setup_ = 0;
  int last_iterations_ = 0;
};

}  // namespace

bool is_builtin_amg_option(const std::string& name) {
  for (const auto& d : kBoomerAmgDefaults)
    if (name == d[0]) return true;
  return false;
}

std::unique_ptr<LinearSolver> make_amg_solver(const LinearSolverConfig& config) {
  return std::make_unique<AmgSolver>(config);
}

int amg_solvers_created() { return created; }

}  // namespace isph
