// The cases of docs/getting_started.md (examples/getting_started), run briefly through `isphdem`
// as a user runs them, so that the copy-me examples cannot rot: the quasi-2D slab with fines and
// clumps (semi-resolved) and the 3D column (unresolved). Each must insert every grain its script
// asks for, finish, and give ParaView the arrays the guide names.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

// The value of `column` in the last row of diagnostics.csv ("" if there is no such column).
std::string last_value(const std::filesystem::path& out, const std::string& column) {
  std::stringstream in(read_file(out / "diagnostics.csv"));
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  const auto names = split(header), values = split(last);
  for (std::size_t k = 0; k < names.size() && k < values.size(); ++k)
    if (names[k] == column) return values[k];
  return "";
}

Result run_example(const std::string& file, const std::filesystem::path& out,
                   const std::string& end) {
  return run(std::string(ISPHDEM_SOURCE_DIR) + "/examples/getting_started/" + file + " --out " +
             out.string() + " --quiet --set time.end=" + end + " --set output.interval=" + end);
}

TEST(GettingStarted, Slab2dSettlesFinesAndClumpsSemiResolved) {
  const auto out = scratch("getting_started_slab_2d");
  const Result r = run_example("slab_2d.toml", out, "0.002");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(out / "result.json").find("\"status\": \"finished\""), std::string::npos);
  // 20 fines and 2 clumps of 7 spheres: every grain inserted (a too thin box inserts none).
  EXPECT_EQ(last_value(out, "atoms"), "34");
  EXPECT_EQ(last_value(out, "step"), "20");
  // The clumps are resolved: their PMS particles are announced, one line per body.
  EXPECT_EQ(count(r.output, "7 PMS particles"), 2) << r.output;
  // What docs/getting_started.md tells to colour by in ParaView.
  const std::string xdmf = read_file(out / "dem.xdmf");
  EXPECT_NE(xdmf.find("Attribute Name=\"body\""), std::string::npos);
  EXPECT_NE(xdmf.find("Attribute Name=\"model\""), std::string::npos);
  EXPECT_NE(read_file(out / "fluid.xdmf").find("Attribute Name=\"kind\""), std::string::npos);
}

TEST(GettingStarted, Box3dSettlesFinesUnresolved) {
  const auto out = scratch("getting_started_box_3d");
  const Result r = run_example("box_3d.toml", out, "0.002");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(out / "result.json").find("\"status\": \"finished\""), std::string::npos);
  EXPECT_EQ(last_value(out, "atoms"), "20");
  EXPECT_EQ(last_value(out, "step"), "20");
  EXPECT_NE(read_file(out / "dem.xdmf").find("Attribute Name=\"body\""), std::string::npos);
}

}  // namespace
}  // namespace isphdem::cli
