// What one output step holds, as plain tables: groups ("fluid", "dem", "bodies") of datasets whose
// rows are particles (or bodies). The solver copies its arrays in here, so the writers never see
// solver types and can be tested on their own.
//
// Shapes: a dataset with cols == 1 is stored 1-D (rows), any other 2-D (rows x cols), row-major.
// Every dataset of a group must have the same number of rows; a group that should appear in
// ParaView needs a double dataset "position" with 2 or 3 columns (docs/output.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace isphdem {

struct Dataset {
  using Values =
      std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::int32_t>>;
  std::string name;
  Values data;  // rows * cols values, row-major
  std::size_t rows = 0;
  std::size_t cols = 1;
};

struct Group {
  std::string name;
  std::vector<Dataset> datasets;

  // Copies rows * cols values from `values` (row-major; cols == 1 for a per-particle scalar).
  template <class T>
  Dataset& add(std::string dataset_name, const T* values, std::size_t rows, std::size_t cols = 1) {
    return add_values(std::move(dataset_name), std::vector<T>(values, values + rows * cols), rows,
                      cols);
  }

  // For solver layouts that are not one contiguous array (array of structs, Eigen vectors,
  // strided storage): value(i, c) gives column c of row i.
  template <class T, class F>
  Dataset& add_generated(std::string dataset_name, std::size_t rows, std::size_t cols, F value) {
    std::vector<T> v;
    v.reserve(rows * cols);
    for (std::size_t i = 0; i < rows; ++i)
      for (std::size_t c = 0; c < cols; ++c) v.push_back(static_cast<T>(value(i, c)));
    return add_values(std::move(dataset_name), std::move(v), rows, cols);
  }

  template <class T>
  Dataset& add_values(std::string dataset_name, std::vector<T> values, std::size_t rows,
                      std::size_t cols = 1) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::int64_t> ||
                      std::is_same_v<T, std::int32_t>,
                  "snapshot datasets hold double, int64_t or int32_t: convert with add_generated");
    datasets.push_back(
        Dataset{std::move(dataset_name), Dataset::Values(std::move(values)), rows, cols});
    return datasets.back();
  }

  const Dataset* find(std::string_view dataset_name) const {
    for (const auto& d : datasets)
      if (d.name == dataset_name) return &d;
    return nullptr;
  }
};

struct Snapshot {
  long step = 0;
  double time = 0.0;  // simulated seconds
  std::vector<Group> groups;

  // The group called `name`, appended if missing. The reference is invalidated by the next call
  // that appends a group.
  Group& group(std::string_view name) {
    for (auto& g : groups)
      if (g.name == name) return g;
    groups.push_back(Group{std::string(name), {}});
    return groups.back();
  }

  const Group* find(std::string_view name) const {
    for (const auto& g : groups)
      if (g.name == name) return &g;
    return nullptr;
  }
};

}  // namespace isphdem
