// ParaView itself (pvpython, its XDMF reader) opens what SnapshotWriter writes as time series:
// number of steps, point count and point arrays of the last step. Skipped without pvpython.
#include <gtest/gtest.h>

#include "io/snapshot_writer.hpp"
#include "output_test_support.hpp"

namespace {

using output_test::quote;
using output_test::sample;
using output_test::scratch_dir;

// pvpython on check_xdmf.py with `args`; skips the test when pvpython is not installed.
output_test::Result check_xdmf(const std::filesystem::path& dir, const std::string& args) {
  const std::string pvpython = output_test::find_on_path("pvpython");
  if (pvpython.empty()) return {-2, ""};
  // No display is needed to read files; keep Qt and VTK from looking for one.
  return output_test::run("env -u DISPLAY QT_QPA_PLATFORM=offscreen " + quote(pvpython) +
                          " --force-offscreen-rendering " +
                          quote(std::string(ISPHDEM_SOURCE_DIR) + "/tests/output/check_xdmf.py") +
                          " " + quote(dir.string()) + " " + args);
}

#define CHECK_XDMF_OR_SKIP(result, dir, args)               \
  const output_test::Result result = check_xdmf(dir, args); \
  if (result.exit_code == -2) GTEST_SKIP() << "pvpython not on PATH";

TEST(ParaView, OpensTwoDimensionalRunAsTimeSeries) {
  const auto dir = scratch_dir();
  isphdem::SnapshotWriter w(dir);
  for (long k = 0; k < 3; ++k) w.write(sample(50 * k, 0.01 * k, 11, 2, 5, 2));
  CHECK_XDMF_OR_SKIP(r, dir,
                     "--steps 3"
                     " --expect fluid=11:pressure/1,velocity/3,porosity/1,kind/1,id/1"
                     " --expect dem=5:velocity/3,radius/1,id/1,body/1,force_hydro/3"
                     " --expect bodies=2:velocity,omega,quat/4,mass,volume,force_hydro,"
                     "torque_hydro");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(ParaView, OpensThreeDimensionalRunAsTimeSeries) {
  const auto dir = scratch_dir();
  isphdem::SnapshotWriter w(dir);
  for (long k = 0; k < 4; ++k) w.write(sample(k, 0.25 * k, 20, 3, 3));
  CHECK_XDMF_OR_SKIP(r, dir,
                     "--steps 4 --expect fluid=20:pressure,velocity/3,kind --expect dem=3:radius");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// The checker is able to fail: wrong point count, a missing array, a missing snapshot file.
TEST(ParaView, CheckerRejectsWrongExpectationsAndMissingFiles) {
  const auto dir = scratch_dir();
  isphdem::SnapshotWriter w(dir);
  for (long k = 0; k < 3; ++k) w.write(sample(k, 1.0 * k, 11, 2));
  {
    CHECK_XDMF_OR_SKIP(r, dir, "--steps 3 --expect fluid=12:pressure");
    EXPECT_EQ(r.exit_code, 1) << r.output;
  }
  {
    CHECK_XDMF_OR_SKIP(r, dir, "--steps 3 --expect fluid=11:pressure,radius");
    EXPECT_EQ(r.exit_code, 1) << r.output;
  }
  std::filesystem::remove(dir / isphdem::SnapshotWriter::file_name(1));
  {
    CHECK_XDMF_OR_SKIP(r, dir, "--steps 3");
    EXPECT_EQ(r.exit_code, 1) << r.output;
  }
}

}  // namespace
