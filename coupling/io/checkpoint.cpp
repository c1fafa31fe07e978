#include "io/checkpoint.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "io/hdf5_handle.hpp"

namespace isphdem {

namespace fs = std::filesystem;

namespace {

template <class T>
const std::vector<T>& find_array(const std::map<std::string, std::vector<T>>& arrays,
                                 const std::string& name) {
  const auto it = arrays.find(name);
  if (it == arrays.end())
    throw std::runtime_error("checkpoint: no array '" + name +
                             "' (a checkpoint of another kind of run, or of an older isphdem)");
  return it->second;
}

template <class T>
void write_array(hid_t file, const std::string& name, const std::vector<T>& v, hid_t file_type,
                 hid_t memory_type, const std::string& context) {
  const hsize_t dims[1] = {v.size()};
  h5::Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose, context,
                   "create dataspace for " + name);
  h5::Handle set(
      H5Dcreate2(file, name.c_str(), file_type, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, context, "create dataset " + name);
  static const T nothing{};  // HDF5 rejects a null buffer even for zero elements
  h5::check(H5Dwrite(set.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                     v.empty() ? &nothing : v.data()),
            context, "write dataset " + name);
}

// "checkpoint_<digits>" -> step
bool parse_checkpoint_name(const std::string& name, long& step) {
  const std::string prefix = "checkpoint_";
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string digits = name.substr(prefix.size());
  if (digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
    return false;
  step = std::stol(digits);
  return true;
}

void remove_tree(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
  if (ec) throw std::runtime_error("cannot remove " + p.string() + ": " + ec.message());
}

}  // namespace

const std::vector<double>& CheckpointArrays::real_array(const std::string& name) const {
  return find_array(reals, name);
}

const std::vector<std::int64_t>& CheckpointArrays::integer_array(const std::string& name) const {
  return find_array(integers, name);
}

double CheckpointArrays::real(const std::string& name) const {
  const auto& v = real_array(name);
  if (v.size() != 1) throw std::runtime_error("checkpoint: '" + name + "' is not one value");
  return v[0];
}

std::int64_t CheckpointArrays::integer(const std::string& name) const {
  const auto& v = integer_array(name);
  if (v.size() != 1) throw std::runtime_error("checkpoint: '" + name + "' is not one value");
  return v[0];
}

void write_checkpoint_arrays(const fs::path& path, const CheckpointArrays& arrays) {
  const std::string context = "writing checkpoint " + path.string();
  h5::QuietErrors quiet;
  h5::Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                  context, "create file");
  for (const auto& [name, v] : arrays.reals)
    write_array(file.id(), name, v, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, context);
  for (const auto& [name, v] : arrays.integers) {
    if (arrays.reals.count(name))
      throw std::invalid_argument("checkpoint: '" + name + "' is both a real and an integer array");
    write_array(file.id(), name, v, H5T_STD_I64LE, H5T_NATIVE_INT64, context);
  }
  file.close(context, "close");
}

CheckpointArrays read_checkpoint_arrays(const fs::path& path) {
  const std::string context = "reading checkpoint " + path.string();
  h5::QuietErrors quiet;
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, context,
                  "open file");
  H5G_info_t info;
  h5::check(H5Gget_info(file.id(), &info), context, "list datasets");
  CheckpointArrays arrays;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    char name[256];
    const ssize_t length = H5Lget_name_by_idx(file.id(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name,
                                              sizeof name, H5P_DEFAULT);
    if (length < 0 || length >= ssize_t(sizeof name))
      throw std::runtime_error(context + ": cannot read the name of dataset " + std::to_string(k));
    h5::Handle set(H5Dopen2(file.id(), name, H5P_DEFAULT), H5Dclose, context,
                   std::string("open dataset ") + name);
    h5::Handle space(H5Dget_space(set.id()), H5Sclose, context, "get dataspace");
    h5::Handle type(H5Dget_type(set.id()), H5Tclose, context, "get type");
    const hssize_t n = H5Sget_simple_extent_npoints(space.id());
    if (n < 0) throw std::runtime_error(context + ": dataset " + name + " has no size");
    if (H5Tget_class(type.id()) == H5T_FLOAT) {
      auto& v = arrays.reals[name];
      v.resize(std::size_t(n) + 1);  // never a null buffer
      h5::check(H5Dread(set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
                context, std::string("read dataset ") + name);
      v.resize(std::size_t(n));
    } else {
      auto& v = arrays.integers[name];
      v.resize(std::size_t(n) + 1);
      h5::check(H5Dread(set.id(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
                context, std::string("read dataset ") + name);
      v.resize(std::size_t(n));
    }
  }
  file.close(context, "close");
  return arrays;
}

std::string checkpoint_name(long step) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "checkpoint_%08ld", step);
  return buf;
}

std::vector<std::pair<long, fs::path>> list_checkpoints(const fs::path& dir) {
  std::vector<std::pair<long, fs::path>> found;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return found;
  for (const auto& entry : fs::directory_iterator(dir)) {
    long step = 0;
    if (entry.is_directory() && parse_checkpoint_name(entry.path().filename().string(), step))
      found.emplace_back(step, entry.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

fs::path stage_checkpoint(const fs::path& dir, long step) {
  const fs::path staged = dir / ("." + checkpoint_name(step) + ".tmp");
  remove_tree(staged);
  std::error_code ec;
  fs::create_directories(staged, ec);
  if (ec) throw std::runtime_error("cannot create " + staged.string() + ": " + ec.message());
  return staged;
}

fs::path commit_checkpoint(const fs::path& dir, long step, int keep) {
  const fs::path staged = dir / ("." + checkpoint_name(step) + ".tmp");
  const fs::path target = dir / checkpoint_name(step);
  remove_tree(target);  // a directory is not replaced by rename
  std::error_code ec;
  fs::rename(staged, target, ec);
  if (ec)
    throw std::runtime_error("cannot rename " + staged.string() + " to " + target.string() + ": " +
                             ec.message());
  const auto all = list_checkpoints(dir);
  for (std::size_t k = 0; k + std::size_t(std::max(keep, 1)) < all.size(); ++k)
    remove_tree(all[k].second);
  return target;
}

void remove_checkpoints(const fs::path& dir, bool all) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    long step = 0;
    const bool staged = name.size() > 5 && name[0] == '.' &&
                        name.compare(name.size() - 4, 4, ".tmp") == 0 &&
                        parse_checkpoint_name(name.substr(1, name.size() - 5), step);
    if (entry.is_directory() && (staged || (all && parse_checkpoint_name(name, step))))
      doomed.push_back(entry.path());
  }
  for (const auto& p : doomed) remove_tree(p);
}

std::int64_t run_identity(const std::string& case_fingerprint,
                          const std::vector<std::string>& overrides) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  auto add = [&](const std::string& text) {
    for (const char c : text + '\n') {
      h ^= static_cast<unsigned char>(c);
      h *= 1099511628211ull;
    }
  };
  add(case_fingerprint);
  for (const auto& o : overrides) {
    std::string key = o.substr(0, o.find('='));
    key.erase(0, key.find_first_not_of(" \t"));
    key.erase(key.find_last_not_of(" \t") + 1);
    if (key != "time.end") add(o);
  }
  return static_cast<std::int64_t>(h);
}

std::optional<std::int64_t> checkpoint_identity(const fs::path& dir) {
  const auto all = list_checkpoints(dir);
  if (all.empty()) return std::nullopt;
  try {
    return read_checkpoint_arrays(all.back().second / "rank_0.h5").integer("run_identity");
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::uintmax_t directory_bytes(const fs::path& path) {
  std::uintmax_t bytes = 0;
  std::error_code ec;
  for (const auto& entry : fs::recursive_directory_iterator(path, ec))
    if (entry.is_regular_file()) bytes += entry.file_size();
  return bytes;
}

}  // namespace isphdem
