#pragma once
// The rows of a step shared between the ranks of a communicator in contiguous blocks
// (sph/row_share.hpp): every rank holds every particle and computes its block of each stage.
#include <mpi.h>

#include "row_share.hpp"

namespace isph {

class BlockRowShare : public RowShare {
 public:
  explicit BlockRowShare(MPI_Comm comm);
  int parts() const override { return parts_; }
  int part() const override { return part_; }
  void exchange_rows(void* data, std::size_t row_bytes, int n) const override;
  std::vector<char> concatenate_bytes(const std::vector<char>& mine) const override;
  double sum(double x) const override;
  void sum_in_place(double* data, std::size_t count) const override;
  double max(double x) const override;

 private:
  MPI_Comm comm_;
  int parts_ = 1, part_ = 0;
};

}  // namespace isph
