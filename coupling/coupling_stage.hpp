// The seam between the coupled driver and the ways grains and fluid talk to each other
// (DESIGN.md decision 2). The unresolved coupling (porosity + drag for fine spheres) and the
// resolved one (PMS particles for clumps) are each one CouplingStage; the driver owns the
// DemBackend and the IsphSolver and calls, per fluid step of length dt:
//
//   state = backend.state()
//   for each stage: stage.move_particles(state, solver)         // PMS solids to their poses
//   solver.redistribute()                                       // decomposed: to their owners
//   for each stage: stage.before_fluid_step(state, solver)      // DEM -> fluid (consistent)
//   solver.step(dt)
//   loads = {}; for each stage: stage.after_fluid_step(state, solver, dt, loads)  // fluid -> DEM
//   backend.set_atom_loads(loads.atom_*); backend.set_body_loads(loads.body_*)    // conservative
//   backend.advance(n_sub)
//
// initialize() is called once, before the first before_fluid_step, with the initial DEM state;
// it is the place to add particles to the solver (PMS) or to check the scene (grains inside the
// fluid domain, slab thickness).
#ifndef ISPHDEM_COUPLING_STAGE_HPP
#define ISPHDEM_COUPLING_STAGE_HPP

#include <map>
#include <string>
#include <vector>

#include "dem_state.hpp"
#include "isph_solver.hpp"

namespace isphdem {

// Hydrodynamic loads for the next DEM substeps, whole grains and bodies, SI (N, N m), 3D even
// for a 2D fluid (z = 0 there; quasi-2D forces are already multiplied by the slab thickness).
// Stages append; a tag or body id appears at most once over all stages.
struct DemLoads {
  std::vector<int> atom_tags;
  std::vector<Vec3> atom_force, atom_torque;
  std::vector<int> body_ids;
  std::vector<Vec3> body_force, body_torque;
};

// The fluid's force on all grains together: what a held body or a fixed bed reads as its drag
// (diagnostics hydro_force_*). Atoms and bodies never overlap (see above), so nothing counts twice.
inline Vec3 total_force(const DemLoads& loads) {
  Vec3 f{0.0, 0.0, 0.0};
  for (const auto* forces : {&loads.atom_force, &loads.body_force})
    for (const Vec3& g : *forces)
      for (int a = 0; a < 3; ++a) f[a] += g[a];
  return f;
}

// What a stage keeps from one step to the next that its case and the DEM state do not give again
// (a checkpoint's part, docs/output.md): named arrays of numbers.
using StageState = std::map<std::string, std::vector<double>>;

template <int Dim>
class CouplingStage {
 public:
  virtual ~CouplingStage() = default;
  virtual std::string name() const = 0;
  virtual void initialize(const DemState& dem, isph::IsphSolver<Dim>& solver) = 0;
  // Moves the fluid particles the stage places itself (none by default), before the fluid is
  // redistributed over the ranks: decomposed, a particle must lie in its owner's region when the
  // step adds its halo.
  virtual void move_particles(const DemState& /*dem*/, isph::IsphSolver<Dim>& /*solver*/) {}
  virtual void before_fluid_step(const DemState& dem, isph::IsphSolver<Dim>& solver) = 0;
  virtual void after_fluid_step(const DemState& dem, const isph::IsphSolver<Dim>& solver, double dt,
                                DemLoads& loads) = 0;
  // Between two steps: saves what the stage carries over (nothing by default), and puts it back
  // in a stage initialize()d for the same case when a run resumes (std::runtime_error when
  // `state` does not fit it).
  virtual void save(StageState& /*state*/) const {}
  virtual void restore(const StageState& /*state*/) {}
};

}  // namespace isphdem

#endif
