#include "io/snapshot_layout.hpp"

#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "io/rank_agreement.hpp"

namespace isphdem {

namespace {

constexpr const char* kTypeNames[] = {"double", "int64", "int32"};

SnapshotLayout shapes_of(const Snapshot& s) {
  SnapshotLayout layout;
  layout.step = s.step;
  layout.time = s.time;
  for (const auto& g : s.groups) {
    GroupLayout out;
    out.name = g.name;
    out.local = &g;
    out.total = g.datasets.empty() ? 0 : g.datasets.front().rows;
    for (const auto& d : g.datasets) out.arrays.push_back({d.name, d.cols, d.data.index()});
    layout.groups.push_back(std::move(out));
  }
  return layout;
}

// Names are letters, digits, '_', '-' and '.' (checked by the writer), so spaces and newlines
// separate them safely. The time goes as its bits, so that "equal" means equal.
std::string encode(const SnapshotLayout& layout) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &layout.time, sizeof bits);
  std::ostringstream out;
  out << layout.step << ' ' << bits << '\n';
  for (const auto& g : layout.groups) {
    out << "g " << g.name << ' ' << g.arrays.size() << '\n';
    for (const auto& a : g.arrays) out << a.name << ' ' << a.cols << ' ' << a.type << '\n';
  }
  return out.str();
}

SnapshotLayout decode(const std::string& text) {
  std::istringstream in(text);
  SnapshotLayout layout;
  std::uint64_t bits = 0;
  in >> layout.step >> bits;
  std::memcpy(&layout.time, &bits, sizeof bits);
  std::string tag;
  std::size_t count = 0;
  while (in >> tag) {
    GroupLayout g;
    in >> g.name >> count;
    g.arrays.resize(count);
    for (auto& a : g.arrays) in >> a.name >> a.cols >> a.type;
    layout.groups.push_back(std::move(g));
  }
  return layout;
}

std::string shape_text(const ArrayShape& a) {
  return std::to_string(a.cols) + " column(s) of " + kTypeNames[a.type];
}

// Fills `lead`'s local pointers from `mine`, or throws naming the first difference.
void match(SnapshotLayout& lead, const SnapshotLayout& mine) {
  if (mine.step != lead.step || mine.time != lead.time)
    throw std::invalid_argument("snapshot of step " + std::to_string(mine.step) +
                                " at t = " + std::to_string(mine.time) + " s, rank 0's of step " +
                                std::to_string(lead.step) + " at t = " + std::to_string(lead.time) +
                                " s: the ranks must write one step");
  for (const auto& g : mine.groups) {
    GroupLayout* to = nullptr;
    for (auto& l : lead.groups)
      if (l.name == g.name) to = &l;
    if (!to) throw std::invalid_argument("group /" + g.name + " is not in rank 0's snapshot");
    for (std::size_t k = 0; k < std::max(g.arrays.size(), to->arrays.size()); ++k) {
      const ArrayShape* a = k < g.arrays.size() ? &g.arrays[k] : nullptr;
      const ArrayShape* b = k < to->arrays.size() ? &to->arrays[k] : nullptr;
      const std::string where = "/" + g.name + "/" + (a ? a->name : b->name);
      if (!a || !b || a->name != b->name)
        throw std::invalid_argument(
            "group /" + g.name + " holds other datasets than rank 0's (first difference at " +
            where + "): every rank's group must hold the same datasets in the same order");
      if (a->cols != b->cols || a->type != b->type)
        throw std::invalid_argument(where + " has " + shape_text(*a) + ", rank 0's " +
                                    shape_text(*b));
    }
    to->local = g.local;
  }
}

}  // namespace

SnapshotLayout lay_out(const Snapshot& local, MPI_Comm comm) {
  SnapshotLayout mine = shapes_of(local);
  const int ranks = ranks_of(comm);
  if (ranks == 1) return mine;

  std::string text = encode(mine);
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, 0, comm);
  SnapshotLayout layout = decode(text);
  agree(comm, [&] { match(layout, mine); });

  // Every rank's rows of every group, then each group's rows in rank order.
  const std::size_t groups = layout.groups.size();
  std::vector<unsigned long long> rows(groups, 0), all(groups * ranks, 0);
  for (std::size_t k = 0; k < groups; ++k) {
    const Group* g = layout.groups[k].local;
    rows[k] = g && !g->datasets.empty() ? g->datasets.front().rows : 0;
  }
  MPI_Allgather(rows.data(), static_cast<int>(groups), MPI_UNSIGNED_LONG_LONG, all.data(),
                static_cast<int>(groups), MPI_UNSIGNED_LONG_LONG, comm);
  const int me = rank_in(comm);
  for (std::size_t k = 0; k < groups; ++k)
    for (int r = 0; r < ranks; ++r) {
      const auto n = static_cast<std::size_t>(all[r * groups + k]);
      if (r < me) layout.groups[k].offset += n;
      layout.groups[k].total += n;
    }
  return layout;
}

XdmfStep describe_layout(const SnapshotLayout& layout, const GroupLayout& group, std::string file) {
  XdmfStep s;
  s.step = layout.step;
  s.time = layout.time;
  s.file = std::move(file);
  s.group = group.name;
  s.rows = group.total;
  for (const auto& a : group.arrays) {
    XdmfArray x;
    x.name = a.name;
    x.cols = a.cols;
    x.floating = a.type == 0;
    x.bytes = a.type == 2 ? 4 : 8;
    s.arrays.push_back(std::move(x));
  }
  return s;
}

}  // namespace isphdem
