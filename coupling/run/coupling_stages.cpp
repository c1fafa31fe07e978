#include "run/coupling_stages.hpp"

#include "case/coupling_table.hpp"
#include "resolved/resolved_case.hpp"
#include "unresolved/mean_flow_drive.hpp"
#include "unresolved/unresolved_case.hpp"

namespace isphdem {

template <int Dim>
std::vector<std::unique_ptr<CouplingStage<Dim>>> make_coupling_stages(const CaseFile& c,
                                                                      const FluidScene<Dim>& scene,
                                                                      double dt, bool report) {
  std::vector<std::unique_ptr<CouplingStage<Dim>>> stages;
  const double h = scene.config.smoothing_ratio * scene.particles.spacing;
  const std::string model = coupling_model(c);
  if (model == "auto")  // run_coupled puts the model auto chose into the case first
    throw CaseError("coupling.model = \"auto\" must be resolved from the grains before the stages");
  if (model != "resolved")
    stages.push_back(make_unresolved_coupling<Dim>(c, h, scene.config.viscosity));
  if (model != "unresolved") stages.push_back(make_resolved_coupling<Dim>(c, scene, report));
  if (c.string("inflow.mode", "zone") == "mean_flow") {
    isph::Vec<Dim> dir = -scene.config.gravity;
    if (c.has("inflow.direction")) {
      const auto d = c.numbers("inflow.direction", Dim);
      for (int a = 0; a < Dim; ++a) dir[a] = d[a];
    }
    if (!(dir.norm() > 0))
      throw CaseError(
          "'inflow.direction' must be a non-zero vector (or set gravity for \"upward\")");
    const std::string flux = c.string("inflow.flux", "velocity");
    if (flux != "velocity" && flux != "particles")
      throw CaseError(
          "'inflow.flux' must be \"velocity\" (the drive holds the particles' mean velocity) or "
          "\"particles\" (the flux they carry: velocity plus shift)");
    stages.push_back(std::make_unique<MeanFlowDrive<Dim>>(
        c.number("inflow.velocity") * dir.normalized(), scene.config.gravity, dt,
        scene.config.density, flux == "particles"));
  }
  return stages;
}

template std::vector<std::unique_ptr<CouplingStage<2>>> make_coupling_stages<2>(
    const CaseFile&, const FluidScene<2>&, double, bool);
template std::vector<std::unique_ptr<CouplingStage<3>>> make_coupling_stages<3>(
    const CaseFile&, const FluidScene<3>&, double, bool);

}  // namespace isphdem
