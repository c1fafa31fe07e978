// DemBackend on Debian's LIGGGHTS 3.8, in process, through its library interface plus direct
// access to Atom and FixMultisphere where the library interface stops (per-body state).
#ifndef ISPHDEM_DEM_LIGGGHTS_BACKEND_HPP
#define ISPHDEM_DEM_LIGGGHTS_BACKEND_HPP

#include <mpi.h>

#include <string>
#include <vector>

#include "dem/dem_backend.hpp"
#include "dem/dem_liggghts_session.hpp"

namespace LAMMPS_NS {
class FixCoupleIsph;
class FixMultisphere;
}  // namespace LAMMPS_NS

namespace isphdem {

class LiggghtsBackend final : public DemBackend {
 public:
  // liggghts_args: command-line options as for `liggghts` (-var, -log, -screen, -echo), no -in.
  explicit LiggghtsBackend(std::vector<std::string> liggghts_args = {},
                           MPI_Comm comm = MPI_COMM_WORLD);
  ~LiggghtsBackend() override;

  // Runs the script, then the commands. Throws std::runtime_error if the script is missing.
  void initialize(const DemSetup& setup) override;
  const DemState& state() override;
  // Need a `fix ID group couple/isph` in the script (std::runtime_error otherwise).
  void set_atom_loads(const std::vector<int>& tags, const std::vector<Vec3>& force,
                      const std::vector<Vec3>& torque) override;
  void set_body_loads(const std::vector<int>& ids, const std::vector<Vec3>& force,
                      const std::vector<Vec3>& torque) override;
  // `run N pre no post no`: no re-setup between chunks, so chunked runs follow one long run.
  void advance(int n_substeps) override;
  double timestep() const override;
  void finalize() override;

  // Resuming a run (docs/output.md, "Checkpoints and --resume"): call before initialize(); the
  // script's `read_restart` then reads `restart` (liggghts_restart_redirect.hpp), and its DEM
  // clock starts at `time`. initialize() throws std::runtime_error when the script reads no
  // restart (the grains would be the first run's).
  void resume_from(const std::string& restart, double time);
  // LIGGGHTS's own restart of the grains now (as `write_restart` writes it: multisphere bodies
  // and contact histories included), without touching the run: the next substeps go on as they
  // would have without it.
  void write_restart(const std::string& file);

  // One LIGGGHTS command, e.g. for tests and diagnostics.
  void command(const std::string& line);
  LAMMPS_NS::LAMMPS* lammps() { return lmp_.get(); }

 private:
  LAMMPS_NS::FixCoupleIsph* coupling_fix();
  LAMMPS_NS::FixMultisphere* multisphere();
  void gather_state();

  std::vector<std::string> args_;
  MPI_Comm comm_;
  int rank_ = 0;
  LammpsHandle lmp_;
  DemState state_;
  bool state_stale_ = true;
  bool ran_ = false;            // a run command has set LIGGGHTS up since initialize()
  std::string resume_restart_;  // resume_from()'s restart, read in place of the script's
  double resume_time_ = 0.0;
};

}  // namespace isphdem

#endif
