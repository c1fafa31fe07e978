// The `[unresolved]` table of a coupled case (docs/unresolved.md):
//
//   [unresolved]
//   grain_diameter = 1e-3             # optional check [m]: every unresolved grain has this
//                                     # diameter (the drag takes each grain's own size)
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

#include "case/case_file.hpp"
#include "unresolved/unresolved_coupling.hpp"

namespace isphdem {

std::vector<std::string> unresolved_keys();

// Throws CaseError naming the key and the fix. fluid_h and viscosity come from the fluid scene.
template <int Dim>
std::unique_ptr<UnresolvedCoupling<Dim>> make_unresolved_coupling(const CaseFile& c, double fluid_h,
                                                                  double viscosity);

}  // namespace isphdem

#endif
