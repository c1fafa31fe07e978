#include "resolved/resolved_case.hpp"

#include "case/coupling_table.hpp"

namespace isphdem {

template <int Dim>
std::unique_ptr<ResolvedCoupling<Dim>> make_resolved_coupling(const CaseFile& c,
                                                              const FluidScene<Dim>& scene,
                                                              bool report) {
  ResolvedSettings s;
  s.report = report;
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
  const std::string surface = c.string("coupling.pms_surface", "lattice");
  if (surface != "lattice" && surface != "spheres")
    throw CaseError(
        "'coupling.pms_surface' must be \"lattice\" (the surface half a spacing beyond the outer "
        "PMS particles) or \"spheres\" (the members' spheres, for the no-slip ghosts)");
  s.surface_from_spheres = surface == "spheres";
  s.free_spheres = coupling_model(c) == "resolved";
  return std::make_unique<ResolvedCoupling<Dim>>(s);
}

template std::unique_ptr<ResolvedCoupling<2>> make_resolved_coupling<2>(const CaseFile&,
                                                                        const FluidScene<2>&, bool);
template std::unique_ptr<ResolvedCoupling<3>> make_resolved_coupling<3>(const CaseFile&,
                                                                        const FluidScene<3>&, bool);

}  // namespace isphdem
