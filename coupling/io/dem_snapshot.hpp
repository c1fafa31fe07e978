#pragma once
// Fills the /dem and /bodies groups of the output contract from a DEM state.
#include <map>

#include "coupling_stage.hpp"
#include "dem_state.hpp"
#include "io/snapshot.hpp"

namespace isphdem {

// force_hydro per atom tag and per body id (force, torque); missing entries are zero.
struct HydroLoads {
  std::map<int, Vec3> atom_force;
  std::map<int, Vec3> body_force, body_torque;
};

// The loads a coupled step handed the DEM, keyed for the snapshot.
HydroLoads hydro_loads(const DemLoads& loads);

// /dem/model per atom, by whether it belongs to a clump: 1 resolved (PMS particles), 0
// unresolved (porosity and drag).
struct GrainModels {
  int clumps = 0, free_spheres = 0;
};

// `models`: write /dem/model (coupled runs); none for a DEM-only run.
void add_dem_groups(const DemState& state, const HydroLoads& loads, Snapshot& snapshot,
                    const GrainModels* models = nullptr);

}  // namespace isphdem
