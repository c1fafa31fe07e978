// Making the outcome of one step of writing common to the ranks that write a file together: a
// rank that fails must not leave the others waiting in the next collective call, and every rank
// should stop with the message of the one that failed.
#pragma once

#include <mpi.h>

#include <functional>

namespace isphdem {

// Runs `local` on every rank of `comm`. If it throws on any rank, every rank throws the lowest
// failing rank's exception: std::invalid_argument or std::runtime_error as it was (any other
// std::exception becomes a std::runtime_error), its message prefixed with "rank R: " on more
// than one rank. Collective over `comm`; with MPI_COMM_NULL it just runs `local`.
void agree(MPI_Comm comm, const std::function<void()>& local);

// Size and rank of `comm` (1 and 0 for MPI_COMM_NULL).
int ranks_of(MPI_Comm comm);
int rank_in(MPI_Comm comm);

}  // namespace isphdem
