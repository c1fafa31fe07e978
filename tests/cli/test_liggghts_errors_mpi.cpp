// LIGGGHTS errors under mpirun: the failing rank's message reaches stderr exactly once, whether
// one rank fails (Error::one, then MPI_Abort) or all do (Error::all, then exit on every rank).
#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

// Open MPI refuses root unless told (CI runs as root on 2 cores): set here, in the harness only.
Result mpirun_dem(const std::string& script_args) {
  const std::string script =
      std::string(ISPHDEM_SOURCE_DIR) + "/tests/dem/inputs/errors/in.zero_diameter_rank1";
  const auto dir = scratch("liggghts_errors_mpi");
  const Result r =
      run_shell("cd " + dir.string() +
                " && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun "
                "--oversubscribe -np 2 " +
                isphdem() + " dem " + script + " -log none -screen screen.txt " + script_args);
  std::printf("%s", r.output.c_str());
  return r;
}

TEST(LiggghtsErrorsMpi, OneRankFailingIsShownOnceWithItsRank) {
  const Result r = mpirun_dem("");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ERROR on proc 1: Fix nve/sphere requires extended particles"), 1);
  EXPECT_EQ(count(r.output, "isphdem: LIGGGHTS stopped the run"), 1);
  EXPECT_NE(r.output.find("while running `run 10`"), std::string::npos);
}

TEST(LiggghtsErrorsMpi, AllRanksFailingIsShownOnce) {
  const Result r = mpirun_dem("-var bad 1");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ERROR: Incorrect args for pair coefficients"), 1);
  EXPECT_EQ(count(r.output, "isphdem: LIGGGHTS stopped the run"), 1);
  EXPECT_EQ(count(r.output, "hint: granular pair styles take no coefficients"), 1);
}

}  // namespace
}  // namespace isphdem::cli
