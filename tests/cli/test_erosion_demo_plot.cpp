// The drawing half of `bash scripts/demo.sh`: scripts/plot_erosion.py with two runs of the reduced
// erosion layer (the packing of the erosion_reduced_packing fixture) side by side, 20 steps of
// each model, so that the demo's picture, GIF and five-line summary cannot rot unnoticed.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

TEST(ErosionDemoPlot, TwoModelsSideBySideWithTheirSummary) {
  if (run_shell("/usr/bin/python3 -c 'import h5py, matplotlib, PIL'").exit_code != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks h5py, matplotlib or PIL";
  const auto dir = scratch("erosion_demo_plot");
  for (const std::string model : {"unresolved", "semi-resolved"}) {
    const Result r = run(reduced_case() + " --out " + (dir / model).string() +
                         " --quiet --set inflow.velocity=0.02 --set time.end=0.002"
                         " --set output.interval=0.001 --set 'coupling.model=\"" + model + "\"'");
    ASSERT_EQ(r.exit_code, 0) << model << ": " << r.output;
  }
  const Result p = run_shell("cd " + dir.string() + " && /usr/bin/python3 " +
                             std::string(ISPHDEM_SOURCE_DIR) +
                             "/scripts/plot_erosion.py unresolved semi-resolved --paths 0 "
                             "--png demo.png --gif demo.gif --summary summary.txt");
  std::printf("%s", p.output.c_str());
  ASSERT_EQ(p.exit_code, 0);
  EXPECT_EQ(count(p.output, "wrote demo.png\n"), 1);
  EXPECT_EQ(count(p.output, "wrote demo.gif (3 frames)\n"), 1);  // t = 0, 0.001, 0.002 s
  const std::string summary = read_file(dir / "summary.txt");
  std::vector<std::string> lines;
  std::stringstream in(summary);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 5u) << summary;
  EXPECT_EQ(lines[0], "2 runs to t = 0.00 s at v_in = 2 cm/s (.)");
  EXPECT_EQ(lines[1].rfind("pore jets (fastest pore water in the layer / v_in, mean after 0.1 s): "
                           "unresolved ",
                           0),
            0u);
  EXPECT_NE(lines[1].find(", semi-resolved "), std::string::npos);
  // Nothing moves half a fine's diameter in 2 ms; all 32 fines are counted in each run.
  EXPECT_EQ(lines[2], "fines moved more than 0.5 mm: unresolved 0 of 32, semi-resolved 0 of 32");
  EXPECT_EQ(lines[3].rfind("layer surface rise: unresolved ", 0), 0u);
  EXPECT_EQ(lines[4].rfind("wall time: unresolved 0 min ", 0), 0u);
  // The summary printed is the one saved.
  EXPECT_NE(p.output.find(summary), std::string::npos);
}

}  // namespace
}  // namespace isphdem::cli
