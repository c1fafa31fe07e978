#include "unresolved/unresolved_case.hpp"

#include "case/coupling_table.hpp"

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
          "unresolved.blend_half_width",
          "unresolved.self_induced_correction",
          "unresolved.porosity_smoothing_diameters"};
}

template <int Dim>
std::unique_ptr<UnresolvedCoupling<Dim>> make_unresolved_coupling(const CaseFile& c, double fluid_h,
                                                                  double viscosity) {
  UnresolvedSettings s;
  s.map.smoothing_length = c.positive("unresolved.porosity_smoothing_length", fluid_h);
  s.map.min_porosity = c.positive("unresolved.min_porosity", s.map.min_porosity);
  if (c.has("unresolved.porosity_smoothing_diameters"))
    s.map.smoothing_diameters = c.positive("unresolved.porosity_smoothing_diameters");
  if (s.map.min_porosity >= 1.0)
    throw CaseError("'unresolved.min_porosity' must lie in (0, 1); 0.25 suits equal spheres");
  if (Dim == 2) s.map.slab_thickness = slab_thickness(c);
  s.clump_spheres = coupling_model(c) == "unresolved";
  const std::string drag = c.string("unresolved.drag", "seed");
  if (drag != "seed")
    throw CaseError("'unresolved.drag' must be \"seed\" (Ergun / Wen-Yu; got \"" + drag + "\")");
  SeedResistanceParameters p;
  // Optional: the drag takes each grain's size from LIGGGHTS; given, it is a check that every
  // unresolved grain has this diameter (UnresolvedCoupling::initialize names those that differ).
  if (c.has("unresolved.grain_diameter"))
    s.grain_diameter = p.grain_diameter = c.positive("unresolved.grain_diameter");
  // The fluid's key, named as such: the drag law divides by it (the fluid alone takes 0).
  if (!(viscosity > 0.0))
    throw CaseError("'fluid.viscosity' (" + c.where("fluid.viscosity") +
                    ") must be positive in a case with [unresolved], whose drag law divides by "
                    "it (water: 1e-6)");
  p.kinematic_viscosity = viscosity;
  s.kinematic_viscosity = viscosity;
  // UnresolvedCoupling refuses it in 2D; the catch below names the table.
  s.self_induced_correction = c.boolean("unresolved.self_induced_correction", false);
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

template std::unique_ptr<UnresolvedCoupling<2>> make_unresolved_coupling<2>(const CaseFile&, double,
                                                                            double);
template std::unique_ptr<UnresolvedCoupling<3>> make_unresolved_coupling<3>(const CaseFile&, double,
                                                                            double);

}  // namespace isphdem
