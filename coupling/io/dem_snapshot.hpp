#pragma once
// Fills the /dem and /bodies groups of the output contract from a DEM state.
#include <map>

#include "dem_state.hpp"
#include "io/snapshot.hpp"

namespace isphdem {

// force_hydro per atom tag and per body id (force, torque); missing entries are zero.
struct HydroLoads {
  std::map<int, Vec3> atom_force;
  std::map<int, Vec3> body_force, body_torque;
};

void add_dem_groups(const DemState& state, const HydroLoads& loads, Snapshot& snapshot);

}  // namespace isphdem
