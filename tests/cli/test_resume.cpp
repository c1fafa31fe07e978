// `isphdem run --resume` (issue 47): a run stopped at a checkpoint, by SIGTERM, or killed hard,
// then resumed, ends with the same bits as the run that was never stopped, and its
// diagnostics.csv and fluid.xdmf hold each time once.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "resume_support.hpp"

namespace isphdem::cli {
namespace {

namespace fs = std::filesystem;

// Taylor-Green at 40 x 40 (automatic dt), to t = 0.4 s: snapshots every 0.05 s, checkpoints
// every 0.1 s.
const std::string kCase = example("taylor_green_2d") +
                          " --quiet --set particles.spacing=0.025 --set output.interval=0.05"
                          " --set output.checkpoint_interval=0.1 --set output.diagnostics_every=3";

class Resume : public ::testing::Test {
 protected:
  // The run never stopped, each test its own (ctest runs the tests side by side).
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    reference_ = scratch(std::string("resume_reference_") + test->name()) / "out";
    const Result r = run(kCase + " --set time.end=0.4 --out " + reference_.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const fs::path& reference() const { return reference_; }

  void expect_same_as_reference(const fs::path& out) const {
    const auto ours = files_named(out, "snap_"), theirs = files_named(reference(), "snap_");
    ASSERT_EQ(ours.size(), theirs.size());
    ASSERT_EQ(ours.size(), 9u);  // t = 0, 0.05, ..., 0.4
    expect_same_snapshot(theirs.back(), ours.back());
    const auto rows = diagnostics_without_wall(out), want = diagnostics_without_wall(reference());
    EXPECT_EQ(rows.size(), want.size());
    EXPECT_TRUE(rows == want) << "diagnostics.csv differs from the run never stopped";
    EXPECT_EQ(xdmf_times(out), xdmf_times(reference()));
    EXPECT_EQ(xdmf_times(out).size(), 9u);
    EXPECT_NE(read_file(out / "result.json").find("\"status\": \"finished\""), std::string::npos);
  }

 private:
  fs::path reference_;
};

TEST_F(Resume, ExtendingAFinishedRunEqualsOneRun) {
  const fs::path out = scratch("resume_extend") / "out";
  const Result first = run(kCase + " --set time.end=0.2 --out " + out.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  // Checkpoints at 0.1 s and at the end, 0.2 s: the last two.
  const auto kept = files_named(out, "checkpoint_");
  ASSERT_EQ(kept.size(), 2u);
  const Result more = run(kCase + " --set time.end=0.4 --out " + out.string() + " --resume");
  ASSERT_EQ(more.exit_code, 0) << more.output;
  expect_same_as_reference(out);
}

TEST_F(Resume, SigtermWritesACheckpointAndTheResumedRunEqualsOneRun) {
  const fs::path out = scratch("resume_sigterm") / "out";
  const Result stopped =
      run_and_signal(out, kCase + " --set time.end=0.4", "TERM", has_checkpoint(out));
  ASSERT_EQ(stopped.exit_code, 143) << stopped.output;  // 128 + SIGTERM
  const std::string result = read_file(out / "result.json");
  EXPECT_NE(result.find("\"status\": \"interrupted\""), std::string::npos) << result;
  EXPECT_NE(result.find("--resume"), std::string::npos) << result;
  // The command printed is the one that resumes (absolute executable, the case, OUT, --set).
  const std::string said = "resume with:\n    ";
  const auto at = stopped.output.find(said);
  ASSERT_NE(at, std::string::npos) << stopped.output;
  const std::string command = stopped.output.substr(
      at + said.size(), stopped.output.find('\n', at + said.size()) - at - said.size());
  EXPECT_NE(command.find(" --out " + out.string()), std::string::npos) << command;
  EXPECT_NE(command.find("--set time.end=0.4"), std::string::npos) << command;
  // The interrupted run's checkpoint is at the step it stopped at; the snapshots stop before.
  const auto kept = files_named(out, "checkpoint_");
  ASSERT_FALSE(kept.empty());
  const Result resumed = run_shell(command);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  expect_same_as_reference(out);
}

TEST_F(Resume, CtrlCEndsTheRunAsSigtermDoesWithStatus130) {
  const fs::path out = scratch("resume_sigint") / "out";
  // A background job of a script starts with SIGINT ignored (and a run keeps ignoring what it was
  // started ignoring): env gives it back its default first, as a terminal's foreground job has.
  const Result stopped = run_and_signal(out, kCase + " --set time.end=0.4", "INT",
                                        has_checkpoint(out), "env --default-signal=INT ");
  ASSERT_EQ(stopped.exit_code, 130) << stopped.output;  // 128 + SIGINT
  EXPECT_NE(stopped.output.find("interrupted by SIGINT"), std::string::npos) << stopped.output;
  EXPECT_NE(read_file(out / "result.json").find("\"status\": \"interrupted\""), std::string::npos);
  const Result resumed = run(kCase + " --set time.end=0.4 --out " + out.string() + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  expect_same_as_reference(out);
}

TEST_F(Resume, AfterAHardKillTheRowsAndSnapshotsPastTheCheckpointAreWrittenOnce) {
  const fs::path out = scratch("resume_kill") / "out";
  // Killed once the snapshot of t = 0.15 s (step 24) is written, after the checkpoint of t = 0.1
  // s (step 16): rows and snapshots past the checkpoint are there to be written again.
  const Result killed =
      run_and_signal(out, kCase + " --set time.end=0.4", "KILL",
                     has_checkpoint(out) + " && test -e " + (out / "snap_00000024.h5").string());
  ASSERT_EQ(killed.exit_code, 137) << killed.output;
  EXPECT_FALSE(fs::exists(out / "result.json"));
  const auto kept = files_named(out, "checkpoint_");
  ASSERT_FALSE(kept.empty());
  const long checkpoint = std::stol(kept.back().filename().string().substr(11));
  // (Unless the kill came later than asked, after the next checkpoint, step 32.)
  if (checkpoint == 16) {
    const auto before = read_csv(out / "diagnostics.csv");
    ASSERT_FALSE(before.empty());
    EXPECT_GE(std::stol(before.back().at("step")), 24);
    EXPECT_GE(files_named(out, "snap_").size(), 4u);
  }
  const Result resumed = run(kCase + " --set time.end=0.4 --out " + out.string() + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  expect_same_as_reference(out);
}

TEST(ResumeRefused, WithoutACheckpointItSaysSo) {
  const fs::path out = scratch("resume_none") / "out";
  const Result r = run(kCase + " --set time.end=0.4 --out " + out.string() + " --resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no checkpoint in " + out.string()), std::string::npos) << r.output;
}

// A study killed (SIGTERM) while its point runs: the point gets SIGTERM too (its parent died),
// writes a checkpoint and stops "interrupted"; the study run again resumes the point from it,
// and the point ends with the same bits as the same run never stopped.
TEST(ResumeStudy, AKilledStudysPointResumesFromItsCheckpoint) {
  const fs::path dir = scratch("resume_study");
  const std::string sets =
      "\"particles.spacing\" = 0.025\n\"output.interval\" = 0.05\n"
      "\"output.checkpoint_interval\" = 0.1\n\"output.diagnostics_every\" = 3\n";
  write_file(dir / "study.toml", "base = \"" + example("taylor_green_2d") + "\"\n[set]\n" + sets +
                                     "[[points]]\nname = \"p\"\nset = { \"time.end\" = 0.4 }\n");
  const fs::path out = dir / "out", point = out / "p";
  const std::string study =
      isphdem() + " study " + (dir / "study.toml").string() + " --out " + out.string() + " --quiet";
  const Result killed =
      run_shell("(" + study + " & pid=$!; for i in $(seq 1 30000); do " + has_checkpoint(point) +
                " && break; kill -0 $pid 2> /dev/null || break; sleep 0.01; done; kill -TERM $pid; "
                "wait $pid; " +
                has_checkpoint(point) + " && for i in $(seq 1 30000); do test -e " +
                (point / "result.json").string() + " && break; sleep 0.01; done)");
  const std::string result = read_file(point / "result.json");
  ASSERT_NE(result.find("\"status\": \"interrupted\""), std::string::npos)
      << result << killed.output << read_file(point / "log.txt");
  const Result again =
      run_shell(isphdem() + " study " + (dir / "study.toml").string() + " --out " + out.string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(count(again.output, "p: resumes from its checkpoint"), 1) << again.output;
  const auto rows = read_csv(out / "study.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("status"), "finished");

  const Result whole = run(example("taylor_green_2d") +
                           " --quiet --set particles.spacing=0.025 --set output.interval=0.05"
                           " --set output.checkpoint_interval=0.1 --set output.diagnostics_every=3"
                           " --set time.end=0.4 --out " +
                           (dir / "ref").string());
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto ours = files_named(point, "snap_"), theirs = files_named(dir / "ref", "snap_");
  ASSERT_EQ(ours.size(), 9u);
  ASSERT_EQ(theirs.size(), 9u);
  expect_same_snapshot(theirs.back(), ours.back());
  EXPECT_TRUE(diagnostics_without_wall(point) == diagnostics_without_wall(dir / "ref"));
  EXPECT_EQ(xdmf_times(point), xdmf_times(dir / "ref"));
}

TEST(ResumeRefused, ACheckpointOfOtherSetOptionsIsNotTaken) {
  const fs::path out = scratch("resume_other") / "out";
  const Result first = run(kCase + " --set time.end=0.2 --out " + out.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const Result other = run(kCase + " --set time.end=0.4 --set fluid.viscosity=0.02 --out " +
                           out.string() + " --resume");
  EXPECT_NE(other.exit_code, 0);
  EXPECT_NE(other.output.find("other --set options"), std::string::npos) << other.output;
}

}  // namespace
}  // namespace isphdem::cli
