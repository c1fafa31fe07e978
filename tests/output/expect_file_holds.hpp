// A snapshot file read back with the plain HDF5 C API (h5_read.hpp) against the snapshot written.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "h5_read.hpp"
#include "io/snapshot.hpp"

namespace output_test {

// Every dataset of `s` is in the file with the same dtype, shape and values.
inline void expect_file_holds(const std::filesystem::path& path, const isphdem::Snapshot& s) {
  h5_read::File f(path.string());
  EXPECT_EQ(f.attribute_f64("time"), s.time);
  EXPECT_EQ(f.attribute_i64("step"), s.step);
  for (const auto& g : s.groups) {
    for (const auto& d : g.datasets) {
      const std::string where = "/" + g.name + "/" + d.name;
      SCOPED_TRACE(where);
      const h5_read::Array a = f.read(where);
      if (d.cols == 1)
        EXPECT_EQ(a.dims, (std::vector<hsize_t>{d.rows}));
      else
        EXPECT_EQ(a.dims, (std::vector<hsize_t>{d.rows, d.cols}));
      if (auto* v = std::get_if<std::vector<double>>(&d.data)) {
        EXPECT_EQ(a.type, h5_read::Type::f64);
        EXPECT_EQ(a.f64, *v);
      } else if (auto* v = std::get_if<std::vector<std::int64_t>>(&d.data)) {
        EXPECT_EQ(a.type, h5_read::Type::i64);
        EXPECT_EQ(a.i64, *v);
      } else if (auto* v = std::get_if<std::vector<std::int32_t>>(&d.data)) {
        EXPECT_EQ(a.type, h5_read::Type::i32);
        EXPECT_EQ(a.i32, *v);
      }
    }
  }
}

}  // namespace output_test
