// Reads snapshots back with the plain HDF5 C API, independently of the writer's own code, so a
// round trip checks the file itself rather than the writer agreeing with itself.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace h5_read {

// Stored dtype, as HDF5 file types (the contract is little-endian IEEE / two's complement).
enum class Type { f64, i64, i32, other };

struct Array {
  Type type = Type::other;
  std::vector<hsize_t> dims;
  std::vector<double> f64;
  std::vector<std::int64_t> i64;
  std::vector<std::int32_t> i32;
};

class File {
 public:
  explicit File(const std::string& path) {
    id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id_ < 0) throw std::runtime_error("cannot open " + path);
  }
  ~File() { H5Fclose(id_); }
  File(const File&) = delete;
  File& operator=(const File&) = delete;

  bool has(const std::string& path) const { return H5Lexists(id_, path.c_str(), H5P_DEFAULT) > 0; }

  Array read(const std::string& path) const {
    Array a;
    const hid_t set = H5Dopen2(id_, path.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + path);
    const hid_t space = H5Dget_space(set);
    const hid_t type = H5Dget_type(set);
    a.dims.resize(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, a.dims.data(), nullptr);
    std::size_t n = 1;
    for (auto d : a.dims) n *= d;
    herr_t status = 0;
    if (H5Tequal(type, H5T_IEEE_F64LE) > 0) {
      a.type = Type::f64;
      a.f64.resize(n);
      if (n) status = H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.f64.data());
    } else if (H5Tequal(type, H5T_STD_I64LE) > 0) {
      a.type = Type::i64;
      a.i64.resize(n);
      if (n) status = H5Dread(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.i64.data());
    } else if (H5Tequal(type, H5T_STD_I32LE) > 0) {
      a.type = Type::i32;
      a.i32.resize(n);
      if (n) status = H5Dread(set, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.i32.data());
    }
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(set);
    if (status < 0) throw std::runtime_error("cannot read " + path);
    return a;
  }

  double attribute_f64(const char* name) const {
    double v = 0;
    read_attribute(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v);
    return v;
  }
  std::int64_t attribute_i64(const char* name) const {
    std::int64_t v = 0;
    read_attribute(name, H5T_STD_I64LE, H5T_NATIVE_INT64, &v);
    return v;
  }

 private:
  void read_attribute(const char* name, hid_t file_type, hid_t memory_type, void* out) const {
    const hid_t attr = H5Aopen(id_, name, H5P_DEFAULT);
    if (attr < 0) throw std::runtime_error(std::string("no root attribute ") + name);
    const hid_t type = H5Aget_type(attr);
    const bool same = H5Tequal(type, file_type) > 0;
    const hid_t space = H5Aget_space(attr);
    const bool scalar = H5Sget_simple_extent_type(space) == H5S_SCALAR;
    const herr_t status = H5Aread(attr, memory_type, out);
    H5Sclose(space);
    H5Tclose(type);
    H5Aclose(attr);
    if (!same || !scalar || status < 0)
      throw std::runtime_error(std::string("root attribute ") + name + " has the wrong type/shape");
  }

  hid_t id_ = -1;
};

}  // namespace h5_read
