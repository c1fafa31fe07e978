// SnapshotWriter on several MPI ranks (run on 2 and 3): each rank hands over its own rows and the
// file is the one a single process writes from all of them; a part that does not fit, or a file
// system that fails, stops every rank with one message and leaves the earlier snapshots valid.
#include <gtest/gtest.h>
#include <mpi.h>

#include <set>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "expect_file_holds.hpp"
#include "io/rank_agreement.hpp"
#include "io/snapshot_writer.hpp"
#include "output_test_support.hpp"

namespace {

using isphdem::Group;
using isphdem::Snapshot;
using isphdem::SnapshotWriter;
namespace fs = std::filesystem;

int rank() { return isphdem::rank_in(MPI_COMM_WORLD); }
int ranks() { return isphdem::ranks_of(MPI_COMM_WORLD); }

// The same directory on every rank, emptied by rank 0 before any rank uses it.
fs::path shared_scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(ISPHDEM_BINARY_DIR) / "test_output" /
                       (std::string("mpi.") + info->test_suite_name() + "." + info->name());
  if (rank() == 0) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return dir;
}

Group rows_of(const Group& whole, std::size_t first, std::size_t last) {
  Group part{whole.name, {}};
  for (const auto& d : whole.datasets)
    std::visit(
        [&](const auto& v) {
          using T = typename std::decay_t<decltype(v)>::value_type;
          part.add_values(d.name,
                          std::vector<T>(v.begin() + first * d.cols, v.begin() + last * d.cols),
                          last - first, d.cols);
        },
        d.data);
  return part;
}

// This rank's part of `whole`, split unevenly: rank 0 holds the first 3 fluid rows and every
// other group, the last rank the rest of the fluid, ranks between nothing (and no groups but the
// fluid's, with no rows).
Snapshot part_of(const Snapshot& whole) {
  Snapshot part;
  part.step = whole.step;
  part.time = whole.time;
  const Group& fluid = *whole.find("fluid");
  const std::size_t n = fluid.datasets.front().rows;
  const std::size_t first = rank() == 0 ? 0 : 3;
  const std::size_t last = rank() == 0 ? 3 : rank() == ranks() - 1 ? n : 3;
  part.groups.push_back(rows_of(fluid, first, last));
  if (rank() == 0)
    for (const auto& g : whole.groups)
      if (g.name != "fluid") part.groups.push_back(g);
  return part;
}

TEST(SnapshotWriterMpi, RanksPartsMakeTheFileOneProcessWrites) {
  const fs::path dir = shared_scratch();
  const Snapshot whole = output_test::sample(1200, 0.1 + 0.2, 13, 2, 5, 2);
  SnapshotWriter writer(dir / "ranks", true, MPI_COMM_WORLD);
  const fs::path written = writer.write(part_of(whole));
  const Snapshot second = output_test::sample(1300, 0.4, 13, 2, 5, 2);
  writer.write(part_of(second));
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() != 0) return;
  EXPECT_EQ(written, dir / "ranks" / "snap_00001200.h5");
  output_test::expect_file_holds(written, whole);
  output_test::expect_file_holds(dir / "ranks" / "snap_00001300.h5", second);
  // The .xdmf ParaView opens is the one a single process writes for the whole.
  SnapshotWriter alone(dir / "one");
  alone.write(whole);
  alone.write(second);
  for (const char* xdmf : {"fluid.xdmf", "dem.xdmf", "bodies.xdmf"})
    EXPECT_EQ(output_test::read_text(dir / "ranks" / xdmf),
              output_test::read_text(dir / "one" / xdmf))
        << xdmf;
  EXPECT_EQ(output_test::file_names(dir / "ranks"), output_test::file_names(dir / "one"));
}

// The refusal tests' start: snapshot 1 written by the ranks into a fresh directory, and this
// rank's part of snapshot 2 to spoil.
struct AfterOneSnapshot {
  fs::path dir = shared_scratch() / "out";
  SnapshotWriter writer{dir, true, MPI_COMM_WORLD};
  Snapshot next = part_of(output_test::sample(2, 0.002, 13, 2, 5, 2));
  int last = ranks() - 1;
  AfterOneSnapshot() { writer.write(part_of(output_test::sample(1, 0.001, 13, 2, 5, 2))); }
};

// Every rank throws `kind` with a message holding each of `parts`; afterwards the directory holds
// the first snapshot only, complete, and no temporary file.
template <class Kind>
void expect_every_rank_refuses(AfterOneSnapshot& run, const std::vector<std::string>& parts) {
  try {
    run.writer.write(run.next);
    ADD_FAILURE() << "rank " << rank() << " wrote a snapshot it should have refused";
  } catch (const Kind& e) {
    const std::string message = e.what();
    std::printf("rank %d: %s\n", rank(), message.c_str());
    for (const auto& p : parts) EXPECT_NE(message.find(p), std::string::npos) << message;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() != 0 || !fs::exists(run.dir)) return;
  std::set<std::string> expected{"snap_00000001.h5", "fluid.xdmf", "dem.xdmf", "bodies.xdmf"};
  EXPECT_EQ(output_test::file_names(run.dir), expected);
  output_test::expect_file_holds(run.dir / "snap_00000001.h5",
                                 output_test::sample(1, 0.001, 13, 2, 5, 2));
}

TEST(SnapshotWriterMpi, PartOfAnotherShapeStopsEveryRankAndWritesNothing) {
  AfterOneSnapshot run;
  if (rank() == run.last) {  // pressure as two columns: fine alone, not beside rank 0's
    auto& pressure = run.next.groups.front().datasets[2];
    pressure.cols = 2;
    std::get<std::vector<double>>(pressure.data).resize(pressure.rows * 2);
  }
  expect_every_rank_refuses<std::invalid_argument>(
      run, {"rank " + std::to_string(run.last), "/fluid/pressure", "rank 0's"});
}

TEST(SnapshotWriterMpi, MalformedPartOnOneRankStopsEveryRank) {
  AfterOneSnapshot run;
  if (rank() == run.last)
    std::get<std::vector<double>>(run.next.groups.front().datasets[2].data).pop_back();
  expect_every_rank_refuses<std::invalid_argument>(
      run, {"rank " + std::to_string(run.last), "/fluid/pressure", "values"});
}

TEST(SnapshotWriterMpi, RanksOnDifferentStepsAreRefused) {
  AfterOneSnapshot run;
  if (rank() == run.last) run.next.step = 3;
  expect_every_rank_refuses<std::invalid_argument>(
      run, {"rank " + std::to_string(run.last), "step 3", "one step"});
}

TEST(SnapshotWriterMpi, FailingFileSystemStopsEveryRank) {
  AfterOneSnapshot run;
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() == 0) fs::remove_all(run.dir);  // the output directory vanishes under the run
  MPI_Barrier(MPI_COMM_WORLD);
  expect_every_rank_refuses<std::runtime_error>(run, {"rank 0", "snap_00000002.h5"});
}

}  // namespace
