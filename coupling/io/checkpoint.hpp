// Checkpoints of a run (docs/output.md, "Checkpoints and --resume"): DIR/checkpoint_<step>/, a
// directory per checkpoint holding one HDF5 file of named arrays per process (and, in coupled
// runs, LIGGGHTS's own restart). A checkpoint is assembled under a hidden staging name and renamed
// into place, so a killed run leaves every checkpoint_* complete; the newest `keep` are kept.
//
// The files know named arrays, not solvers: coupling/run/ says which arrays a run saves.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isphdem {

// One process's state as named arrays (a scalar is an array of one value). Names are letters,
// digits and '_'. Values are stored as they are in memory: read back, they are the same bits.
struct CheckpointArrays {
  std::map<std::string, std::vector<double>> reals;
  std::map<std::string, std::vector<std::int64_t>> integers;

  void set(const std::string& name, double value) { reals[name] = {value}; }
  void set_integer(const std::string& name, std::int64_t value) { integers[name] = {value}; }
  // std::runtime_error naming the array when it is missing (or, for a scalar, not one value).
  const std::vector<double>& real_array(const std::string& name) const;
  const std::vector<std::int64_t>& integer_array(const std::string& name) const;
  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
};

// Writes `arrays` to `file` (replacing it), std::runtime_error naming file and array on failure.
void write_checkpoint_arrays(const std::filesystem::path& file, const CheckpointArrays& arrays);
// Reads every array of a file write_checkpoint_arrays wrote.
CheckpointArrays read_checkpoint_arrays(const std::filesystem::path& file);

// "checkpoint_00001200"
std::string checkpoint_name(long step);
// The checkpoints in `dir`, oldest first, as (step, path).
std::vector<std::pair<long, std::filesystem::path>> list_checkpoints(
    const std::filesystem::path& dir);
// DIR/.checkpoint_<step>.tmp, created empty (an earlier attempt's content removed).
std::filesystem::path stage_checkpoint(const std::filesystem::path& dir, long step);
// Renames the staged checkpoint of `step` into place (replacing one of the same step), then
// removes all but the newest `keep` checkpoints. Returns the checkpoint's path.
std::filesystem::path commit_checkpoint(const std::filesystem::path& dir, long step, int keep);
// Removes staged checkpoints a killed run left; with `all`, every checkpoint too (a fresh run).
void remove_checkpoints(const std::filesystem::path& dir, bool all);
// Which run a checkpoint belongs to: a fingerprint of the case file's (hex, as result.json's
// case_fingerprint) and of the --set options but time.end (a resumed run may end later). Rank 0's
// file of every checkpoint holds it as "run_identity".
std::int64_t run_identity(const std::string& case_fingerprint,
                          const std::vector<std::string>& overrides);
// The run_identity of the newest checkpoint in `dir`; nothing when there is none or it cannot be
// read.
std::optional<std::int64_t> checkpoint_identity(const std::filesystem::path& dir);

// The bytes of the files under `path` (a checkpoint's size).
std::uintmax_t directory_bytes(const std::filesystem::path& path);

}  // namespace isphdem
