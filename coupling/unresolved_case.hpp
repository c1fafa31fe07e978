// The `[unresolved]` table of a coupled case (docs/unresolved.md):
//
//   [unresolved]
//   grain_diameter = 1e-3             # d_s of the drag law [m]
//   slab_thickness = 1e-3             # quasi-2D: DEM slab thickness T [m] (required in 2D)
//   porosity_smoothing_length = 1.3e-3  # h_p [m], default the fluid's h
//   min_porosity = 0.25
//   drag = "seed"                     # Ergun (eps < 0.8) / Wen-Yu, seed Eqs. (3)-(8)
//   alpha = 150.0
//   beta = 1.75
//   blend = false                     # ramp across the Ergun/Wen-Yu switch instead of a jump
//   blend_half_width = 0.05
#ifndef ISPHDEM_UNRESOLVED_CASE_HPP
#define ISPHDEM_UNRESOLVED_CASE_HPP

#include <memory>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "fluid_scene.hpp"
#include "unresolved_coupling.hpp"

namespace isphdem {

std::vector<std::string> unresolved_keys();

// The `[coupling]` table: which grains the fluid resolves (docs/resolved.md, "Case keys").
// clang-format off
//   [coupling]
//   model = "unresolved"       # every grain unresolved, clump spheres too (default)
//         | "semi-resolved"    # clumps resolved by PMS particles, free spheres unresolved
//         | "resolved"         # clumps resolved, no porosity/drag stage
//   slab_thickness = 1e-3      # quasi-2D: DEM slab thickness T [m] (alias unresolved.slab_thickness)
//   pms_shape = "auto"         # "lattice" | "per_sphere" | "auto"
//   pms_volume = "dem"         # "dem" | "particles"
//   pms_overlap = 0.5          # fluid closer than this many dx to a PMS particle is removed
// clang-format on
std::vector<std::string> coupling_keys();

// Throws CaseError naming the key and the fix. fluid_h and viscosity come from the fluid scene.
template <int Dim>
std::unique_ptr<UnresolvedCoupling<Dim>> make_unresolved_coupling(const CaseFile& c, double fluid_h,
                                                                  double viscosity);

// All stages of a coupled case, in the order the driver runs them, by coupling.model: the
// unresolved coupling (not for "resolved"), the resolved PMS stage ("semi-resolved",
// "resolved"), then, with [inflow] mode = "mean_flow", the MeanFlowDrive (mean_flow_drive.hpp).
template <int Dim>
std::vector<std::unique_ptr<CouplingStage<Dim>>> make_coupling_stages(const CaseFile& c,
                                                                      const FluidScene<Dim>& scene,
                                                                      double dt);

}  // namespace isphdem

#endif
