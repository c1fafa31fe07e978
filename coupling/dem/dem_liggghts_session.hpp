// Starting Debian's LIGGGHTS as a library with `fix couple/isph` available, shared by
// `isphdem dem` and LiggghtsBackend so both start LIGGGHTS exactly the same way: the screen and
// log pass through a LiggghtsOutputTee, so LIGGGHTS's errors reach stderr with a hint.
#ifndef ISPHDEM_DEM_LIGGGHTS_SESSION_HPP
#define ISPHDEM_DEM_LIGGGHTS_SESSION_HPP

#include <mpi.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dem/liggghts_output_tee.hpp"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace isphdem {

// Deletes LAMMPS, then closes the streams it wrote to.
struct LammpsCloser {
  std::shared_ptr<LiggghtsOutputTee> tee;
  void operator()(LAMMPS_NS::LAMMPS* lmp) const;
};
using LammpsHandle = std::unique_ptr<LAMMPS_NS::LAMMPS, LammpsCloser>;

// args: liggghts command-line options without the program name (-in, -var, -log, -screen,
// -echo, ...), handed to LAMMPS's constructor as the stock launcher does. MPI must be
// initialised. A LIGGGHTS error in the input ends the process (LIGGGHTS calls exit(1) or
// MPI_Abort); its message is on stderr first (liggghts_output_tee.hpp).
LammpsHandle open_liggghts(const std::vector<std::string>& args, MPI_Comm comm);

// Where the next LIGGGHTS commands come from, named in an error message ("script in.liggghts").
void set_liggghts_context(LammpsHandle& lmp, std::string where);

// Put around every call that runs LIGGGHTS commands: while it lives, what LIGGGHTS prints with a
// bare printf goes to its screen stream, not to isphdem's stdout
// (LiggghtsOutputTee::capture_stdout).
class LiggghtsStdoutToScreen {
 public:
  explicit LiggghtsStdoutToScreen(LammpsHandle& lmp);
  ~LiggghtsStdoutToScreen();
  LiggghtsStdoutToScreen(const LiggghtsStdoutToScreen&) = delete;
  LiggghtsStdoutToScreen& operator=(const LiggghtsStdoutToScreen&) = delete;

 private:
  std::shared_ptr<LiggghtsOutputTee> tee_;
  FILE* previous_ = nullptr;
};

}  // namespace isphdem

#endif
