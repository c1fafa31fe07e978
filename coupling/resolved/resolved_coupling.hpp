// Resolved coupling of multisphere clumps with PMS particles (docs/resolved.md).
//
// initialize: per DEM body, PMS particles (coupling/pms_generation.hpp) are added to the fluid
//   as kind kSolid; fluid particles closer than `overlap` spacings to one of them are removed
//   (on the fluid lattice these are exactly the nodes the solids take).
// move_particles: every PMS particle is put at its body's pose with v = v_cm + omega x r.
// after_fluid_step: per body, the sum of the particles' fluid forces and their moments about the
//   centre of mass (sph/rigid_solids.hpp; decomposed, each rank's own particles', summed over the
//   ranks) go to DemLoads.body_* (for a resolved free sphere to
//   DemLoads.atom_*, by its tag); in 2D the per-unit-depth loads
//   are multiplied by the slab thickness T. Nothing else is scaled, so what the fluid gives is
//   what the bodies receive.
//
// 2D: the fluid is the x-y plane and the DEM a slab with normal z (DESIGN.md decision 4); bodies
// must rotate about z only (fix couple/isph planar z Z0 ensures it).
#ifndef ISPHDEM_RESOLVED_COUPLING_HPP
#define ISPHDEM_RESOLVED_COUPLING_HPP

#include <map>
#include <string>
#include <vector>

#include "coupling_stage.hpp"
#include "resolved/pms_generation.hpp"
#include "rigid_solids.hpp"

namespace isphdem {

// Intended case keys in brackets (docs/resolved.md).
struct ResolvedSettings {
  double spacing = 0.0;             // dx [m] (particles.spacing); must equal the solver's
  double fluid_density = 0.0;       // rho_f [kg/m^3] (fluid.density); must equal the solver's
  double slab_thickness = 0.0;      // T [m], 2D only (coupling.slab_thickness)
  PmsShape shape = PmsShape::Auto;  // (coupling.pms_shape = "auto" | "lattice" | "per_sphere")
  double overlap = 0.5;             // fluid closer than this many dx to a PMS particle is removed
  // Each PMS particle of body b stands for the solid volume V_b / N_b (the DEM volume shared out),
  // so that buoyancy is rho_f g V_b exactly and a body of the fluid's density is neutral; the
  // lattice can only match V_b to half a particle, and a per-sphere clump not at all. Off: each
  // particle stands for dx^Dim (x T). (coupling.pms_volume = "dem" | "particles")
  bool dem_volume = true;
  // The depth and normal of each PMS particle under the body's surface, which place the no-slip
  // condition of the viscous term: from the lattice (half a spacing beyond the outer particles,
  // a staircase on curved bodies) or, true, from the member spheres (pms_surface_from_spheres).
  // (coupling.pms_surface = "lattice" | "spheres")
  bool surface_from_spheres = false;
  // Free spheres (fines) resolved too, each a rigid body of its own whose loads go to its atom
  // (force and torque by tag); off, only multisphere clumps are resolved. (coupling.model =
  // "resolved" turns it on.)
  bool free_spheres = false;
  // One line per clump (and the count of free spheres) at initialize(); under mpirun, rank 0's.
  bool report = true;
};

template <int Dim>
class ResolvedCoupling : public CouplingStage<Dim> {
 public:
  explicit ResolvedCoupling(const ResolvedSettings& settings);

  std::string name() const override { return "resolved (PMS)"; }
  void initialize(const DemState& dem, isph::IsphSolver<Dim>& solver) override;
  void move_particles(const DemState& dem, isph::IsphSolver<Dim>& solver) override;
  void before_fluid_step(const DemState&, isph::IsphSolver<Dim>&) override {}
  void after_fluid_step(const DemState& dem, const isph::IsphSolver<Dim>& solver, double dt,
                        DemLoads& loads) override;
  // The bodies as initialize() found them (their PMS particles' count, volume and scale, the
  // orientation and PMS centroid of that moment): a resumed run's initialize() sees the bodies
  // where the checkpoint left them, and restore() puts the first run's back.
  void save(StageState& state) const override;
  void restore(const StageState& state) override;

  struct BodyInfo {
    int id = 0;                 // DEM body id
    std::size_t particles = 0;  // PMS particles
    double dem_volume = 0.0;    // V from the DEM [m^3]
    double fluid_volume = 0.0;  // the solid volume the fluid sees: N dx^Dim (x T in 2D)
    // Loads on the body = scale x (sum of the particles' forces, N per unit depth in 2D):
    // T (2D) times dem_volume / fluid_volume when ResolvedSettings::dem_volume.
    double scale = 1.0;
  };
  const std::vector<BodyInfo>& bodies() const { return info_; }
  std::size_t removed_fluid() const { return removed_; }
  // The pose of a DEM body in the fluid's frame (2D: its x-y plane, rotation about z).
  isph::RigidPose<Dim> pose(const DemBody& body) const;

  // The bodies this stage resolves: the clumps, and with free_spheres each free sphere as a body
  // of id -tag (a sphere needs no orientation: its pose rotates its velocity field only).
  std::vector<DemBody> resolved_bodies(const DemState& dem) const;

 private:
  int index_of(int body_id) const;
  static std::string name_of(int body_id);

  ResolvedSettings settings_;
  std::vector<BodyInfo> info_;
  std::map<int, int> index_;                       // DEM body id -> stage body index
  std::vector<Eigen::Matrix3d> initial_rotation_;  // per body, at initialize()
  // Per body: the PMS particles' centroid relative to the centre of mass, in the frame of
  // initialize(). Moments are taken about that centroid (see after_fluid_step).
  std::vector<isph::Vec<Dim>> centroid_offset_;
  std::size_t removed_ = 0;
};

}  // namespace isphdem

#endif
