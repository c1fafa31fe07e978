// All stages of a coupled case, in the order the driver runs them (coupling_stage.hpp).
#ifndef ISPHDEM_COUPLING_STAGES_HPP
#define ISPHDEM_COUPLING_STAGES_HPP

#include <memory>
#include <vector>

#include "case/case_file.hpp"
#include "case/fluid_scene.hpp"
#include "coupling_stage.hpp"

namespace isphdem {

// By coupling.model: the unresolved coupling (not for "resolved"), the resolved PMS stage
// ("semi-resolved", "resolved"), then, with [inflow] mode = "mean_flow", the MeanFlowDrive
// (unresolved/mean_flow_drive.hpp). Throws CaseError naming the key and the fix. report: whether
// the stages print what they set up (rank 0 of a run under mpirun).
template <int Dim>
std::vector<std::unique_ptr<CouplingStage<Dim>>> make_coupling_stages(const CaseFile& c,
                                                                      const FluidScene<Dim>& scene,
                                                                      double dt,
                                                                      bool report = true);

}  // namespace isphdem

#endif
