// GoogleTest main for tests that start LIGGGHTS: MPI must be up before LAMMPS is constructed
// (the driver's main does the same for `isphdem`).
#include <gtest/gtest.h>
#include <mpi.h>

int main(int argc, char** argv) {
  int provided = 0;  // dem.exchange = "staggered" runs LIGGGHTS on a second thread
  MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);
  ::testing::InitGoogleTest(&argc, argv);
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  return rc;
}
