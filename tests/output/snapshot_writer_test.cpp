// Snapshots written by SnapshotWriter read back exactly with the plain HDF5 C API, malformed input
// writes nothing, and whatever happens (bad data halfway through a file, a killed process) the
// directory only ever holds complete snapshots.
#include "io/snapshot_writer.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <thread>

#include "expect_file_holds.hpp"
#include "h5_read.hpp"
#include "mini_xml.hpp"
#include "output_test_support.hpp"

namespace {

using isphdem::Dataset;
using isphdem::Snapshot;
using isphdem::SnapshotWriter;
using output_test::expect_file_holds;
using output_test::file_names;
using output_test::sample;
using output_test::scratch_dir;
namespace fs = std::filesystem;

// Opens every snap_*.h5 in `dir` and reads every dataset listed in fluid.xdmf from the files it
// names; returns the number of grids in fluid.xdmf.
std::size_t expect_directory_consistent(const fs::path& dir) {
  for (const auto& name : file_names(dir)) {
    if (name.rfind("snap_", 0) != 0 || !fs::is_regular_file(dir / name)) continue;
    SCOPED_TRACE(name);
    h5_read::File f((dir / name).string());  // throws if incomplete
    for (const char* d : {"position", "velocity", "pressure", "porosity", "kind", "id"})
      EXPECT_NO_THROW(f.read(std::string("/fluid/") + d));
  }
  if (!fs::exists(dir / "fluid.xdmf")) return 0;
  const auto doc = mini_xml::parse(output_test::read_text(dir / "fluid.xdmf"));
  const auto grids = doc.one("Domain").one("Grid").all("Grid");
  for (const auto* grid : grids) {
    const std::string ref = grid->one("Geometry").one("DataItem").text;
    const std::string file = ref.substr(0, ref.find(':'));
    EXPECT_TRUE(fs::exists(dir / file)) << ref;
  }
  return grids.size();
}

TEST(SnapshotWriter, FileNameIsStepPaddedToEightDigits) {
  EXPECT_EQ(SnapshotWriter::file_name(1200), "snap_00001200.h5");
  EXPECT_EQ(SnapshotWriter::file_name(0), "snap_00000000.h5");
  EXPECT_EQ(SnapshotWriter::file_name(123456789), "snap_123456789.h5");
}

TEST(SnapshotWriter, RoundTrip2D) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  const Snapshot s = sample(1200, 0.1 + 0.2, 13, 2, 5, 2);
  const fs::path written = w.write(s);
  EXPECT_EQ(written, dir / "snap_00001200.h5");
  expect_file_holds(written, s);
  h5_read::File f(written.string());
  EXPECT_EQ(f.read("/fluid/position").dims, (std::vector<hsize_t>{13, 2}));
  EXPECT_EQ(f.read("/fluid/kind").type, h5_read::Type::i32);
  EXPECT_EQ(f.read("/bodies/quat").dims, (std::vector<hsize_t>{2, 4}));
}

TEST(SnapshotWriter, RoundTrip3DFromArrayOfStructs) {
  struct Particle {
    double x[3], v[3], p;
    int kind;
    long id;
  };
  std::vector<Particle> ps;
  for (int i = 0; i < 7; ++i)
    ps.push_back(
        {{i * 0.1, -i * 0.2, 1e-9 * i}, {1.0 / (i + 1), 0, -2.5}, 101325.0 + i, i % 4, 7L * i});
  Snapshot s;
  s.step = 42;
  s.time = 1.0 / 3.0;
  auto& g = s.group("fluid");
  g.add_generated<double>("position", ps.size(), 3, [&](auto i, auto c) { return ps[i].x[c]; });
  g.add_generated<double>("velocity", ps.size(), 3, [&](auto i, auto c) { return ps[i].v[c]; });
  g.add_generated<double>("pressure", ps.size(), 1, [&](auto i, auto) { return ps[i].p; });
  g.add_generated<std::int32_t>("kind", ps.size(), 1, [&](auto i, auto) { return ps[i].kind; });
  g.add_generated<std::int64_t>("id", ps.size(), 1, [&](auto i, auto) { return ps[i].id; });
  const std::vector<double> flat = {1, 2, 3, 4, 5, 6};
  s.group("extra").add("pair", flat.data(), 3, 2);  // the pointer + rows + cols helper
  const auto dir = scratch_dir();
  expect_file_holds(SnapshotWriter(dir).write(s), s);
  h5_read::File f((dir / "snap_00000042.h5").string());
  EXPECT_EQ(f.read("/fluid/position").f64[3 * 6 + 2], 1e-9 * 6);
  EXPECT_EQ(f.read("/fluid/id").i64[6], 42);
  EXPECT_EQ(f.read("/extra/pair").f64, flat);
}

TEST(SnapshotWriter, EmptyGroupIsWrittenWithZeroRows) {
  Snapshot s = sample(3, 0.5, 4, 2);
  output_test::add_dem(s, 0);  // a fluid-only run that still reports its (empty) DEM side
  const auto dir = scratch_dir();
  expect_file_holds(SnapshotWriter(dir).write(s), s);
  h5_read::File f((dir / "snap_00000003.h5").string());
  EXPECT_EQ(f.read("/dem/position").dims, (std::vector<hsize_t>{0, 3}));
  EXPECT_EQ(f.read("/dem/radius").dims, (std::vector<hsize_t>{0}));
}

TEST(SnapshotWriter, SameStepAgainReplacesTheFile) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  w.write(sample(5, 0.5, 8, 2));
  const Snapshot again = sample(5, 0.5, 3, 3);
  w.write(again);
  expect_file_holds(dir / "snap_00000005.h5", again);
  EXPECT_EQ(expect_directory_consistent(dir), 1u);
}

TEST(SnapshotWriter, MalformedSnapshotThrowsAndWritesNothing) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  auto expect_rejected = [&](Snapshot s, const char* why) {
    SCOPED_TRACE(why);
    EXPECT_THROW(w.write(s), std::invalid_argument);
    EXPECT_TRUE(file_names(dir).empty());
  };
  {
    Snapshot s = sample(1, 0.0, 4, 2);
    s.groups[0].datasets[2].rows = 5;  // pressure: 4 values but claims 5 rows
    expect_rejected(s, "values != rows x cols");
  }
  {
    Snapshot s = sample(1, 0.0, 4, 2);
    const std::vector<double> five(5, 1.0);
    s.group("fluid").add("extra", five.data(), 5);
    expect_rejected(s, "rows differ within a group");
  }
  {
    Snapshot s = sample(1, 0.0, 4, 2);
    s.groups[0].datasets[0].name = "pos/ition";
    expect_rejected(s, "slash in a name");
  }
  {
    Snapshot s = sample(1, 0.0, 4, 2);
    s.groups.push_back(s.groups[0]);
    expect_rejected(s, "group twice");
  }
  expect_rejected(sample(-1, 0.0, 4, 2), "negative step");
  expect_rejected(sample(1, std::nan(""), 4, 2), "time NaN");
}

TEST(SnapshotWriter, DirectoryThatIsAFileThrows) {
  const auto dir = scratch_dir();
  std::ofstream(dir / "plain") << "x";
  EXPECT_THROW(SnapshotWriter(dir / "plain"), std::runtime_error);
}

TEST(SnapshotWriter, CreatesNestedDirectory) {
  const auto dir = scratch_dir() / "a" / "b";
  SnapshotWriter(dir).write(sample(0, 0.0, 4, 2));
  EXPECT_TRUE(fs::exists(dir / "snap_00000000.h5"));
}

// HDF5 itself refuses the duplicate dataset once half the file is written: the error names file
// and dataset, the temporary file is gone, and the directory still holds exactly the earlier
// complete snapshots and an .xdmf listing only them.
TEST(SnapshotWriter, FailureHalfwayLeavesOnlyCompleteSnapshots) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  w.write(sample(0, 0.0, 6, 2, 3));
  w.write(sample(10, 0.1, 6, 2, 3));
  const auto before = file_names(dir);
  const std::string xdmf_before = output_test::read_text(dir / "fluid.xdmf");

  Snapshot bad = sample(20, 0.2, 6, 2, 3);
  bad.group("dem").datasets.push_back(bad.group("dem").datasets[2]);  // "radius" twice
  try {
    w.write(bad);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("snap_00000020.h5"), std::string::npos) << what;
    EXPECT_NE(what.find("/dem/radius"), std::string::npos) << what;
  }
  EXPECT_EQ(file_names(dir), before);
  EXPECT_EQ(output_test::read_text(dir / "fluid.xdmf"), xdmf_before);
  EXPECT_EQ(expect_directory_consistent(dir), 2u);

  w.write(sample(20, 0.2, 6, 2, 3));  // the writer is still usable
  EXPECT_EQ(expect_directory_consistent(dir), 3u);
}

TEST(SnapshotWriter, FreshRemovesAnEarlierRunButNothingElse) {
  const auto dir = scratch_dir();
  {
    SnapshotWriter old(dir);
    for (long step : {0, 100, 200}) old.write(sample(step, step * 1e-3, 5, 2, 2, 1));
  }
  std::ofstream(dir / "diagnostics.csv") << "time\n0\n";
  std::ofstream(dir / ".snap_00000300.h5.tmp") << "half a file from a killed run";
  std::ofstream(dir / ".fluid.xdmf.tmp") << "<Xdmf";
  std::ofstream(dir / "notes.txt") << "mine";
  std::ofstream(dir / "snapshot_plot.h5") << "mine too";
  fs::create_directories(dir / "snap_00000007.h5");  // not a regular file: left alone

  SnapshotWriter fresh(dir);
  EXPECT_EQ(file_names(dir),
            (std::set<std::string>{"notes.txt", "snapshot_plot.h5", "snap_00000007.h5"}));
  fresh.write(sample(50, 0.05, 5, 2));
  EXPECT_EQ(expect_directory_consistent(dir), 1u);
}

// Continuing (fresh = false) from step 100 of a run that got to 200: the snapshots up to 100 stay
// and stay listed, the abandoned 200 goes, and new steps join the same series.
TEST(SnapshotWriter, ContinuingKeepsEarlierSnapshotsAndDropsLaterOnes) {
  const auto dir = scratch_dir();
  {
    SnapshotWriter old(dir);
    for (long step : {0, 100, 200}) old.write(sample(step, step * 1e-3, 5, 2, 2));
  }
  std::ofstream(dir / ".snap_00000300.h5.tmp") << "half a file from a killed run";
  SnapshotWriter cont(dir, /*fresh=*/false);
  EXPECT_FALSE(fs::exists(dir / ".snap_00000300.h5.tmp"));
  EXPECT_TRUE(fs::exists(dir / "snap_00000200.h5"));  // nothing dropped before the first write
  const Snapshot restart = sample(100, 0.1, 5, 2, 2);
  cont.write(restart);
  EXPECT_FALSE(fs::exists(dir / "snap_00000200.h5"));
  cont.write(sample(150, 0.15, 5, 2, 2));
  EXPECT_EQ(expect_directory_consistent(dir), 3u);  // 0, 100, 150
  const auto dem = mini_xml::parse(output_test::read_text(dir / "dem.xdmf"));
  EXPECT_EQ(dem.one("Domain").one("Grid").all("Grid").size(), 3u);
  expect_file_holds(dir / "snap_00000100.h5", restart);
}

// A real crash: a child process writes large snapshots in a loop (cycling over 4 step numbers, so
// files are also being replaced) and is killed with SIGKILL at various moments. Whenever it dies,
// every snap_*.h5 must be complete and fluid.xdmf must parse and point at existing files.
TEST(SnapshotWriter, KilledWriterLeavesValidDirectory) {
  const auto dir = scratch_dir();
  for (int round = 0; round < 4; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    int ready[2];
    ASSERT_EQ(pipe(ready), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      close(ready[0]);
      try {  // an exception must not unwind into the forked copy of the test runner
        SnapshotWriter w(dir, /*fresh=*/round == 0);
        Snapshot s = sample(0, 0.0, 60000, 2, 100);  // built once: the loop is all writing
        for (long i = 0; i < 2000; ++i) {
          s.step = i % 4;
          s.time = 0.01 * s.step;
          w.write(s);
          if (write(ready[1], "x", 1) != 1) break;
        }
      } catch (...) {
        _exit(1);
      }
      _exit(0);
    }
    close(ready[1]);
    char c;
    for (int i = 0; i < 2 + round; ++i) ASSERT_EQ(read(ready[0], &c, 1), 1);
    // Different points in the write cycle each round; correctness must not depend on which.
    std::this_thread::sleep_for(std::chrono::microseconds(700 * round));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    close(ready[0]);
    EXPECT_GE(expect_directory_consistent(dir), 1u);
  }
}

}  // namespace
