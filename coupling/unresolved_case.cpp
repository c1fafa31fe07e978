#include "unresolved_case.hpp"

#include "mean_flow_drive.hpp"
#include "resolved_coupling.hpp"

namespace isphdem {

std::vector<std::string> unresolved_keys() {
  return {"unresolved.grain_diameter",
          "unresolved.slab_thickness",
          "unresolved.porosity_smoothing_length",
          "unresolved.min_porosity",
          "unresolved.drag",
          "unresolved.alpha",
          "unresolved.beta",
          "unresolved.blend",
          "unresolved.blend_half_width"};
}

std::vector<std::string> coupling_keys() {
  return {"coupling.model", "coupling.slab_thickness", "coupling.pms_shape", "coupling.pms_volume",
          "coupling.pms_overlap"};
}

namespace {

std::string coupling_model(const CaseFile& c) {
  const std::string m = c.string("coupling.model", "unresolved");
  if (m != "unresolved" && m != "semi-resolved" && m != "resolved")
    throw CaseError(
        "'coupling.model' must be \"unresolved\", \"semi-resolved\" or \"resolved\" (got \"" + m +
        "\")");
  return m;
}

// One slab thickness for both stages; the older key unresolved.slab_thickness still works.
double slab_thickness(const CaseFile& c) {
  if (c.has("coupling.slab_thickness") && c.has("unresolved.slab_thickness"))
    throw CaseError(
        "both 'coupling.slab_thickness' and 'unresolved.slab_thickness' are set: keep one "
        "(coupling.slab_thickness)");
  if (c.has("coupling.slab_thickness")) return c.positive("coupling.slab_thickness");
  if (c.has("unresolved.slab_thickness")) return c.positive("unresolved.slab_thickness");
  throw CaseError(
      "a 2D coupled case needs 'coupling.slab_thickness': the thickness T [m] of the DEM slab "
      "(usually one grain diameter) over which grain volume and forces are spread");
}

template <int Dim>
std::unique_ptr<ResolvedCoupling<Dim>> make_resolved_coupling(const CaseFile& c,
                                                              const FluidScene<Dim>& scene) {
  ResolvedSettings s;
  s.spacing = scene.particles.spacing;
  s.fluid_density = scene.config.density;
  if (Dim == 2) s.slab_thickness = slab_thickness(c);
  try {
    s.shape = pms_shape_from_name(c.string("coupling.pms_shape", "auto"));
  } catch (const std::invalid_argument& e) {
    throw CaseError(std::string("'coupling.pms_shape': ") + e.what());
  }
  const std::string volume = c.string("coupling.pms_volume", "dem");
  if (volume != "dem" && volume != "particles")
    throw CaseError("'coupling.pms_volume' must be \"dem\" or \"particles\"");
  s.dem_volume = volume == "dem";
  s.overlap = c.positive("coupling.pms_overlap", s.overlap);
  return std::make_unique<ResolvedCoupling<Dim>>(s);
}

}  // namespace

template <int Dim>
std::unique_ptr<UnresolvedCoupling<Dim>> make_unresolved_coupling(const CaseFile& c, double fluid_h,
                                                                  double viscosity) {
  UnresolvedSettings s;
  s.map.smoothing_length = c.positive("unresolved.porosity_smoothing_length", fluid_h);
  s.map.min_porosity = c.positive("unresolved.min_porosity", s.map.min_porosity);
  if (s.map.min_porosity >= 1.0)
    throw CaseError("'unresolved.min_porosity' must lie in (0, 1); 0.25 suits equal spheres");
  if (Dim == 2) s.map.slab_thickness = slab_thickness(c);
  s.clump_spheres = coupling_model(c) == "unresolved";
  const std::string drag = c.string("unresolved.drag", "seed");
  if (drag != "seed")
    throw CaseError("'unresolved.drag' must be \"seed\" (Ergun / Wen-Yu; got \"" + drag + "\")");
  SeedResistanceParameters p;
  if (!c.has("unresolved.grain_diameter"))
    throw CaseError(
        "'unresolved.grain_diameter' is required: the fine grains' diameter d_s [m] "
        "used by the drag law");
  p.grain_diameter = c.positive("unresolved.grain_diameter");
  p.kinematic_viscosity = viscosity;
  p.alpha = c.positive("unresolved.alpha", p.alpha);
  p.beta = c.positive("unresolved.beta", p.beta);
  p.blend = c.boolean("unresolved.blend", p.blend);
  p.blend_half_width = c.positive("unresolved.blend_half_width", p.blend_half_width);
  try {
    auto law = std::make_shared<SeedResistance>(p);
    return std::make_unique<UnresolvedCoupling<Dim>>(s, law);
  } catch (const std::invalid_argument& e) {
    throw CaseError(std::string("[unresolved]: ") + e.what());
  }
}

template <int Dim>
std::vector<std::unique_ptr<CouplingStage<Dim>>> make_coupling_stages(const CaseFile& c,
                                                                      const FluidScene<Dim>& scene,
                                                                      double dt) {
  std::vector<std::unique_ptr<CouplingStage<Dim>>> stages;
  const double h = scene.config.smoothing_ratio * scene.particles.spacing;
  const std::string model = coupling_model(c);
  if (model != "resolved")
    stages.push_back(make_unresolved_coupling<Dim>(c, h, scene.config.viscosity));
  if (model != "unresolved") stages.push_back(make_resolved_coupling<Dim>(c, scene));
  if (c.string("inflow.mode", "zone") == "mean_flow") {
    isph::Vec<Dim> dir = -scene.config.gravity;
    if (c.has("inflow.direction")) {
      const auto d = c.numbers("inflow.direction", Dim);
      for (int a = 0; a < Dim; ++a) dir[a] = d[a];
    }
    if (!(dir.norm() > 0))
      throw CaseError(
          "'inflow.direction' must be a non-zero vector (or set gravity for \"upward\")");
    stages.push_back(
        std::make_unique<MeanFlowDrive<Dim>>(c.number("inflow.velocity") * dir.normalized(),
                                             scene.config.gravity, dt, scene.config.density));
  }
  return stages;
}

template std::vector<std::unique_ptr<CouplingStage<2>>> make_coupling_stages<2>(
    const CaseFile&, const FluidScene<2>&, double);
template std::vector<std::unique_ptr<CouplingStage<3>>> make_coupling_stages<3>(
    const CaseFile&, const FluidScene<3>&, double);

template std::unique_ptr<UnresolvedCoupling<2>> make_unresolved_coupling<2>(const CaseFile&, double,
                                                                            double);
template std::unique_ptr<UnresolvedCoupling<3>> make_unresolved_coupling<3>(const CaseFile&, double,
                                                                            double);

}  // namespace isphdem
