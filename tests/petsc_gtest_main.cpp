// gtest main for tests that may solve the PPE with solver.preconditioner = "amg": PETSc lives
// for the whole test binary, as it does for the whole of `isphdem`.
#include <gtest/gtest.h>

#include "petsc_session.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  isph::PetscSession petsc;
  return RUN_ALL_TESTS();
}
