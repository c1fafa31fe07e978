#include "block_row_share.hpp"

#include "mpi_collectives.hpp"

namespace isph {

BlockRowShare::BlockRowShare(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_size(comm_, &parts_);
  MPI_Comm_rank(comm_, &part_);
}

void BlockRowShare::exchange_rows(void* data, std::size_t row_bytes, int n) const {
  std::vector<int> counts(parts_), starts(parts_);
  for (int r = 0; r < parts_; ++r) {
    starts[r] = block_start(n, r, parts_);
    counts[r] = block_start(n, r + 1, parts_) - starts[r];
  }
  const collectives::ItemType row(row_bytes);
  MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, data, counts.data(), starts.data(), row.get(),
                 comm_);
}

std::vector<char> BlockRowShare::concatenate_bytes(const std::vector<char>& mine) const {
  return collectives::concatenate(comm_, mine);
}

double BlockRowShare::sum(double x) const { return collectives::sum(comm_, x); }

void BlockRowShare::sum_in_place(double* data, std::size_t count) const {
  collectives::sum_in_place(comm_, data, count);
}

double BlockRowShare::max(double x) const { return collectives::max(comm_, x); }

}  // namespace isph
