#include "run/replicated_ranks.hpp"

#include <mpi.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "block_row_share.hpp"
#include "case/case_file.hpp"
#include "format_number.hpp"
#include "isph_solver.hpp"

namespace isphdem {

template <int Dim>
void check_replicas(const isph::Particles<Dim>& P, long step) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (ranks == 1) return;
  // Sums in storage order: equal copies give bit-equal sums; different ones almost never do.
  std::array<double, 4> sum{double(P.size()), 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < P.size(); ++i) {
    sum[1] += P.x[i].sum();
    sum[2] += P.v[i].sum();
    sum[3] += P.p[i];
  }
  std::array<double, 4> lo = sum, hi = sum;
  MPI_Allreduce(MPI_IN_PLACE, lo.data(), 4, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, hi.data(), 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  if (lo == hi) return;
  const char* what[] = {"particle counts", "sums of positions", "sums of velocities",
                        "sums of pressures"};
  int k = 0;
  while (lo[k] == hi[k]) ++k;
  throw isph::SimulationError(
      "the ranks' copies of the fluid differ at step " + std::to_string(step) + " (" + what[k] +
          " from " + isph::format_number(lo[k], 17) + " to " + isph::format_number(hi[k], 17) +
          "): every rank must hold the same case and step the fluid alike (they do with any "
          "OMP_NUM_THREADS); if they ran one case, this is a bug of isphdem: run on one rank "
          "and report it",
      "replicas");
}

namespace {

// Runs `write`; if it throws while other ranks run, `who` prints the message and every rank is
// stopped. On one rank the exception goes on to the caller.
void write_or_stop_all(const std::function<void()>& write, bool speaks, const char* who) {
  try {
    write();
  } catch (const std::exception& e) {
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (ranks == 1) throw;
    // A rank that does not speak first gives the speaking one time to stop everything.
    if (!speaks) std::this_thread::sleep_for(std::chrono::seconds(2));
    std::fprintf(stderr,
                 "isphdem run: %s could not write the output: %s\n"
                 "  stopping all %d ranks; the snapshots written before are complete.\n",
                 who, e.what(), ranks);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
}

}  // namespace

void agree_on_failure(bool collective, const std::function<void()>& make) {
  if (!collective) return make();
  std::string failure;
  try {
    make();
  } catch (const std::exception& e) {
    failure = e.what();
    if (failure.empty()) failure = "an error without a message";
  }
  const std::string first = isph::BlockRowShare(MPI_COMM_WORLD).first_text(failure);
  if (!first.empty()) throw CaseError(first);
}

void write_on_rank_zero(int rank, const std::function<void()>& write) {
  if (rank == 0) write_or_stop_all(write, true, "rank 0");
}

void write_collectively(int rank, const std::function<void()>& write) {
  // The writer throws one message (naming the rank it came from) on every rank, and rank 0 says
  // it; a rank that failed alone, before the writer could agree, says its own.
  write_or_stop_all(write, rank == 0, "the ranks");
}

template void check_replicas<2>(const isph::Particles<2>&, long);
template void check_replicas<3>(const isph::Particles<3>&, long);

}  // namespace isphdem
