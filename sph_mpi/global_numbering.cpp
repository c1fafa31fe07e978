#include "global_numbering.hpp"

namespace isph {

GlobalNumbering number_globally(MPI_Comm comm, const HaloPlan& plan) {
  GlobalNumbering g;
  g.owned = plan.owned;
  int64_t owned = plan.owned, start = 0;
  MPI_Exscan(&owned, &start, 1, MPI_INT64_T, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) start = 0;  // MPI_Exscan leaves rank 0's result undefined
  MPI_Allreduce(&owned, &g.total, 1, MPI_INT64_T, MPI_SUM, comm);
  g.global.resize(plan.owned);
  for (int i = 0; i < plan.owned; ++i) g.global[i] = start + i;
  refresh_halo(comm, plan, g.global);  // appends the halo's numbers from their owners
  return g;
}

}  // namespace isph
