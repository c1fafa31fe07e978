#pragma once
// Hydrodynamic loads on unresolved grains (docs/unresolved.md, DESIGN.md decision 3).
//
// Drag is distributed conservatively: the reaction f_a of fluid particle a (what the fluid loses
// to the grains, f_a = -eps_a rho_f V_a F_r*,a, V_a the bulk particle volume, F_r* from the law
// at the local Sauter mean diameter) is split over the grains in range by their surface,
// w_ak = (V_k W_ak / d_k) / sum_k' (V_k' W_ak' / d_k'): the polydisperse correction of
// Beetstra, van der Hoef & Kuipers (2007, with its erratum) in the form for a pressure-gradient
// force on the grains, whose shares of the Sauter-mean drag add up to it exactly. Equal grains
// get their volume shares V_k W_ak / sum V W, bit for bit. The w_ak of one fluid particle sum
// to one, so sum_k f_k = sum_a f_a exactly, up to round-off,
// whenever every particle with a reaction has a grain in range (the field's porosity is then
// < 1); anything else is reported as `unassigned`, never silently dropped.
#include <vector>

#include "unresolved/drag_law.hpp"
#include "unresolved/porosity_map.hpp"
#include "vec.hpp"

namespace isphdem {

template <int Dim>
struct GrainLoads {
  std::vector<int> tag;                                // same order as the grains passed in
  std::vector<isph::Vec<Dim>> force;                   // [N]
  isph::Vec<Dim> unassigned = isph::Vec<Dim>::Zero();  // reaction of particles with no grain
};

// Per fluid particle, the reaction -eps rho_f V F_r*(v_r) with v_r = v_D / eps - v_s, the
// interstitial relative velocity (drag_law.hpp). bulk_volume is the particle's volume (dx^Dim:
// per unit depth in 2D). Zero where no grain is in range.
template <int Dim>
std::vector<isph::Vec<Dim>> resistance_reactions(const PorosityField<Dim>& field,
                                                 const std::vector<isph::Vec<Dim>>& darcy_velocity,
                                                 const DragLaw& law, double fluid_density,
                                                 double bulk_volume);

// Grain k gets depth * sum_a f_a w_ak (w_ak by surface, above). depth converts a 2D fluid's
// per-unit-depth reactions into newtons on the grains of the quasi-2D slab: pass the slab thickness
// in 2D, 1 in 3D.
template <int Dim>
GrainLoads<Dim> distribute_reactions(const GrainWeights& weights,
                                     const std::vector<Grain<Dim>>& grains,
                                     const std::vector<isph::Vec<Dim>>& fluid_reaction,
                                     double depth = 1.0);

// Buoyancy and the dynamic pressure-gradient force of seed Eq. (9): -grad p(x_k) V_k, with the
// full 3D sphere volume (no depth factor: grad p is already per metre in the plane).
template <int Dim>
isph::Vec<Dim> pressure_gradient_force(const isph::Vec<Dim>& grad_p, double grain_volume) {
  return -grain_volume * grad_p;
}

// Adds -grad p V_k to every grain's load; grad_p_at_grains[k] is interpolated by the caller
// (with the fluid's corrected gradient) at grains[k].x.
template <int Dim>
void add_pressure_gradient_forces(GrainLoads<Dim>& loads, const std::vector<Grain<Dim>>& grains,
                                  const std::vector<isph::Vec<Dim>>& grad_p_at_grains);

}  // namespace isphdem
