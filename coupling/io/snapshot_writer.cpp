#include "io/snapshot_writer.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/hdf5_handle.hpp"
#include "io/rank_agreement.hpp"
#include "io/snapshot_layout.hpp"

namespace isphdem {

namespace fs = std::filesystem;

namespace {

// snap_<digits>.h5
bool is_snapshot_name(const std::string& name, long* step = nullptr) {
  constexpr std::size_t prefix = 5, suffix = 3;  // "snap_", ".h5"
  if (name.size() <= prefix + suffix || name.compare(0, prefix, "snap_") != 0 ||
      name.compare(name.size() - suffix, suffix, ".h5") != 0)
    return false;
  const std::string digits = name.substr(prefix, name.size() - prefix - suffix);
  if (digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
    return false;  // (18 digits always fit a long)
  if (step) *step = std::stol(digits);
  return true;
}

bool is_xdmf_name(const std::string& name) {
  return name.size() > 5 && name.compare(name.size() - 5, 5, ".xdmf") == 0;
}

// Only our own temporaries: ".snap_<step>.h5.tmp", ".<group>.xdmf.tmp".
bool is_our_temporary(const std::string& name) {
  if (!is_temporary_name(name)) return false;
  const std::string target = name.substr(1, name.size() - 5);
  return is_snapshot_name(target) || is_xdmf_name(target);
}

// Names end up in HDF5 paths and XML, so keep them to characters that need no quoting there.
void check_name(const std::string& name, const std::string& what) {
  if (name.empty() || name.front() == '.' ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") !=
          std::string::npos)
    throw std::invalid_argument("snapshot: " + what + " name '" + name +
                                "' must be letters, digits, '_', '-', '.' (not leading)");
}

std::size_t value_count(const Dataset& d) {
  return std::visit([](const auto& v) { return v.size(); }, d.data);
}

void validate(const Snapshot& s) {
  if (s.step < 0) throw std::invalid_argument("snapshot: negative step " + std::to_string(s.step));
  if (!std::isfinite(s.time)) throw std::invalid_argument("snapshot: time is not finite");
  std::set<std::string> groups;
  for (const auto& g : s.groups) {
    check_name(g.name, "group");
    if (!groups.insert(g.name).second)
      throw std::invalid_argument("snapshot: group '" + g.name + "' appears twice");
    for (const auto& d : g.datasets) {
      const std::string where = "/" + g.name + "/" + d.name;
      check_name(d.name, "dataset " + where);
      if (d.cols == 0) throw std::invalid_argument("snapshot: " + where + " has 0 columns");
      if (value_count(d) != d.rows * d.cols)
        throw std::invalid_argument("snapshot: " + where + " holds " +
                                    std::to_string(value_count(d)) + " values, not rows x cols = " +
                                    std::to_string(d.rows) + " x " + std::to_string(d.cols));
      if (d.rows != g.datasets.front().rows)
        throw std::invalid_argument("snapshot: " + where + " has " + std::to_string(d.rows) +
                                    " rows but /" + g.name + "/" + g.datasets.front().name +
                                    " has " + std::to_string(g.datasets.front().rows) +
                                    " (a row is one particle)");
    }
  }
}

template <class T>
struct H5Types;
template <>
struct H5Types<double> {
  static hid_t file() { return H5T_IEEE_F64LE; }
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct H5Types<std::int64_t> {
  static hid_t file() { return H5T_STD_I64LE; }
  static hid_t memory() { return H5T_NATIVE_INT64; }
};
template <>
struct H5Types<std::int32_t> {
  static hid_t file() { return H5T_STD_I32LE; }
  static hid_t memory() { return H5T_NATIVE_INT32; }
};

template <class T>
void write_scalar_attribute(hid_t file, const char* name, T value, const std::string& context) {
  const std::string what = std::string("attribute ") + name;
  h5::Handle space(H5Screate(H5S_SCALAR), H5Sclose, context, "create dataspace for " + what);
  h5::Handle attr(H5Acreate2(file, name, H5Types<T>::file(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
                  H5Aclose, context, "create " + what);
  h5::check(H5Awrite(attr.id(), H5Types<T>::memory(), &value), context, "write " + what);
}

hid_t file_type(std::size_t type) {
  return type == 0   ? H5Types<double>::file()
         : type == 1 ? H5Types<std::int64_t>::file()
                     : H5Types<std::int32_t>::file();
}

hid_t memory_type(std::size_t type) {
  return type == 0   ? H5Types<double>::memory()
         : type == 1 ? H5Types<std::int64_t>::memory()
                     : H5Types<std::int32_t>::memory();
}

// Array k of `g`: the whole dataset, of which this rank writes its rows from g.offset on. With
// several ranks every rank takes part in the write (collective transfer), also with no rows.
void write_dataset(hid_t group, const std::string& path, const GroupLayout& g, std::size_t k,
                   hid_t transfer, const std::string& context) {
  const ArrayShape& a = g.arrays[k];
  const Dataset* mine = g.local ? &g.local->datasets[k] : nullptr;
  const hsize_t rows = mine ? mine->rows : 0;
  const hsize_t dims[2] = {g.total, a.cols}, local_dims[2] = {rows, a.cols};
  const int rank = a.cols == 1 ? 1 : 2;
  h5::Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose, context,
                   "create dataspace for dataset " + path);
  h5::Handle set(H5Dcreate2(group, a.name.c_str(), file_type(a.type), space.id(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, context, "create dataset " + path);
  // HDF5 rejects a null buffer even for zero elements.
  static const double nothing = 0.0;
  const void* data = &nothing;
  if (mine && rows > 0)
    data = std::visit([](const auto& v) { return static_cast<const void*>(v.data()); }, mine->data);
  // An empty dataset has no storage to write to (HDF5 fails on it, also with nothing selected).
  // Otherwise every rank writes, its rows or none (one process: all rows from offset 0).
  if (g.total > 0) {
    h5::Handle memory(H5Screate_simple(rank, local_dims, nullptr), H5Sclose, context,
                      "create memory dataspace for dataset " + path);
    const hsize_t start[2] = {g.offset, 0};
    if (rows == 0) {
      h5::check(H5Sselect_none(space.id()), context, "select no rows of dataset " + path);
      h5::check(H5Sselect_none(memory.id()), context, "select no rows for dataset " + path);
    } else {
      h5::check(
          H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, start, nullptr, local_dims, nullptr),
          context, "select this rank's rows of dataset " + path);
    }
    h5::check(H5Dwrite(set.id(), memory_type(a.type), memory.id(), space.id(), transfer, data),
              context, "write dataset " + path);
  }
  set.close(context, "close dataset " + path);
}

// With several ranks the file is opened by all of them through MPI-IO (parallel HDF5) and every
// call below is collective.
void write_hdf5(const fs::path& tmp, const SnapshotLayout& layout, MPI_Comm comm,
                const std::string& context) {
  h5::QuietErrors quiet;
  const bool parallel = ranks_of(comm) > 1;
  h5::Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, context, "create file access list");
  h5::Handle transfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose, context, "create transfer list");
  if (parallel) {
    h5::check(H5Pset_fapl_mpio(access.id(), comm, MPI_INFO_NULL), context, "use MPI-IO");
    h5::check(H5Pset_dxpl_mpio(transfer.id(), H5FD_MPIO_COLLECTIVE), context,
              "use collective transfers");
  }
  h5::Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id()), H5Fclose,
                  context, "create " + tmp.string());
  write_scalar_attribute<double>(file.id(), "time", layout.time, context);
  write_scalar_attribute<std::int64_t>(file.id(), "step", layout.step, context);
  for (const auto& g : layout.groups) {
    h5::Handle group(H5Gcreate2(file.id(), g.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Gclose, context, "create group /" + g.name);
    for (std::size_t k = 0; k < g.arrays.size(); ++k)
      write_dataset(group.id(), "/" + g.name + "/" + g.arrays[k].name, g, k, transfer.id(),
                    context);
    group.close(context, "close group /" + g.name);
  }
  file.close(context, "close (flush) file");
}

// --- reading back the shapes of an existing snapshot (continuing a run) ---

struct Names {
  std::vector<std::string> names;
};

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<Names*>(data)->names.push_back(name);
  return 0;
}

std::vector<std::string> children(hid_t location, const std::string& context,
                                  const std::string& what) {
  Names n;
  h5::check(H5Literate(location, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &n), context,
            "list " + what);
  return n.names;
}

template <class T>
T read_scalar_attribute(hid_t file, const char* name, const std::string& context) {
  T value{};
  h5::Handle attr(H5Aopen(file, name, H5P_DEFAULT), H5Aclose, context,
                  std::string("open attribute ") + name);
  h5::check(H5Aread(attr.id(), H5Types<T>::memory(), &value), context,
            std::string("read attribute ") + name);
  return value;
}

// One XdmfStep per group of the snapshot file at `path`.
std::vector<XdmfStep> describe_file(const fs::path& path) {
  const std::string context = "reading " + path.string();
  h5::QuietErrors quiet;
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, context, "open");
  const double time = read_scalar_attribute<double>(file.id(), "time", context);
  const long step = read_scalar_attribute<std::int64_t>(file.id(), "step", context);
  std::vector<XdmfStep> steps;
  for (const auto& g : children(file.id(), context, "/")) {
    h5::Handle group(H5Gopen2(file.id(), g.c_str(), H5P_DEFAULT), H5Gclose, context,
                     "open group /" + g);
    XdmfStep s;
    s.step = step;
    s.time = time;
    s.file = path.filename().string();
    s.group = g;
    for (const auto& d : children(group.id(), context, "/" + g)) {
      const std::string where = "/" + g + "/" + d;
      h5::Handle set(H5Dopen2(group.id(), d.c_str(), H5P_DEFAULT), H5Dclose, context,
                     "open dataset " + where);
      h5::Handle space(H5Dget_space(set.id()), H5Sclose, context, "get dataspace of " + where);
      h5::Handle type(H5Dget_type(set.id()), H5Tclose, context, "get type of " + where);
      hsize_t dims[2] = {0, 1};
      const int rank = H5Sget_simple_extent_ndims(space.id());
      if (rank < 1 || rank > 2)
        throw std::runtime_error(context + ": dataset " + where + " is not 1-D or 2-D");
      H5Sget_simple_extent_dims(space.id(), dims, nullptr);
      XdmfArray a;
      a.name = d;
      a.cols = rank == 1 ? 1 : dims[1];
      a.floating = H5Tget_class(type.id()) == H5T_FLOAT;
      a.bytes = static_cast<int>(H5Tget_size(type.id()));
      s.rows = dims[0];
      s.arrays.push_back(std::move(a));
    }
    steps.push_back(std::move(s));
  }
  file.close(context, "close");
  return steps;
}

}  // namespace

std::string SnapshotWriter::file_name(long step) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "snap_%08ld.h5", step);
  return buf;
}

SnapshotWriter::SnapshotWriter(fs::path dir, bool fresh, MPI_Comm comm)
    : dir_(std::move(dir)), comm_(comm), lead_(rank_in(comm) == 0) {
  // Rank 0 alone prepares the directory; the others learn whether it could.
  agree(comm_, [&] {
    if (lead_) prepare(fresh);
  });
}

void SnapshotWriter::prepare(bool fresh) {
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw std::runtime_error("output directory " + dir_.string() +
                             " exists and is not a directory");
  fs::create_directories(dir_, ec);
  if (ec)
    throw std::runtime_error("cannot create output directory " + dir_.string() + ": " +
                             ec.message());
  for (const auto& entry : fs::directory_iterator(dir_)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    const bool stale =
        is_our_temporary(name) ||
        (fresh && (is_snapshot_name(name) || is_xdmf_name(name) || name == "diagnostics.csv"));
    if (stale && !fs::remove(entry.path(), ec) && ec)
      throw std::runtime_error("cannot remove " + entry.path().string() + ": " + ec.message());
  }
  if (!fresh) index_existing();
}

void SnapshotWriter::index_existing() {
  for (const auto& entry : fs::directory_iterator(dir_)) {
    if (!entry.is_regular_file() || !is_snapshot_name(entry.path().filename().string())) continue;
    for (auto& s : describe_file(entry.path())) index_[s.group][s.step] = std::move(s);
  }
}

void SnapshotWriter::drop_steps_after(long step) {
  for (const auto& entry : fs::directory_iterator(dir_)) {
    long s = 0;
    if (entry.is_regular_file() && is_snapshot_name(entry.path().filename().string(), &s) &&
        s > step)
      fs::remove(entry.path());
  }
  for (auto& [group, steps] : index_) {
    steps.erase(steps.upper_bound(step), steps.end());
    update_xdmf(group);
  }
}

void SnapshotWriter::resume_after(long step) {
  agree(comm_, [&] {
    if (lead_) drop_steps_after(step);
  });
  written_ = true;
}

void SnapshotWriter::update_xdmf(const std::string& group) {
  const fs::path path = dir_ / (group + ".xdmf");
  std::vector<XdmfStep> steps;
  bool drawable = false;
  for (const auto& [step, s] : index_[group]) {
    steps.push_back(s);
    drawable = drawable || s.drawable();
  }
  // A group never seen with particles (no DEM in a fluid-only run) gets no .xdmf at all.
  if (drawable || fs::exists(path)) write_xdmf(path, group, steps);
}

fs::path SnapshotWriter::write(const Snapshot& snapshot) {
  agree(comm_, [&] { validate(snapshot); });
  const SnapshotLayout layout = lay_out(snapshot, comm_);
  if (!written_)
    agree(comm_, [&] {
      if (lead_) drop_steps_after(layout.step);
    });
  written_ = true;

  const std::string name = file_name(layout.step);
  const fs::path target = dir_ / name;
  const fs::path tmp = temporary_path_for(target);
  const std::string context = "writing " + target.string();
  try {
    agree(comm_, [&] { write_hdf5(tmp, layout, comm_, context); });
  } catch (...) {
    std::error_code ignored;
    if (lead_) fs::remove(tmp, ignored);
    throw;
  }
  agree(comm_, [&] {
    if (!lead_) return;
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
      fs::remove(tmp, ec);
      throw std::runtime_error(context + ": cannot rename " + tmp.string() + ": " + ec.message());
    }
    std::set<std::string> touched;
    for (auto& [group, steps] : index_)
      if (steps.erase(layout.step)) touched.insert(group);  // the file there was just replaced
    for (const auto& g : layout.groups) {
      index_[g.name][layout.step] = describe_layout(layout, g, name);
      touched.insert(g.name);
    }
    for (const auto& group : touched) update_xdmf(group);
  });
  return target;
}

}  // namespace isphdem
