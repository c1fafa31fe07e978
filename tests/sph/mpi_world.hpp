#pragma once
// MPI_COMM_WORLD as the sph_mpi tests ask about it: this rank, the rank count, and sums over all
// ranks.
#include <mpi.h>

namespace isph::test {

inline int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

inline int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

inline long global_sum(long v) {
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  return v;
}

}  // namespace isph::test
