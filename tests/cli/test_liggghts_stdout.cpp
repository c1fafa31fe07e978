// What LIGGGHTS prints belongs in its screen file (or on stderr, for its errors), never on
// isphdem's stdout. LIGGGHTS 3.8's read_restart prints "version 3 8" with a bare printf on every
// rank, whatever -screen says: every run of a case whose DEM script reads a restart (the erosion
// cases) began its stdout with that line (coupling/dem/liggghts_output_tee.hpp).
#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

TEST(LiggghtsStdout, RestartVersionLineGoesToTheScreenFile) {
  ASSERT_TRUE(std::filesystem::exists(reduced_packing_dir() / "packing_reduced.restart"))
      << "pack the layer first (ctest runs the erosion_reduced_packing fixture)";
  const auto out = scratch("liggghts_stdout");
  // stdout alone: stderr to a file of its own.
  const Result r =
      run_shell("(" + isphdem() + " run " + reduced_case() + " --out " + (out / "run").string() +
                " --set time.end=0.002 --set output.interval=0.002 2> " +
                (out / "stderr.txt").string() + ")");
  std::printf("stdout:\n%s\nstderr:\n%s", r.output.c_str(), read_file(out / "stderr.txt").c_str());
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output.rfind("isphdem run: ", 0), 0u) << "stdout starts with isphdem's header";
  EXPECT_EQ(count(r.output, "version 3 8"), 0);
  EXPECT_EQ(count(read_file(out / "stderr.txt"), "version 3 8"), 0);
  EXPECT_EQ(count(read_file(out / "run" / "liggghts.screen"), "\nversion 3 8\n"), 1);
}

}  // namespace
}  // namespace isphdem::cli
