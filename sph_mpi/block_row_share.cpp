#include "block_row_share.hpp"

#include <stdexcept>
#include <string>

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
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(parts_), starts(parts_, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  for (int r = 1; r < parts_; ++r) starts[r] = starts[r - 1] + counts[r - 1];
  std::vector<char> all(static_cast<std::size_t>(starts.back()) + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), starts.data(), MPI_BYTE,
                 comm_);
  return all;
}

double BlockRowShare::sum(double x) const {
  MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return x;
}

void BlockRowShare::sum_in_place(double* data, std::size_t count) const {
  MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(count), MPI_DOUBLE, MPI_SUM, comm_);
}

double BlockRowShare::max(double x) const {
  MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return x;
}

}  // namespace isph
