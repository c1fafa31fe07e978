// diagnostics.csv: a header row, rows whose numbers read back exactly, on disk after every row,
// and misuse (wrong row length, bad column names, a different header to append to) rejected.
#include "io/diagnostics_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "io/snapshot_writer.hpp"
#include "output_test_support.hpp"

namespace {

using isphdem::DiagnosticsWriter;
using output_test::read_text;
using output_test::scratch_dir;
namespace fs = std::filesystem;

std::vector<std::string> lines(const fs::path& path) {
  std::vector<std::string> out;
  std::stringstream ss(read_text(path));
  std::string line;
  while (std::getline(ss, line)) out.push_back(line);
  return out;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(std::strtod(cell.c_str(), nullptr));
  return out;
}

const std::vector<std::string> kColumns = {"time",           "step",      "wall_seconds",
                                           "ppe_iterations", "max_speed", "bed_height"};

TEST(DiagnosticsWriter, HeaderThenRowsThatReadBackExactly) {
  const auto path = scratch_dir() / "diagnostics.csv";
  const std::vector<double> a = {0.1, 1200, 1.0 / 3.0, 57, 1e-300, -2.5e17};
  const std::vector<double> b = {
      0.30000000000000004, 1201, 3.14159, 0, std::numeric_limits<double>::infinity(), std::nan("")};
  {
    DiagnosticsWriter d(path, kColumns);
    d.row(a);
    d.row(b);
  }
  const auto l = lines(path);
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0], "time,step,wall_seconds,ppe_iterations,max_speed,bed_height");
  EXPECT_EQ(parse_row(l[1]), a);
  EXPECT_EQ(l[1].substr(0, 9), "0.1,1200,");  // shortest form, integers without decimals
  const auto rb = parse_row(l[2]);
  ASSERT_EQ(rb.size(), b.size());
  for (std::size_t i = 0; i + 1 < b.size(); ++i) EXPECT_EQ(rb[i], b[i]);
  EXPECT_TRUE(std::isnan(rb.back()));
  EXPECT_NE(l[2].find(",inf,nan"), std::string::npos) << l[2];
}

TEST(DiagnosticsWriter, EveryRowIsInTheFileBeforeTheNextCall) {
  const auto path = scratch_dir() / "diagnostics.csv";
  DiagnosticsWriter d(path, {"time", "step"});
  EXPECT_EQ(lines(path).size(), 1u);  // header already there
  for (int i = 1; i <= 3; ++i) {
    d.row({0.5 * i, double(i)});
    EXPECT_EQ(lines(path).size(), 1u + i);
  }
}

TEST(DiagnosticsWriter, WrongRowLengthThrowsAndWritesNothing) {
  const auto path = scratch_dir() / "diagnostics.csv";
  DiagnosticsWriter d(path, kColumns);
  EXPECT_THROW(d.row({1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(d.row(std::vector<double>(kColumns.size() + 1, 0.0)), std::invalid_argument);
  EXPECT_EQ(lines(path).size(), 1u);
}

TEST(DiagnosticsWriter, BadColumnNamesThrow) {
  const auto path = scratch_dir() / "diagnostics.csv";
  EXPECT_THROW(DiagnosticsWriter(path, {}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsWriter(path, {"time", ""}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsWriter(path, {"time", "a,b"}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsWriter(path, {"time", "a\nb"}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsWriter(path, {"time", "\"q\""}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsWriter(path, {"time", "time"}), std::invalid_argument);
}

TEST(DiagnosticsWriter, NewWriterTruncatesAnOldFile) {
  const auto path = scratch_dir() / "diagnostics.csv";
  std::ofstream(path) << "old,header\n1,2\n";
  DiagnosticsWriter d(path, {"time", "step"});
  EXPECT_EQ(lines(path), (std::vector<std::string>{"time,step"}));
}

TEST(DiagnosticsWriter, AppendContinuesAndDropsAPartialLastLine) {
  const auto path = scratch_dir() / "diagnostics.csv";
  std::ofstream(path) << "time,step\n0.5,1\n1,2\n1.5,";  // killed halfway through a row
  {
    DiagnosticsWriter d(path, {"time", "step"}, /*append=*/true);
    d.row({1.5, 3});
  }
  EXPECT_EQ(lines(path), (std::vector<std::string>{"time,step", "0.5,1", "1,2", "1.5,3"}));
}

TEST(DiagnosticsWriter, AppendThroughAStepDropsTheRowsAfterIt) {
  // A run resumed from its checkpoint at step 20: the rows of steps 30 and 40 written before it
  // was killed are written again by the continuation, so they go.
  const auto path = scratch_dir() / "diagnostics.csv";
  std::ofstream(path) << "time,step,x\n0.1,10,1\n0.2,20,2\n0.3,30,3\n0.4,40,4\n0.5,";
  {
    DiagnosticsWriter d(path, {"time", "step", "x"}, /*append=*/true, /*through_step=*/20);
    d.row({0.3, 30, 3.5});
  }
  EXPECT_EQ(lines(path),
            (std::vector<std::string>{"time,step,x", "0.1,10,1", "0.2,20,2", "0.3,30,3.5"}));
}

TEST(DiagnosticsWriter, AppendToAMissingFileStartsIt) {
  const auto path = scratch_dir() / "diagnostics.csv";
  DiagnosticsWriter d(path, {"time", "step"}, /*append=*/true);
  d.row({0, 0});
  EXPECT_EQ(lines(path), (std::vector<std::string>{"time,step", "0,0"}));
}

TEST(DiagnosticsWriter, AppendWithADifferentHeaderThrows) {
  const auto path = scratch_dir() / "diagnostics.csv";
  std::ofstream(path) << "time,step\n0.5,1\n";
  EXPECT_THROW(DiagnosticsWriter(path, {"time", "step", "extra"}, true), std::runtime_error);
  EXPECT_EQ(lines(path).size(), 2u);  // untouched
}

TEST(DiagnosticsWriter, UnwritablePathThrows) {
  const auto dir = scratch_dir();
  EXPECT_THROW(DiagnosticsWriter(dir / "missing" / "diagnostics.csv", {"time"}),
               std::runtime_error);
}

// Wrong construction order: the SnapshotWriter's fresh start deletes the open diagnostics.csv.
// Rows must not silently vanish into the unlinked file.
TEST(DiagnosticsWriter, FileRemovedWhileOpenThrows) {
  const auto dir = scratch_dir();
  DiagnosticsWriter d(dir / "diagnostics.csv", {"time"});
  isphdem::SnapshotWriter s(dir);
  EXPECT_THROW(d.row({0.0}), std::runtime_error);
}

}  // namespace
