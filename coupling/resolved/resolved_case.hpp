// The resolved (PMS) stage of a coupled case, built from the `[coupling]` table
// (case/coupling_table.hpp) and the fluid scene's spacing and density.
#ifndef ISPHDEM_RESOLVED_CASE_HPP
#define ISPHDEM_RESOLVED_CASE_HPP

#include <memory>

#include "case/case_file.hpp"
#include "case/fluid_scene.hpp"
#include "resolved/resolved_coupling.hpp"

namespace isphdem {

// Throws CaseError naming the key and the fix. report: ResolvedSettings::report.
template <int Dim>
std::unique_ptr<ResolvedCoupling<Dim>> make_resolved_coupling(const CaseFile& c,
                                                              const FluidScene<Dim>& scene,
                                                              bool report = true);

}  // namespace isphdem

#endif
