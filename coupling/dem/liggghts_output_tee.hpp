// LIGGGHTS's screen and log streams, passed through isphdem on their way to their files.
//
// In library mode LIGGGHTS ends the process itself on an input error: Error::all writes the
// ERROR line to screen and log, closes both, calls MPI_Finalize and exit(1); Error::one (one rank,
// e.g. a lost atom) writes to screen unflushed and calls MPI_Abort. No exception reaches the host
// and nothing returns from input->file() (docs/dem.md, "When LIGGGHTS stops a run"). The stream
// pointers are plain public FILE* members every LIGGGHTS class holds by reference, so replacing
// lmp->screen and lmp->logfile by our own streams (fopencookie) lets isphdem see every byte:
//   - an ERROR line goes to stderr at once, with the command that was running, where it came
//     from and a hint (liggghts_error_hints.hpp), and the file is flushed before MPI_Abort;
//   - LIGGGHTS closing the screen itself means it is about to exit: the close says so on stderr;
//   - LIGGGHTS 3.8 sometimes follows an ERROR line with a "comment from the off" built in a
//     string that is already freed (error_special.h), i.e. stray heap bytes ending in the ERROR's
//     "(file:line)": that one write is dropped, so the files hold LIGGGHTS's output without it.
// On ranks other than 0 LIGGGHTS opens no screen; there only ERROR lines are passed on (stderr),
// so that the message of the failing rank is shown once.
// LIGGGHTS 3.8 also writes a few lines with a bare printf, to the process's stdout whatever
// -screen says: read_restart prints "version 3 8" on every rank. While LIGGGHTS runs commands
// (capture_stdout), C's stdout is our screen stream, so those lines go where the rest of
// LIGGGHTS's output goes (the screen file; nowhere on ranks > 0 or with -screen none) and never
// among isphdem's own lines. Needs glibc (fopencookie; stdout is an assignable variable).
#ifndef ISPHDEM_LIGGGHTS_OUTPUT_TEE_HPP
#define ISPHDEM_LIGGGHTS_OUTPUT_TEE_HPP

#include <sys/types.h>

#include <cstdio>
#include <string>
#include <utility>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace isphdem {

class LiggghtsOutputTee {
 public:
  // Installs the streams into lmp (screen, logfile and the universe's copies of them).
  LiggghtsOutputTee(LAMMPS_NS::LAMMPS* lmp, int rank);
  ~LiggghtsOutputTee() { close(); }
  LiggghtsOutputTee(const LiggghtsOutputTee&) = delete;
  LiggghtsOutputTee& operator=(const LiggghtsOutputTee&) = delete;

  // Where the next commands come from, for the error message: "script in.liggghts",
  // "isphdem's DEM substeps", ...
  void set_context(std::string where) { context_ = std::move(where); }
  // Call before deleting lmp: from then on a close is ours, not LIGGGHTS ending the process.
  void host_closing() { host_closing_ = true; }
  // Closes our streams and the files behind them (after lmp is deleted); idempotent.
  void close();
  // Points C's stdout at the screen stream and returns what it pointed at, for release_stdout.
  // Nested captures are fine. When LIGGGHTS closes the screen itself (Error::all, just before it
  // exits) stdout is given back at once.
  FILE* capture_stdout();
  void release_stdout(FILE* previous);

 private:
  struct Stream {
    LiggghtsOutputTee* owner = nullptr;
    FILE* real = nullptr;      // where LIGGGHTS would have written; may be stdout or null
    FILE* ours = nullptr;      // what LIGGGHTS writes to now
    bool is_screen = false;    // ERROR lines go to stderr from the screen only (the log repeats)
    bool closed = false;       // by LIGGGHTS or by us
    std::string error_suffix;  // " (file:line)\n" of the last ERROR write, for the stray write
  };
  static ssize_t write(void* cookie, const char* buf, size_t size);
  static int close(void* cookie);
  void install(Stream& s, FILE*& member, FILE*& universe_member, bool is_screen);
  void report_error(const std::string& line) const;
  std::string running_command() const;

  LAMMPS_NS::LAMMPS* lmp_;
  int rank_;
  FILE* host_stdout_;  // stdout as isphdem set it up
  bool host_closing_ = false;
  std::string context_;
  Stream screen_, log_;
};

}  // namespace isphdem

#endif
