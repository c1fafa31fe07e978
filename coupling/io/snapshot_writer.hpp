// Writes one HDF5 file per output step, DIR/snap_<step>.h5, and keeps DIR/<group>.xdmf (fluid,
// dem, bodies: every group with a "position") listing all of them for ParaView. Layout and
// guarantees are in docs/output.md.
//
// On several MPI ranks (a communicator given) the ranks write each snapshot together, each its
// own rows (parallel HDF5, collective; io/snapshot_layout.hpp says how the parts make up the
// file); rank 0 alone touches the directory and the .xdmf. Every call is then collective, and an
// error on any rank is thrown on every rank with that rank's message (io/rank_agreement.hpp).
//
// Crash safety: each file is written under a hidden temporary name and renamed into place, so at
// any moment every snap_*.h5 and *.xdmf in DIR is complete, and the .xdmf only lists snapshots
// that exist. Nothing needs to be called at the end of a run.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <map>
#include <string>

#include "io/snapshot.hpp"
#include "io/xdmf_writer.hpp"

namespace isphdem {

class SnapshotWriter {
 public:
  // Creates `dir` if needed (std::runtime_error if it exists and is not a directory).
  // fresh: remove what an earlier run left in `dir` (snap_*.h5, *.xdmf, diagnostics.csv), so old
  //   and new results never mix. Construct it before the DiagnosticsWriter for the same directory.
  // !fresh (continuing a run): keep existing snapshots and list them in the .xdmf; the first
  //   write() removes the ones after its step, which belong to the abandoned continuation.
  explicit SnapshotWriter(std::filesystem::path dir, bool fresh = true,
                          MPI_Comm comm = MPI_COMM_NULL);

  // Writes DIR/snap_<step>.h5 (on several ranks: this rank's rows of it) (replacing a snapshot of
  // the same step) and rewrites the .xdmf of each group in it. std::invalid_argument for a
  // malformed snapshot (nothing written), std::runtime_error naming file and dataset if HDF5 or the
  // file system fails (the previous snapshots and .xdmf stay as they were). Returns the path
  // written.
  std::filesystem::path write(const Snapshot& snapshot);

  // Continuing from a checkpoint at `step` (!fresh): removes the snapshots after it, which the
  // continuation writes again, so that the .xdmf lists each time once. Collective.
  void resume_after(long step);

  const std::filesystem::path& directory() const { return dir_; }

  static std::string file_name(long step);  // "snap_00001200.h5"

 private:
  void prepare(bool fresh);
  void index_existing();
  void drop_steps_after(long step);
  void update_xdmf(const std::string& group);

  std::filesystem::path dir_;
  std::map<std::string, std::map<long, XdmfStep>> index_;  // group -> step -> shapes
  MPI_Comm comm_;
  bool lead_;  // rank 0 (or the only process)
  bool written_ = false;
};

}  // namespace isphdem
