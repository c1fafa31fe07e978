#include "io/rank_agreement.hpp"

#include <stdexcept>
#include <string>

namespace isphdem {

int ranks_of(MPI_Comm comm) {
  int n = 1;
  if (comm != MPI_COMM_NULL) MPI_Comm_size(comm, &n);
  return n;
}

int rank_in(MPI_Comm comm) {
  int r = 0;
  if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &r);
  return r;
}

void agree(MPI_Comm comm, const std::function<void()>& local) {
  const int ranks = ranks_of(comm);
  if (ranks == 1) {
    local();
    return;
  }
  enum Kind : int { kNone, kInvalid, kRuntime };
  int kind = kNone;
  std::string message;
  try {
    local();
  } catch (const std::invalid_argument& e) {
    kind = kInvalid;
    message = e.what();
  } catch (const std::exception& e) {
    kind = kRuntime;
    message = e.what();
  }
  const int me = rank_in(comm);
  int failed = kind == kNone ? ranks : me;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MIN, comm);
  if (failed == ranks) return;
  int length = static_cast<int>(message.size());
  MPI_Bcast(&kind, 1, MPI_INT, failed, comm);
  MPI_Bcast(&length, 1, MPI_INT, failed, comm);
  message.resize(static_cast<std::size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, failed, comm);
  message = "rank " + std::to_string(failed) + ": " + message;
  if (kind == kInvalid) throw std::invalid_argument(message);
  throw std::runtime_error(message);
}

}  // namespace isphdem
