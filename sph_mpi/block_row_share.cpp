#include "block_row_share.hpp"

#include <stdexcept>
#include <string>

#include "mpi_collectives.hpp"

namespace isph {

BlockRowShare::BlockRowShare(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_size(comm_, &parts_);
  MPI_Comm_rank(comm_, &part_);
}

void BlockRowShare::exchange_rows(void* data, std::size_t row_bytes, int n) const {
  std::vector<int> counts(parts_), starts(parts_);
  for (int r = 0; r < parts_; ++r) {
    const long first = block_start(n, r, parts_), last = block_start(n, r + 1, parts_);
    // Byte counts are ints in MPI: a block beyond 2 GiB is not a block of one node's rows.
    if ((last - first) * static_cast<long>(row_bytes) > 2147483647L ||
        first * static_cast<long>(row_bytes) > 2147483647L)
      throw std::length_error("row exchange of " + std::to_string(n) + " rows of " +
                              std::to_string(row_bytes) + " bytes exceeds MPI's int counts");
    starts[r] = static_cast<int>(first * static_cast<long>(row_bytes));
    counts[r] = static_cast<int>((last - first) * static_cast<long>(row_bytes));
  }
  MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, data, counts.data(), starts.data(), MPI_BYTE,
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
