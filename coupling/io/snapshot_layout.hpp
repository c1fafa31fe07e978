// How the ranks' parts of one snapshot make up one file. Each rank hands the writer the rows it
// holds; the file holds every group's rows in rank order, so a fluid whose rows are shared out in
// blocks of the storage order (sph/row_share.hpp) is stored in the order one process stores it.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <string>
#include <vector>

#include "io/snapshot.hpp"
#include "io/xdmf_writer.hpp"

namespace isphdem {

struct ArrayShape {
  std::string name;
  std::size_t cols = 1;
  std::size_t type = 0;  // the index of Dataset::Values: double, int64, int32
};

struct GroupLayout {
  std::string name;
  std::vector<ArrayShape> arrays;
  std::size_t total = 0;         // rows in the file
  std::size_t offset = 0;        // the first row this rank writes
  const Group* local = nullptr;  // this rank's rows (nullptr: it has none of this group)
};

struct SnapshotLayout {
  long step = 0;
  double time = 0.0;
  std::vector<GroupLayout> groups;  // in the order of rank 0's snapshot
};

// Collective over `comm` (MPI_COMM_NULL: one process). Rank 0's snapshot fixes step, time, the
// groups and their datasets' names, columns and types; another rank may leave a group out (it
// then writes none of its rows) but the groups it has must match rank 0's exactly. Throws
// std::invalid_argument on every rank, naming the rank and what differs, if they do not.
// `local` must stay alive while the layout is used.
SnapshotLayout lay_out(const Snapshot& local, MPI_Comm comm);

// The shapes the file will have, for the .xdmf.
XdmfStep describe_layout(const SnapshotLayout& layout, const GroupLayout& group, std::string file);

}  // namespace isphdem
