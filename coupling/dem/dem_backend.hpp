// The DEM side as the coupling sees it: a narrow front with an explicit lifecycle, in the
// manner of preCICE's participant API:
//   initialize(setup) -> { state(); set_atom_loads(); set_body_loads(); advance(n_sub); }* ->
//   finalize()
//
// MPI: every call is collective over the backend's communicator. state() is gathered to every
// rank (the fluid may run on rank 0 only or replicated). Loads are taken from rank 0's
// arguments and broadcast; other ranks' arguments are ignored, so both layouts work.
//
// Loads are piecewise constant: loads set before advance(n) act, unchanged, on each of those n
// DEM steps (force fields, not impulses), and stay until replaced. Each set_* call replaces the
// whole previous set of its kind; grains not listed get zero.
#ifndef ISPHDEM_DEM_BACKEND_HPP
#define ISPHDEM_DEM_BACKEND_HPP

#include <filesystem>
#include <string>
#include <vector>

#include "dem_state.hpp"

namespace isphdem {

struct DemSetup {
  std::filesystem::path script;       // LIGGGHTS input script, run first (may be empty)
  std::vector<std::string> commands;  // then these commands, one per entry
};

class DemBackend {
 public:
  virtual ~DemBackend() = default;

  virtual void initialize(const DemSetup& setup) = 0;

  // Current state, all atoms and bodies on every rank.
  virtual const DemState& state() = 0;

  // force/torque: one Vec3 per tag (N), torque about the sphere's centre. Throws
  // std::invalid_argument if sizes differ or a tag is not a coupled atom.
  virtual void set_atom_loads(const std::vector<int>& tags, const std::vector<Vec3>& force,
                              const std::vector<Vec3>& torque) = 0;

  // Body force at the centre of mass and torque about it, by body id.
  virtual void set_body_loads(const std::vector<int>& ids, const std::vector<Vec3>& force,
                              const std::vector<Vec3>& torque) = 0;

  virtual void advance(int n_substeps) = 0;

  virtual double timestep() const = 0;  // DEM time step (s)

  virtual void finalize() = 0;
};

}  // namespace isphdem

#endif
