// Starting Debian's LIGGGHTS as a library with `fix couple/isph` available, shared by
// `isphdem dem` and LiggghtsBackend so both start LIGGGHTS exactly the same way.
#ifndef ISPHDEM_DEM_LIGGGHTS_SESSION_HPP
#define ISPHDEM_DEM_LIGGGHTS_SESSION_HPP

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace isphdem {

struct LammpsCloser {
  void operator()(LAMMPS_NS::LAMMPS* lmp) const;
};
using LammpsHandle = std::unique_ptr<LAMMPS_NS::LAMMPS, LammpsCloser>;

// args: liggghts command-line options without the program name (-in, -var, -log, -screen,
// -echo, ...), handed to LAMMPS's constructor as the stock launcher does. MPI must be
// initialised. LIGGGHTS errors in the input end the process (LIGGGHTS calls exit(1)).
LammpsHandle open_liggghts(const std::vector<std::string>& args, MPI_Comm comm);

}  // namespace isphdem

#endif
