#include "mpi_collectives.hpp"

namespace isph::collectives {

std::vector<char> concatenate(MPI_Comm comm, const std::vector<char>& mine) {
  int parts = 1;
  MPI_Comm_size(comm, &parts);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(parts), starts(parts, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < parts; ++r) starts[r] = starts[r - 1] + counts[r - 1];
  std::vector<char> all(static_cast<std::size_t>(starts.back()) + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), starts.data(), MPI_BYTE,
                 comm);
  return all;
}

double sum(MPI_Comm comm, double x) {
  MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_SUM, comm);
  return x;
}

void sum_in_place(MPI_Comm comm, double* data, std::size_t count) {
  MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(count), MPI_DOUBLE, MPI_SUM, comm);
}

double max(MPI_Comm comm, double x) {
  MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, comm);
  return x;
}

}  // namespace isph::collectives
