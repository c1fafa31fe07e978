// The `[coupling]` table: which grains the fluid resolves (docs/resolved.md, "Case keys"). Both
// the unresolved and the resolved stage read it, so it lives here rather than in either room.
// clang-format off
//   [coupling]
//   model = "unresolved"       # every grain unresolved, clump spheres too (default)
//         | "semi-resolved"    # clumps resolved by PMS particles, free spheres unresolved
//         | "resolved"         # clumps and free spheres resolved, no porosity/drag stage
//         | "auto"             # per grain class from d/dx at start (run/auto_model.hpp)
//   auto.resolve_above = 3.0   # "auto": a class with d/dx at or above this is resolved
//   auto.unresolve_below = 0.5 # "auto": below this unresolved drag holds; between, a warning
//   slab_thickness = 1e-3      # quasi-2D: DEM slab thickness T [m] (alias unresolved.slab_thickness)
//   pms_shape = "auto"         # "lattice" | "per_sphere" | "auto"
//   pms_volume = "dem"         # "dem" | "particles"
//   pms_overlap = 0.5          # fluid closer than this many dx to a PMS particle is removed
// clang-format on
#ifndef ISPHDEM_COUPLING_TABLE_HPP
#define ISPHDEM_COUPLING_TABLE_HPP

#include <string>
#include <vector>

#include "case/case_file.hpp"

namespace isphdem {

std::vector<std::string> coupling_keys();

// coupling.model, checked: "unresolved" (the default), "semi-resolved", "resolved" or "auto".
// "auto" is replaced by one of the others when the run starts (CaseFile::with_override), so
// the stages never see it.
std::string coupling_model(const CaseFile& c);

// The d/dx thresholds of coupling.model = "auto" (docs/study.md, "Choosing the model"). From
// the charts of docs/study/: a resolved sphere settles within 4% of Hasimoto from d/dx = 4 and
// is 15% fast at 2.9 (settling_sphere), a clump loses its shape below 3 particles across
// (clump_resolution_stability); an unresolved grain settles within 1.1% at d/dx = 0.5 in the
// quasi-2D slab (settling_grain), 17% fast in 3D (settling_sphere), and a packed bed keeps
// Ergun to d/dx = 1 (fixed_bed).
struct AutoThresholds {
  double resolve_above = 3.0;
  double unresolve_below = 0.5;
};
AutoThresholds auto_thresholds(const CaseFile& c);

// The quasi-2D DEM slab thickness T [m], one value for both stages; the older key
// unresolved.slab_thickness still works. Throws CaseError when neither or both are set.
double slab_thickness(const CaseFile& c);

}  // namespace isphdem

#endif
