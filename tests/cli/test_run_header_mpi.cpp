// `mpirun -np 2 isphdem run`: the run's header says the ranks and how they share the fluid, and a
// run whose fluid every rank steps whole (a pressure preconditioner that does not decompose, as
// the default jacobi and the erosion cases' ilu0) says so at its start, with the setting that
// shares it (docs/parallel.md). Nothing LIGGGHTS prints reaches the output on any rank.
#include <gtest/gtest.h>

#include "mpi_support.hpp"

namespace isphdem::cli {
namespace {

const char* kReplicated = "\n  ranks: 2, fluid replicated (every rank steps all of it)\n";

std::string warning(const std::string& preconditioner) {
  return "isphdem run: warning: solver.preconditioner = \"" + preconditioner +
         "\" does not decompose: each of the 2 ranks steps the whole fluid, so the fluid runs no "
         "faster than on one; set --set solver.preconditioner=amg (solver.preconditioner = "
         "\"amg\" in the case) to share it over the ranks\n";
}

const std::string kVortex = " --set particles.spacing=0.05 --set time.end=0.01";

TEST(RunHeaderMpi, ReplicatedFluidSaysSoAndWhatToSet) {
  const auto dir = scratch("run_header_mpi_replicated");
  const Result r = mpirun_run(2, example("taylor_green_2d") + " --out " + dir.string() + kVortex);
  std::printf("%s", r.output.c_str());
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(count(r.output, kReplicated), 1);
  EXPECT_EQ(count(r.output, warning("jacobi")), 1);
}

TEST(RunHeaderMpi, QuietRunStillWarns) {
  const auto dir = scratch("run_header_mpi_quiet");
  const Result r = mpirun_run(2, example("taylor_green_2d") + " --out " + dir.string() + kVortex +
                                     " --quiet --set solver.preconditioner=ilu0");
  std::printf("%s", r.output.c_str());
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(count(r.output, "ranks: 2"), 0);
  EXPECT_EQ(count(r.output, warning("ilu0")), 1);
}

TEST(RunHeaderMpi, DecomposedAndSharedRowsSayWhichWithoutAWarning) {
  const auto dir = scratch("run_header_mpi_amg");
  const std::string amg = kVortex + " --set solver.preconditioner=amg";
  const Result d = mpirun_run(2, example("taylor_green_2d") + " --out " + dir.string() + amg);
  std::printf("%s", d.output.c_str());
  ASSERT_EQ(d.exit_code, 0);
  EXPECT_EQ(count(d.output, "\n  ranks: 2, fluid decomposed (each rank steps its own region)\n"),
            1);
  EXPECT_EQ(count(d.output, "warning"), 0);
  const Result s = mpirun_run(2, example("taylor_green_2d") + " --out " + dir.string() + amg +
                                     " --set parallel.decompose=false");
  std::printf("%s", s.output.c_str());
  ASSERT_EQ(s.exit_code, 0);
  EXPECT_EQ(count(s.output,
                  "\n  ranks: 2, fluid held by every rank, each computing its block of rows "
                  "(parallel.decompose = false)\n"),
            1);
  EXPECT_EQ(count(s.output, "warning"), 0);
}

// A coupled case whose script reads a restart (LIGGGHTS printed "version 3 8" once per rank),
// with the erosion cases' ilu0.
TEST(RunHeaderMpi, CoupledErosionCaseSaysItsRanksAndNothingOfLiggghts) {
  ASSERT_TRUE(std::filesystem::exists(reduced_packing_dir() / "packing_reduced.restart"))
      << "pack the layer first (ctest runs the erosion_reduced_packing fixture)";
  const auto out = scratch("run_header_mpi_coupled");
  const Result r = mpirun_run(2, reduced_case() + " --out " + out.string() +
                                     " --set time.end=0.002 --set output.interval=0.002");
  std::printf("%s", r.output.c_str());
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(count(r.output, kReplicated), 1);
  EXPECT_EQ(count(r.output, warning("ilu0")), 1);
  EXPECT_EQ(count(r.output, "version 3 8"), 0);
}

}  // namespace
}  // namespace isphdem::cli
