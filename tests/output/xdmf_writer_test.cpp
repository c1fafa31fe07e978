// The .xdmf files SnapshotWriter keeps: structure ParaView's XDMF 2 reader needs (Temporal
// Collection of Uniform Polyvertex grids), times ascending and exact, and every DataItem pointing
// at an existing HDF5 dataset with the declared shape and number type.
#include "io/xdmf_writer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "h5_read.hpp"
#include "io/snapshot_writer.hpp"
#include "mini_xml.hpp"
#include "output_test_support.hpp"

namespace {

using isphdem::SnapshotWriter;
using isphdem::XdmfArray;
using isphdem::XdmfStep;
using output_test::sample;
using output_test::scratch_dir;
namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string word;
  while (ss >> word) out.push_back(word);
  return out;
}

// The DataItem's reference resolves (relative to the .xdmf) to a dataset whose dims and dtype
// match what the DataItem declares.
void expect_data_item_resolves(const fs::path& dir, const mini_xml::Element& item) {
  SCOPED_TRACE(item.text);
  EXPECT_EQ(item.attr("Format"), "HDF");
  const auto colon = item.text.find(':');
  ASSERT_NE(colon, std::string::npos);
  const fs::path file = dir / item.text.substr(0, colon);
  ASSERT_TRUE(fs::exists(file));
  h5_read::File f(file.string());
  const auto a = f.read(item.text.substr(colon + 1));
  std::vector<std::string> dims;
  for (auto d : a.dims) dims.push_back(std::to_string(d));
  EXPECT_EQ(split(item.attr("Dimensions")), dims);
  const std::string type = item.attr("NumberType") + item.attr("Precision");
  switch (a.type) {
    case h5_read::Type::f64:
      EXPECT_EQ(type, "Float8");
      break;
    case h5_read::Type::i64:
      EXPECT_EQ(type, "Int8");
      break;
    case h5_read::Type::i32:
      EXPECT_EQ(type, "Int4");
      break;
    default:
      ADD_FAILURE() << "unexpected dtype";
  }
}

struct SeriesExpectation {
  std::size_t points;
  const char* geometry;
  std::set<std::string> attributes;
};

// Checks the whole document and returns the grids' times.
std::vector<double> check_series(const fs::path& xdmf, const SeriesExpectation& want) {
  SCOPED_TRACE(xdmf.string());
  const auto doc = mini_xml::parse(output_test::read_text(xdmf));
  EXPECT_EQ(doc.name, "Xdmf");
  EXPECT_EQ(doc.attr("Version"), "2.0");
  const auto& collection = doc.one("Domain").one("Grid");
  EXPECT_EQ(collection.attr("GridType"), "Collection");
  EXPECT_EQ(collection.attr("CollectionType"), "Temporal");
  std::vector<double> times;
  for (const auto* grid : collection.all("Grid")) {
    EXPECT_EQ(grid->attr("GridType"), "Uniform");
    times.push_back(std::strtod(grid->one("Time").attr("Value").c_str(), nullptr));
    const auto& topology = grid->one("Topology");
    EXPECT_EQ(topology.attr("TopologyType"), "Polyvertex");
    EXPECT_EQ(topology.attr("NumberOfElements"), std::to_string(want.points));
    const auto& geometry = grid->one("Geometry");
    EXPECT_EQ(geometry.attr("GeometryType"), want.geometry);
    expect_data_item_resolves(xdmf.parent_path(), geometry.one("DataItem"));
    std::set<std::string> names;
    for (const auto* a : grid->all("Attribute")) {
      names.insert(a->attr("Name"));
      EXPECT_EQ(a->attr("Center"), "Node");
      expect_data_item_resolves(xdmf.parent_path(), a->one("DataItem"));
      // The HDF5 dataset behind an attribute is the one of the same name.
      EXPECT_EQ(a->one("DataItem").text.substr(a->one("DataItem").text.rfind('/') + 1),
                a->attr("Name"));
    }
    EXPECT_EQ(names, want.attributes);
  }
  return times;
}

TEST(XdmfSeries, ThreeSnapshotsMakeThreeAscendingSteps) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  const std::vector<double> times = {0.0, 0.1 + 0.2, 1.0 / 3.0 + 1e-12};
  for (std::size_t k = 0; k < times.size(); ++k) w.write(sample(100 * k, times[k], 9, 2, 4, 2));

  EXPECT_EQ(check_series(dir / "fluid.xdmf",
                         {9, "XY", {"velocity", "pressure", "porosity", "kind", "id"}}),
            times);  // exact: the XML carries round-trip digits
  EXPECT_EQ(check_series(dir / "dem.xdmf",
                         {4, "XYZ", {"velocity", "radius", "id", "body", "force_hydro"}}),
            times);
  EXPECT_EQ(check_series(dir / "bodies.xdmf", {2,
                                               "XYZ",
                                               {"velocity", "omega", "quat", "mass", "volume",
                                                "force_hydro", "torque_hydro"}}),
            times);
}

TEST(XdmfSeries, ThreeDimensionalFluidUsesXYZ) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  for (long k = 0; k < 3; ++k) w.write(sample(k, 0.5 * k, 6, 3));
  EXPECT_EQ(check_series(dir / "fluid.xdmf",
                         {6, "XYZ", {"velocity", "pressure", "porosity", "kind", "id"}})
                .size(),
            3u);
}

// Written out of order (a restart that went back): the series is still sorted by step.
TEST(XdmfSeries, StepsAreListedInStepOrder) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  w.write(sample(0, 0.0, 4, 2));
  w.write(sample(20, 2.0, 4, 2));
  w.write(sample(10, 1.0, 4, 2));
  EXPECT_EQ(check_series(dir / "fluid.xdmf",
                         {4, "XY", {"velocity", "pressure", "porosity", "kind", "id"}}),
            (std::vector<double>{0.0, 1.0, 2.0}));
}

// ParaView's readers fail (XDMF Reader) or abort (Xdmf3) on a grid without points, so a group
// that never has particles gets no .xdmf at all.
TEST(XdmfSeries, GroupWithoutParticlesGetsNoXdmf) {
  const auto dir = scratch_dir();
  SnapshotWriter w(dir);
  auto s = sample(0, 0.0, 4, 2);
  output_test::add_dem(s, 0);
  w.write(s);
  EXPECT_TRUE(fs::exists(dir / "fluid.xdmf"));
  EXPECT_FALSE(fs::exists(dir / "dem.xdmf"));
  EXPECT_TRUE(fs::exists(dir / "snap_00000000.h5"));
}

XdmfStep step_with(std::vector<std::size_t> cols, std::size_t rows = 3) {
  XdmfStep s;
  s.step = 7;
  s.time = 0.25;
  s.file = "snap_00000007.h5";
  s.group = "g";
  s.rows = rows;
  s.arrays.push_back({"position", 3, true, 8});
  for (auto c : cols) s.arrays.push_back({"a" + std::to_string(c), c, true, 8});
  return s;
}

TEST(XdmfDocument, AttributeTypeFollowsColumnCount) {
  const auto doc = mini_xml::parse(isphdem::xdmf_document("g", {step_with({1, 2, 3, 4, 6, 9})}));
  std::map<std::string, std::string> types;
  for (const auto* a : doc.one("Domain").one("Grid").one("Grid").all("Attribute"))
    types[a->attr("Name")] = a->attr("AttributeType");
  EXPECT_EQ(types, (std::map<std::string, std::string>{{"a1", "Scalar"},
                                                       {"a2", "Vector"},
                                                       {"a3", "Vector"},
                                                       {"a4", "Matrix"},
                                                       {"a6", "Tensor6"},
                                                       {"a9", "Tensor"}}));
}

TEST(XdmfDocument, StepsWithoutPointsOrPositionAreLeftOut) {
  XdmfStep no_position = step_with({1});
  no_position.arrays.erase(no_position.arrays.begin());
  XdmfStep integer_position = step_with({1});
  integer_position.arrays[0].floating = false;
  const auto doc = mini_xml::parse(isphdem::xdmf_document(
      "g", {step_with({1}, 0), no_position, integer_position, step_with({1}, 5)}));
  const auto grids = doc.one("Domain").one("Grid").all("Grid");
  ASSERT_EQ(grids.size(), 1u);
  EXPECT_EQ(grids[0]->one("Topology").attr("NumberOfElements"), "5");
}

TEST(XdmfDocument, NamesAreEscaped) {
  XdmfStep s = step_with({1});
  s.arrays[1].name = "a<b>&\"c\"";
  const auto doc = mini_xml::parse(isphdem::xdmf_document("x&y", {s}));
  const auto& grid = doc.one("Domain").one("Grid");
  EXPECT_EQ(grid.attr("Name"), "x&y");
  EXPECT_EQ(grid.one("Grid").one("Attribute").attr("Name"), "a<b>&\"c\"");
}

}  // namespace
