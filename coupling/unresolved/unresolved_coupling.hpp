// Unresolved coupling of fine grains (free LIGGGHTS spheres, body == -1) as a CouplingStage
// (docs/unresolved.md). Before the fluid step: grains -> PorosityMap -> porosity, solid velocity
// and resistance K = law(eps, |v_D/eps - v_s|) on every fluid and forcing-zone particle. After
// it: the reaction of the resistance with the same K and the v_D the fluid ended the step with,
// f_a = eps rho V K (v_D/eps - v_s), spread over the grains by the weights of that same map
// (times the slab thickness in 2D), plus -grad p(x_k) V_k with grad p interpolated at the grain
// centres. The grains' drag is then exactly minus the resistance the fluid received.
#ifndef ISPHDEM_UNRESOLVED_COUPLING_HPP
#define ISPHDEM_UNRESOLVED_COUPLING_HPP

#include <memory>
#include <vector>

#include "coupling_stage.hpp"
#include "unresolved/drag_law.hpp"
#include "unresolved/porosity_map.hpp"
#include "unresolved/self_induced_velocity.hpp"

namespace isphdem {

struct UnresolvedSettings {
  PorosityMapSettings map;  // smoothing_length, kernel, min_porosity, slab_thickness
  // coupling.model = "unresolved": the spheres of clumps are unresolved grains too (their loads
  // go to the member atoms, which fix multisphere sums into the body). Otherwise only free
  // spheres are, and clumps are left to the resolved (PMS) stage.
  bool clump_spheres = false;
  // unresolved.grain_diameter when the case gives it: initialize() stops if an unresolved grain
  // has another diameter. 0: no check (the drag always takes each grain's own size).
  double grain_diameter = 0.0;
  // unresolved.self_induced_correction (3D only): each grain's drag from the fluid's velocity less
  // the part its own reaction induced there (self_induced_velocity.hpp); needs the viscosity.
  bool self_induced_correction = false;
  double kinematic_viscosity = 0.0;  // [m^2/s]
};

template <int Dim>
struct UnresolvedBalance {
  isph::Vec<Dim> fluid_resistance = isph::Vec<Dim>::Zero();  // force on the fluid [N (2D: x T)]
  isph::Vec<Dim> grain_drag = isph::Vec<Dim>::Zero();        // sum of the drag handed to grains
  isph::Vec<Dim> grain_pressure = isph::Vec<Dim>::Zero();    // sum of -grad p V_k
  std::size_t grains = 0, floored = 0;
  // With the self-induced correction: the largest s = F u_self / (F u_rel) of a grain, and how
  // many grains had s above the cap (their drag raised by at most 1 / (1 - cap)).
  double max_self_induced = 0.0;
  std::size_t self_induced_capped = 0;
};

template <int Dim>
class UnresolvedCoupling final : public CouplingStage<Dim> {
 public:
  UnresolvedCoupling(const UnresolvedSettings& settings, std::shared_ptr<const DragLaw> law);

  std::string name() const override { return "unresolved"; }
  void initialize(const DemState& dem, isph::IsphSolver<Dim>& solver) override;
  void before_fluid_step(const DemState& dem, isph::IsphSolver<Dim>& solver) override;
  void after_fluid_step(const DemState& dem, const isph::IsphSolver<Dim>& solver, double dt,
                        DemLoads& loads) override;

  // Whether this stage maps the atom as an unresolved grain (free spheres; clump members too
  // with UnresolvedSettings::clump_spheres).
  bool maps(const DemAtom& a) const { return a.body == -1 || settings_.clump_spheres; }

  // Totals of the last exchange, for diagnostics and the momentum test.
  const UnresolvedBalance<Dim>& balance() const { return balance_; }
  // Fine grains of the last exchange (in-plane parts in 2D), periodic images appended.
  const std::vector<Grain<Dim>>& grains() const { return grains_; }

 private:
  // Throws naming the grains whose diameter is not UnresolvedSettings::grain_diameter.
  void check_grain_diameter(const DemState& dem) const;
  // Raises the resistance of the rows of grains_ by each grain's 1 / (1 - s), s = B I / (6 pi mu)
  // (self_induced_velocity.hpp); rows[r] is the particle of row r of field_.
  void correct_for_self_induced_velocity(isph::IsphSolver<Dim>& solver,
                                         const std::vector<std::size_t>& rows);

  UnresolvedSettings settings_;
  std::shared_ptr<const DragLaw> law_;
  PorosityMap<Dim> map_;
  double depth_;                    // slab thickness in 2D, 1 in 3D
  std::vector<Grain<Dim>> grains_;  // fine grains, then their periodic images
  std::vector<std::size_t> owner_;  // index of the real grain of each entry of grains_
  PorosityField<Dim> field_;
  std::vector<std::int64_t> mapped_ids_;  // particle id of each row of field_ (pre-step order)
  UnresolvedBalance<Dim> balance_;
  std::unique_ptr<SelfInducedVelocity> self_induced_;  // with self_induced_correction only
  bool warned_cap_ = false;
};

}  // namespace isphdem

#endif
