// `isphdem run --resume` (issue 47): a run stopped at a checkpoint, by SIGTERM, or killed hard,
// then resumed, ends with the same bits as the run that was never stopped, and its
// diagnostics.csv and fluid.xdmf hold each time once.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "../output/h5_read.hpp"
#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

namespace fs = std::filesystem;

// Taylor-Green at 40 x 40 (automatic dt), to t = 0.4 s: snapshots every 0.05 s, checkpoints
// every 0.1 s.
const std::string kCase = example("taylor_green_2d") +
                          " --quiet --set particles.spacing=0.025 --set output.interval=0.05"
                          " --set output.checkpoint_interval=0.1 --set output.diagnostics_every=3";

std::vector<fs::path> files_named(const fs::path& dir, const std::string& prefix) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

// Every dataset of /fluid and the root attributes, bit for bit (storage order).
void expect_same_snapshot(const fs::path& a, const fs::path& b) {
  ASSERT_EQ(a.filename(), b.filename());
  h5_read::File fa(a.string()), fb(b.string());
  EXPECT_EQ(fa.attribute_f64("time"), fb.attribute_f64("time"));
  EXPECT_EQ(fa.attribute_i64("step"), fb.attribute_i64("step"));
  for (const char* name :
       {"position", "velocity", "pressure", "porosity", "kind", "free_surface", "id"}) {
    const std::string path = std::string("fluid/") + name;
    const h5_read::Array x = fa.read(path), y = fb.read(path);
    EXPECT_EQ(x.dims, y.dims) << path;
    EXPECT_TRUE(x.f64 == y.f64) << path << " differs in " << a.filename();
    EXPECT_TRUE(x.i64 == y.i64) << path;
    EXPECT_TRUE(x.i32 == y.i32) << path;
  }
}

// The rows without their wall-clock column, as text (the shortest round-trip spelling: equal
// text is equal bits).
std::vector<Row> diagnostics_without_wall(const fs::path& dir) {
  auto rows = read_csv(dir / "diagnostics.csv");
  for (auto& r : rows) r.erase("wall_seconds");
  return rows;
}

// The Time values fluid.xdmf lists, in order.
std::vector<std::string> xdmf_times(const fs::path& dir) {
  return spans_between(read_file(dir / "fluid.xdmf"), "<Time Value=\"", "\"", "0123456789.e-+");
}

// Runs CASE ARGS into OUT in the background and sends SIGNAL once `ready` (a shell test) holds;
// returns the run's exit status (-1 when it never ended) and output.
Result run_and_signal(const fs::path& out, const std::string& args, const std::string& signal,
                      const std::string& ready) {
  const std::string script = "(" + isphdem() + " run " + args + " --out " + out.string() + " > " +
                             (out.string() + ".log") +
                             " 2>&1 & pid=$!; for i in $(seq 1 30000); do " + ready +
                             " && break; kill -0 $pid 2> /dev/null || break; sleep 0.01; done; "
                             "kill -" +
                             signal + " $pid; wait $pid; echo \"exit=$?\")";
  Result r = run_shell(script);
  r.output += read_file(out.string() + ".log");
  const auto at = r.output.find("exit=");
  r.exit_code = at == std::string::npos ? -1 : std::stoi(r.output.substr(at + 5));
  return r;
}

// A checkpoint is in OUT.
std::string has_checkpoint(const fs::path& out) {
  return "ls -d " + out.string() + "/checkpoint_* > /dev/null 2>&1";
}

class Resume : public ::testing::Test {
 protected:
  // The run never stopped, shared by the tests (written once).
  static fs::path reference() {
    static const fs::path dir = [] {
      const fs::path d = scratch("resume_reference") / "out";
      const Result r = run(kCase + " --set time.end=0.4 --out " + d.string());
      EXPECT_EQ(r.exit_code, 0) << r.output;
      return d;
    }();
    return dir;
  }

  static void expect_same_as_reference(const fs::path& out) {
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
};

TEST_F(Resume, ExtendingAFinishedRunEqualsOneRun) {
  reference();
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
  reference();
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

TEST_F(Resume, AfterAHardKillTheRowsAndSnapshotsPastTheCheckpointAreWrittenOnce) {
  reference();
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

TEST_F(Resume, WithoutACheckpointItSaysSo) {
  const fs::path out = scratch("resume_none") / "out";
  const Result r = run(kCase + " --set time.end=0.4 --out " + out.string() + " --resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no checkpoint in " + out.string()), std::string::npos) << r.output;
}

}  // namespace
}  // namespace isphdem::cli
