#pragma once
// The reductions and the concatenation both RowShare implementations of sph_mpi/ offer.
#include <mpi.h>

#include <cstddef>
#include <vector>

namespace isph::collectives {

// Every process's bytes, in the order of the ranks, to every process.
std::vector<char> concatenate(MPI_Comm comm, const std::vector<char>& mine);
double sum(MPI_Comm comm, double x);
void sum_in_place(MPI_Comm comm, double* data, std::size_t count);
double max(MPI_Comm comm, double x);

}  // namespace isph::collectives
