// The communicator LIGGGHTS runs on: MPI_COMM_WORLD, or a duplicate of it when the DEM steps on a
// thread of its own beside the fluid (dem.exchange = "staggered"), so that the two threads'
// collectives never meet on one communicator (MPI forbids it, even with MPI_THREAD_MULTIPLE).
#ifndef ISPHDEM_DEM_COMMUNICATOR_HPP
#define ISPHDEM_DEM_COMMUNICATOR_HPP

#include <mpi.h>

namespace isphdem {

class DemCommunicator {
 public:
  explicit DemCommunicator(bool own) {
    if (own) MPI_Comm_dup(MPI_COMM_WORLD, &comm_);
  }
  ~DemCommunicator() {
    if (comm_ != MPI_COMM_WORLD) MPI_Comm_free(&comm_);
  }
  DemCommunicator(const DemCommunicator&) = delete;
  DemCommunicator& operator=(const DemCommunicator&) = delete;
  MPI_Comm get() const { return comm_; }

 private:
  MPI_Comm comm_ = MPI_COMM_WORLD;
};

}  // namespace isphdem

#endif
