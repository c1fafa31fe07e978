#include "unresolved/drag_distribution.hpp"

#include <stdexcept>

namespace isphdem {

template <int Dim>
std::vector<isph::Vec<Dim>> resistance_reactions(const PorosityField<Dim>& field,
                                                 const std::vector<isph::Vec<Dim>>& darcy_velocity,
                                                 const DragLaw& law, double fluid_density,
                                                 double bulk_volume) {
  const std::size_t n = field.porosity.size();
  if (darcy_velocity.size() != n)
    throw std::invalid_argument("resistance: one Darcy velocity per fluid point expected");
  std::vector<isph::Vec<Dim>> f(n, isph::Vec<Dim>::Zero());
  for (std::size_t a = 0; a < n; ++a) {
    if (field.weights.offset[a + 1] == field.weights.offset[a]) continue;
    const double eps = field.porosity[a];
    const isph::Vec<Dim> vr = darcy_velocity[a] / eps - field.solid_velocity[a];
    const double speed = vr.norm();
    const double k = law.coefficients(eps, speed, field.diameter[a]).total(speed);
    // F_r* = -k v_r acts on the fluid; the grains get the opposite.
    f[a] = eps * fluid_density * bulk_volume * k * vr;
  }
  return f;
}

template <int Dim>
GrainLoads<Dim> distribute_reactions(const GrainWeights& weights,
                                     const std::vector<Grain<Dim>>& grains,
                                     const std::vector<isph::Vec<Dim>>& fluid_reaction,
                                     double depth) {
  if (fluid_reaction.size() != weights.fluid_count())
    throw std::invalid_argument("drag distribution: one reaction per fluid point expected");
  GrainLoads<Dim> loads;
  loads.tag.reserve(grains.size());
  for (const auto& g : grains) loads.tag.push_back(g.tag);
  loads.force.assign(grains.size(), isph::Vec<Dim>::Zero());
  for (std::size_t a = 0; a < fluid_reaction.size(); ++a) {
    const std::size_t b = weights.offset[a], e = weights.offset[a + 1];
    // Each grain's share is its surface in the kernel (GrainWeights::surface).
    double sum = 0.0;
    for (std::size_t i = b; i < e; ++i) sum += weights.surface[i];
    if (!(sum > 0.0)) {
      loads.unassigned += depth * fluid_reaction[a];
      continue;
    }
    const isph::Vec<Dim> fa = depth * fluid_reaction[a] / sum;
    for (std::size_t i = b; i < e; ++i) {
      if (weights.grain[i] >= grains.size())
        throw std::invalid_argument("drag distribution: weights refer to a missing grain");
      loads.force[weights.grain[i]] += weights.surface[i] * fa;
    }
  }
  return loads;
}

template <int Dim>
void add_pressure_gradient_forces(GrainLoads<Dim>& loads, const std::vector<Grain<Dim>>& grains,
                                  const std::vector<isph::Vec<Dim>>& grad_p_at_grains) {
  if (grains.size() != loads.force.size() || grad_p_at_grains.size() != grains.size())
    throw std::invalid_argument("pressure-gradient force: one gradient per grain expected");
  for (std::size_t k = 0; k < grains.size(); ++k)
    loads.force[k] += pressure_gradient_force<Dim>(grad_p_at_grains[k], grains[k].volume());
}

#define ISPHDEM_INSTANTIATE(D)                                                                    \
  template std::vector<isph::Vec<D>> resistance_reactions<D>(                                     \
      const PorosityField<D>&, const std::vector<isph::Vec<D>>&, const DragLaw&, double, double); \
  template GrainLoads<D> distribute_reactions<D>(const GrainWeights&,                             \
                                                 const std::vector<Grain<D>>&,                    \
                                                 const std::vector<isph::Vec<D>>&, double);       \
  template void add_pressure_gradient_forces<D>(GrainLoads<D>&, const std::vector<Grain<D>>&,     \
                                                const std::vector<isph::Vec<D>>&);
ISPHDEM_INSTANTIATE(2)
ISPHDEM_INSTANTIATE(3)
#undef ISPHDEM_INSTANTIATE

}  // namespace isphdem
