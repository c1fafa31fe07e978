#pragma once
// When a run writes its checkpoints and how the ranks write one together (docs/output.md,
// "Checkpoints and --resume"): every output.checkpoint_interval of simulated time, at the end of
// a finished run, and when interrupted. A checkpoint is DIR/checkpoint_<step>/ with one file per
// rank (rank_<r>.h5: that rank's fluid; rank 0's also where the run's loop stood), plus what
// `extra` puts into the staged directory (LIGGGHTS's restart). The last two are kept.
#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "io/checkpoint.hpp"

namespace isphdem {

// Where the run's loop stood at the checkpoint, besides the fluid: the output time it was
// stepping towards (run_to_end's k), the next checkpoint's index, and the running totals that
// result.json reports.
struct RunPosition {
  long output_index = 1;
  long next_checkpoint = 1;
  long ppe_total = 0;
  double wall_seconds = 0.0;
};

class Checkpoints {
 public:
  // interval: output.checkpoint_interval in simulated seconds (0: only an interrupted run writes
  // one). comm: the ranks of the run (MPI_COMM_NULL: one process).
  Checkpoints(std::filesystem::path out, double interval, MPI_Comm comm);

  // Which run this is (io/checkpoint.hpp's run_identity): written into every checkpoint, and
  // resume() refuses a checkpoint of another.
  void set_identity(std::int64_t identity) { identity_ = identity; }

  // A fresh run: rank 0 removes the checkpoints an earlier run left in the directory. Collective.
  void start_fresh();
  // --resume: reads this rank's file of the newest checkpoint into `arrays` and where the run
  // stood. std::runtime_error when there is none, or when it was written by another number of
  // ranks. Collective.
  RunPosition resume(CheckpointArrays& arrays);
  long resumed_step() const { return resumed_step_; }
  const std::filesystem::path& resumed_directory() const { return resumed_dir_; }

  // Whether simulated time `t` has reached the next scheduled checkpoint.
  bool due(double t) const;
  // Writes checkpoint `step`: `fill` puts this rank's arrays into its file and anything else
  // into the staged directory (called on every rank, collective calls allowed); rank 0's file
  // also gets `position`. Moves the schedule past `t`. Collective; every rank throws the first
  // failing rank's error. Returns the checkpoint's directory.
  std::filesystem::path write(
      long step, double t, RunPosition position,
      const std::function<void(CheckpointArrays&, const std::filesystem::path&)>& fill);
  long next_checkpoint() const { return next_; }
  long last_written() const { return last_step_; }

 private:
  std::filesystem::path out_;
  double interval_;
  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
  long next_ = 1;
  std::int64_t identity_ = 0;
  long resumed_step_ = -1;
  long last_step_ = -1;
  std::filesystem::path resumed_dir_;
};

// rank_<r>.h5
std::string checkpoint_rank_file(int rank);

// What a run's loop does between two steps (run_to_end's between_steps), the run at simulated
// time `t` after `steps` steps and stepping towards output time k: `save(k)` writes a checkpoint
// when one is due, and when any rank got SIGINT or SIGTERM, after which Interrupted is thrown
// (interrupt.hpp). Collective.
void checkpoint_between_steps(double t, long steps, const Checkpoints& checkpoints, long k,
                              const std::function<std::filesystem::path(long)>& save);

}  // namespace isphdem
