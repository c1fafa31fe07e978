// Checkpoint files and directories (coupling/io/checkpoint.hpp): arrays read back with the same
// bits, the newest two checkpoints kept, staged ones a killed run left removed.
#include "io/checkpoint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "output_test_support.hpp"

namespace {

using namespace isphdem;
using output_test::file_names;
using output_test::scratch_dir;
namespace fs = std::filesystem;

TEST(Checkpoint, ArraysReadBackWithTheSameBits) {
  const auto file = scratch_dir() / "rank_0.h5";
  CheckpointArrays a;
  a.reals["x"] = {0.1,
                  -0.0,
                  1e-310,
                  std::numeric_limits<double>::max(),
                  std::numeric_limits<double>::quiet_NaN(),
                  -INFINITY};
  a.reals["empty"] = {};
  a.set("time", 0.30000000000000004);
  a.integers["id"] = {0, -1, std::numeric_limits<std::int64_t>::max()};
  a.set_integer("steps", 1234567);
  write_checkpoint_arrays(file, a);
  const CheckpointArrays b = read_checkpoint_arrays(file);
  ASSERT_EQ(b.reals.size(), 3u);
  ASSERT_EQ(b.real_array("x").size(), a.reals["x"].size());
  EXPECT_EQ(std::memcmp(b.real_array("x").data(), a.reals["x"].data(), 6 * sizeof(double)), 0);
  EXPECT_TRUE(b.real_array("empty").empty());
  EXPECT_EQ(b.real("time"), 0.30000000000000004);
  EXPECT_EQ(b.integer_array("id"), a.integers["id"]);
  EXPECT_EQ(b.integer("steps"), 1234567);
  EXPECT_THROW(b.real("missing"), std::runtime_error);
  EXPECT_THROW(b.real("x"), std::runtime_error);  // not one value
}

TEST(Checkpoint, TheNewestTwoAreKeptAndStagedLeftoversGo) {
  const auto dir = scratch_dir();
  for (long step : {100L, 200L, 300L}) {
    const fs::path staged = stage_checkpoint(dir, step);
    write_checkpoint_arrays(staged / "rank_0.h5", CheckpointArrays{});
    EXPECT_EQ(commit_checkpoint(dir, step, 2), dir / checkpoint_name(step));
  }
  EXPECT_EQ(file_names(dir), (std::set<std::string>{"checkpoint_00000200", "checkpoint_00000300"}));
  const auto all = list_checkpoints(dir);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all.back().first, 300);
  // Killed while writing the checkpoint of step 400: only the staged directory is left.
  stage_checkpoint(dir, 400);
  EXPECT_EQ(list_checkpoints(dir).back().first, 300);
  remove_checkpoints(dir, false);
  EXPECT_EQ(file_names(dir), (std::set<std::string>{"checkpoint_00000200", "checkpoint_00000300"}));
  remove_checkpoints(dir, true);  // a fresh run
  EXPECT_TRUE(file_names(dir).empty());
}

}  // namespace
