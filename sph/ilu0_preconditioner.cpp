#include "ilu0_preconditioner.hpp"

#include <algorithm>
#include <cmath>

namespace isph {

void Ilu0Preconditioner::copy_compressed(Eigen::Index rows, Eigen::Index cols,
                                         Eigen::Index nonzeros, const StorageIndex* outer,
                                         const StorageIndex* inner, const double* values) {
  Matrix A(rows, cols);
  A.resizeNonZeros(nonzeros);
  std::copy(outer, outer + rows + 1, A.outerIndexPtr());
  std::copy(inner, inner + nonzeros, A.innerIndexPtr());
  std::copy(values, values + nonzeros, A.valuePtr());
  factor(std::move(A));
}

void Ilu0Preconditioner::factor(Matrix A) {
  A.makeCompressed();
  lu_ = std::move(A);
  const StorageIndex n = static_cast<StorageIndex>(lu_.rows());
  const StorageIndex* outer = lu_.outerIndexPtr();
  const StorageIndex* inner = lu_.innerIndexPtr();
  double* val = lu_.valuePtr();
  diag_.assign(n, -1);
  info_ = Eigen::Success;
  for (StorageIndex i = 0; i < n; ++i)
    for (StorageIndex p = outer[i]; p < outer[i + 1]; ++p)
      if (inner[p] == i) diag_[i] = p;
  for (StorageIndex i = 0; i < n; ++i)
    if (diag_[i] < 0) {
      info_ = Eigen::NumericalIssue;  // a row without a diagonal entry: not a pressure matrix
      return;
    }

  // Row-wise (IKJ) elimination restricted to the pattern; `where` maps a column of row i to its
  // position (rows are sorted by column, as Eigen's compressed storage keeps them).
  std::vector<StorageIndex> where(n, -1);
  for (StorageIndex i = 0; i < n; ++i) {
    for (StorageIndex p = outer[i]; p < outer[i + 1]; ++p) where[inner[p]] = p;
    for (StorageIndex p = outer[i]; p < diag_[i]; ++p) {
      const StorageIndex k = inner[p];
      const double pivot = val[diag_[k]];
      val[p] /= pivot;
      const double lik = val[p];
      if (lik == 0.0) continue;
      for (StorageIndex q = diag_[k] + 1; q < outer[k + 1]; ++q) {
        const StorageIndex w = where[inner[q]];
        if (w >= 0) val[w] -= lik * val[q];
      }
    }
    // A vanishing pivot (possible for an indefinite row) would make the solve blow up; keep
    // the preconditioner usable with the row's own scale instead.
    double& d = val[diag_[i]];
    if (std::abs(d) < 1e-14) {
      double s = 0.0;
      for (StorageIndex p = outer[i]; p < outer[i + 1]; ++p) s = std::max(s, std::abs(val[p]));
      d = s > 0.0 ? 1e-8 * s : 1.0;
    }
    for (StorageIndex p = outer[i]; p < outer[i + 1]; ++p) where[inner[p]] = -1;
  }
}

void Ilu0Preconditioner::apply(Eigen::VectorXd& x) const {
  const StorageIndex n = static_cast<StorageIndex>(lu_.rows());
  const StorageIndex* outer = lu_.outerIndexPtr();
  const StorageIndex* inner = lu_.innerIndexPtr();
  const double* val = lu_.valuePtr();
  for (StorageIndex i = 0; i < n; ++i) {
    double s = x[i];
    for (StorageIndex p = outer[i]; p < diag_[i]; ++p) s -= val[p] * x[inner[p]];
    x[i] = s;
  }
  for (StorageIndex i = n - 1; i >= 0; --i) {
    double s = x[i];
    for (StorageIndex p = diag_[i] + 1; p < outer[i + 1]; ++p) s -= val[p] * x[inner[p]];
    x[i] = s / val[diag_[i]];
  }
}

}  // namespace isph
