#include "run/checkpoints.hpp"

#include <csignal>
#include <stdexcept>

#include "format_number.hpp"
#include "io/rank_agreement.hpp"
#include "run/interrupt.hpp"

namespace isphdem {

namespace fs = std::filesystem;

namespace {
constexpr int kKeep = 2;            // checkpoints kept
constexpr double kLanding = 1e-12;  // relative slack on a checkpoint time (as on output times)
}  // namespace

std::string checkpoint_rank_file(int rank) { return "rank_" + std::to_string(rank) + ".h5"; }

Checkpoints::Checkpoints(fs::path out, double interval, MPI_Comm comm)
    : out_(std::move(out)), interval_(interval), comm_(comm) {
  rank_ = rank_in(comm_);
  ranks_ = ranks_of(comm_);
}

void Checkpoints::start_fresh() {
  agree(comm_, [&] {
    if (rank_ == 0) remove_checkpoints(out_, true);
  });
}

RunPosition Checkpoints::resume(CheckpointArrays& arrays) {
  RunPosition p;
  agree(comm_, [&] {
    const auto all = list_checkpoints(out_);
    if (all.empty())
      throw std::runtime_error("--resume: no checkpoint in " + out_.string() +
                               " (checkpoint_<step>/): run the case without --resume");
    resumed_step_ = all.back().first;
    resumed_dir_ = all.back().second;
    if (!fs::exists(resumed_dir_ / checkpoint_rank_file(ranks_ - 1)) ||
        fs::exists(resumed_dir_ / checkpoint_rank_file(ranks_)))
      throw std::runtime_error("--resume: " + resumed_dir_.string() +
                               " was written by another number of MPI ranks than this run's " +
                               std::to_string(ranks_) + ": resume on as many ranks as ran it");
    arrays = read_checkpoint_arrays(resumed_dir_ / checkpoint_rank_file(rank_));
    if (rank_ == 0 && arrays.integer("run_identity") != identity_)
      throw std::runtime_error(
          "--resume: " + resumed_dir_.string() +
          " was written by a run of another case file (or an edited one) or with other --set "
          "options (time.end aside): resume with the command that run printed, or run anew "
          "without --resume");
  });
  // Rank 0's file says where the loop stood; every rank needs it.
  double v[5] = {0, 0, 0, 0, 0};
  agree(comm_, [&] {
    if (rank_ != 0) return;
    const CheckpointArrays& a = arrays;
    v[0] = double(a.integer("run_output_index"));
    v[1] = double(a.integer("run_next_checkpoint"));
    v[2] = double(a.integer("run_ppe_total"));
    v[3] = a.real("run_wall_seconds");
    v[4] = double(a.integer("run_ranks"));
  });
  if (comm_ != MPI_COMM_NULL) MPI_Bcast(v, 5, MPI_DOUBLE, 0, comm_);
  p.output_index = long(v[0]);
  p.next_checkpoint = long(v[1]);
  p.ppe_total = long(v[2]);
  p.wall_seconds = v[3];
  next_ = p.next_checkpoint;
  last_step_ = resumed_step_;
  agree(comm_, [&] {
    if (rank_ == 0) remove_checkpoints(out_, false);  // staged ones a killed run left
  });
  return p;
}

bool Checkpoints::due(double t) const {
  return interval_ > 0.0 && t >= double(next_) * interval_ * (1.0 - kLanding);
}

fs::path Checkpoints::write(long step, double t, RunPosition position,
                            const std::function<void(CheckpointArrays&, const fs::path&)>& fill) {
  if (interval_ > 0.0)
    while (t >= double(next_) * interval_ * (1.0 - kLanding)) ++next_;
  position.next_checkpoint = next_;
  fs::path staged;
  agree(comm_, [&] {
    if (rank_ == 0) staged = stage_checkpoint(out_, step);
  });
  staged = out_ / ("." + checkpoint_name(step) + ".tmp");
  CheckpointArrays mine;
  fill(mine, staged);
  agree(comm_, [&] {
    if (rank_ == 0) {
      mine.set_integer("run_output_index", position.output_index);
      mine.set_integer("run_next_checkpoint", position.next_checkpoint);
      mine.set_integer("run_ppe_total", position.ppe_total);
      mine.set("run_wall_seconds", position.wall_seconds);
      mine.set_integer("run_ranks", ranks_);
      mine.set_integer("run_identity", identity_);
      mine.set_integer("run_step", step);
      mine.set("run_time", t);
    }
    write_checkpoint_arrays(staged / checkpoint_rank_file(rank_), mine);
  });
  fs::path target;
  agree(comm_, [&] {
    if (rank_ == 0) target = commit_checkpoint(out_, step, kKeep);
  });
  last_step_ = step;
  return out_ / checkpoint_name(step);
}

void checkpoint_between_steps(double t, long steps, const Checkpoints& checkpoints, long k,
                              const std::function<fs::path(long)>& save) {
  const int signal = agreed_signal(MPI_COMM_WORLD);
  if (!signal && !checkpoints.due(t)) return;
  const fs::path dir = save(k);
  if (signal)
    throw Interrupted(signal, std::string(signal == SIGINT ? "SIGINT" : "SIGTERM") + " at t = " +
                                  isph::format_number(t, 6) + " s, step " + std::to_string(steps) +
                                  ": checkpoint " + dir.filename().string() + " written");
}

}  // namespace isphdem
