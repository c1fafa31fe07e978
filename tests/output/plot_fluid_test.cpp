// scripts/plot_fluid.py turns a snapshot written by SnapshotWriter into a PNG, for every --field,
// with arrows and grains, in 2-D and 3-D, and fails loudly on a field the snapshot lacks.
// Skipped when /usr/bin/python3 or its h5py/matplotlib are missing.
#include <gtest/gtest.h>

#include "io/snapshot_writer.hpp"
#include "output_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using output_test::quote;
using output_test::run;

const char* const kPython = "/usr/bin/python3";

bool python_can_plot() {
  return access(kPython, X_OK) == 0 &&
         run(std::string(kPython) + " -c 'import h5py, matplotlib, numpy'").exit_code == 0;
}

output_test::Result plot(const fs::path& snapshot, const std::string& args) {
  return run(std::string(kPython) + " " +
             quote(std::string(ISPHDEM_SOURCE_DIR) + "/scripts/plot_fluid.py") + " " +
             quote(snapshot.string()) + " " + args);
}

void expect_png(const fs::path& png) {
  ASSERT_TRUE(fs::exists(png)) << png;
  EXPECT_GT(fs::file_size(png), 1000u);
  EXPECT_EQ(output_test::read_text(png).substr(0, 8), "\x89PNG\r\n\x1a\n");
}

class PlotFluid : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!python_can_plot()) GTEST_SKIP() << kPython << " lacks h5py or matplotlib";
    dir_ = output_test::scratch_dir();
  }
  fs::path dir_;
};

TEST_F(PlotFluid, TwoDimensionalSnapshotEveryField) {
  const fs::path snap =
      isphdem::SnapshotWriter(dir_).write(output_test::sample(1200, 0.125, 400, 2, 6));
  for (const char* field : {"speed", "pressure", "porosity"}) {
    SCOPED_TRACE(field);
    const fs::path png = dir_ / (std::string(field) + ".png");
    const auto r = plot(snap, "-o " + quote(png.string()) + " --field " + field);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    expect_png(png);
  }
  const auto r = plot(snap, "-o " + quote((dir_ / "arrows.png").string()) + " --quiver 7 --dem");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_png(dir_ / "arrows.png");
}

TEST_F(PlotFluid, DefaultOutputIsTheSnapshotNameAsPng) {
  const fs::path snap = isphdem::SnapshotWriter(dir_).write(output_test::sample(3, 0.5, 50, 2));
  const auto r = plot(snap, "");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_png(dir_ / "snap_00000003.png");
}

TEST_F(PlotFluid, ThreeDimensionalSnapshotIsProjected) {
  const fs::path snap = isphdem::SnapshotWriter(dir_).write(output_test::sample(7, 1.0, 300, 3, 4));
  for (const char* axes : {"xz", "yz"}) {
    const fs::path png = dir_ / (std::string(axes) + ".png");
    const auto r =
        plot(snap, "-o " + quote(png.string()) + " --axes " + axes + " --dem --quiver 5");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    expect_png(png);
  }
}

TEST_F(PlotFluid, ThreeDimensionalSectionKeepsArrowsWithTheirParticles) {
  // --slab keeps a section of the particles; the velocity arrows must be filtered with them
  // (an unfiltered velocity array has the wrong length and matplotlib refuses it).
  const fs::path snap = isphdem::SnapshotWriter(dir_).write(output_test::sample(8, 1.0, 300, 3, 4));
  const fs::path png = dir_ / "section.png";
  const auto r = plot(snap, "-o " + quote(png.string()) + " --axes xz --slab 0.3 --quiver 3");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_png(png);
}

TEST_F(PlotFluid, MissingFieldFailsWithoutWritingAPng) {
  isphdem::Snapshot s = output_test::sample(1, 0.0, 20, 2);
  auto& datasets = s.group("fluid").datasets;
  datasets.erase(datasets.begin() + 3);  // porosity
  const fs::path snap = isphdem::SnapshotWriter(dir_).write(s);
  const fs::path png = dir_ / "no.png";
  const auto r = plot(snap, "-o " + quote(png.string()) + " --field porosity");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("porosity"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(png));
}

}  // namespace
