// XDMF 2 "light data" that makes a series of snap_<step>.h5 files one ParaView time series per
// group: a Temporal Collection of Uniform grids with Polyvertex topology (one vertex per
// particle), Geometry XY or XYZ from <group>/position, every other dataset an attribute.
//
// Checked with ParaView 5.11 (pvpython, tests/output/check_xdmf.py): its "XDMF Reader" accepts
// GeometryType XY and pads z = 0, and pads 2-component vectors to 3; an empty grid (0 particles)
// makes it report errors and makes the Xdmf3 readers abort, so steps without particles are left
// out of the collection.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace isphdem {

struct XdmfArray {
  std::string name;
  std::size_t cols = 1;  // 1: stored 1-D; otherwise rows x cols
  bool floating = true;  // false: signed integer
  int bytes = 8;         // 4 or 8
};

// One time step of one group: where its datasets live and their shapes.
struct XdmfStep {
  long step = 0;
  double time = 0.0;
  std::string file;  // HDF5 file, relative to the directory of the .xdmf
  std::string group;
  std::size_t rows = 0;
  std::vector<XdmfArray> arrays;  // must include "position" with 2 or 3 cols to be shown

  bool drawable() const;  // has particles and a usable "position"
};

// The document for `steps` (in the given order; steps that are not drawable are skipped).
std::string xdmf_document(const std::string& name, const std::vector<XdmfStep>& steps);

// Replaces `path` atomically with xdmf_document(name, steps).
void write_xdmf(const std::filesystem::path& path, const std::string& name,
                const std::vector<XdmfStep>& steps);

}  // namespace isphdem
