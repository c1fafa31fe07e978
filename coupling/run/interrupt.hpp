#pragma once
// SIGINT and SIGTERM during `isphdem run` (docs/output.md, "Checkpoints and --resume"): the
// handler only notes the signal; the run looks at it between two steps, on every rank at once
// (agreed_signal), writes a checkpoint and result.json with status "interrupted", prints the
// command that resumes it, and exits with 128 + the signal. A second signal of the same kind
// while the checkpoint is written ends the process the default way.
#include <mpi.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace isphdem {

// Installs the handlers for its lifetime (the previous ones come back after); a signal the process
// was started ignoring stays ignored.
class InterruptHandlers {
 public:
  InterruptHandlers();
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;
};

// The signal this process received since the handlers were installed, 0 if none.
int pending_signal();
// The largest signal number any rank of `comm` received (MPI_COMM_NULL: this process alone).
// Collective: call it at the same step on every rank.
int agreed_signal(MPI_Comm comm);

// Thrown between two steps once the checkpoint of an interrupted run is written.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  int signal() const { return signal_; }
  int exit_status() const { return 128 + signal_; }

 private:
  int signal_;
};

// The shell command that resumes a run: `[mpirun -np N] EXE run CASE --out DIR --set ...
// --resume`, each word quoted where the shell would split or expand it.
std::string resume_command(const std::string& executable, const std::string& case_file,
                           const std::string& out, const std::vector<std::string>& overrides,
                           int ranks);
// Says on stderr (when `talk`) that the run was interrupted and the command that resumes it;
// returns the same in one line, for result.json's message.
std::string announce_interruption(const Interrupted& e, const std::string& case_file,
                                  const std::string& out, const std::vector<std::string>& overrides,
                                  int ranks, bool talk);
// This process's executable (/proc/self/exe), or `fallback` when it cannot be read.
std::string this_executable(const std::string& fallback);

}  // namespace isphdem
