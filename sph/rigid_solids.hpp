#pragma once
// Passively Moving Solids (Koshizuka, Nobe & Oka 1998): a rigid body is a set of solid SPH
// particles (kind kSolid) fixed in the body frame.
//
// In a step they are computed as fluid: the predictor gives them the viscous and gravity terms,
// they are unknowns of the pressure equation like fluid rows, and the corrector's velocity
// change is their hydrodynamic acceleration. (In the projection itself their u* is, by default,
// v + dt c grad p^n / rho, so that a body stays rigid through a steady projection:
// IsphConfig::pms_pressure_increment; their force keeps the predictor's u*.) The body takes that
// momentum (minus gravity, which the DEM applies itself): the particle's force is
//     f_i = rho0 V_i (nu lap u_i - grad p_i / rho0)
// and their velocity is left at the prescribed rigid one (they do not shift or advect; the
// coupling places them at the body's next pose). Why fluid rows rather than Adami-type moving
// wall rows: a fluid row makes the pressure continuous through the body, so a body at rest in
// still water gets exactly rho0 g V (the pressure field is the hydrostatic one, and its gradient
// inside the body is rho0 g); a wall row extrapolates the pressure from one side and the force
// has to be summed over a ragged boundary layer, which carries the wall extrapolation error into
// the force. The projection also sees the body's region with fluid inertia, which keeps the
// explicit exchange stable for bodies lighter than the fluid (docs/resolved.md).
#include <vector>

#include "domain.hpp"
#include "neighbors.hpp"
#include "operators.hpp"
#include "particles.hpp"
#include "row_share.hpp"

namespace isph {

// Angular velocity and torque: a scalar (about z) in 2D, a vector in 3D.
template <int Dim>
using AngularVec = Eigen::Matrix<double, Dim == 2 ? 1 : 3, 1>;

template <int Dim>
struct RigidPose {
  Vec<Dim> x = Vec<Dim>::Zero();             // centre of mass
  Mat<Dim> rotation = Mat<Dim>::Identity();  // body frame -> space
  Vec<Dim> v = Vec<Dim>::Zero();
  AngularVec<Dim> omega = AngularVec<Dim>::Zero();
};

template <int Dim>
struct RigidLoad {
  Vec<Dim> force = Vec<Dim>::Zero();                 // N (2D: per unit depth)
  AngularVec<Dim> torque = AngularVec<Dim>::Zero();  // about the centre of mass
};

// omega x r (2D: omega about z).
template <int Dim>
Vec<Dim> rigid_velocity(const AngularVec<Dim>& omega, const Vec<Dim>& r);

// r x f (2D: its z component).
template <int Dim>
AngularVec<Dim> moment(const Vec<Dim>& r, const Vec<Dim>& f);

// Appends solid particles of body `body` at the space positions `x`, taking their body-frame
// offsets from `pose`, with the pose's rigid velocity. Each gets its depth below the body's
// surface (wall_distance; the surface half a spacing beyond the outermost particles) and the
// outward normal (normal, and body_normal in the body frame), so that the viscous term can put
// the no-slip condition on that surface, as for walls (IsphSolver::compute_wall_ghosts).
template <int Dim>
void add_rigid_body(Particles<Dim>& particles, int body, const std::vector<Vec<Dim>>& x,
                    const RigidPose<Dim>& pose);

// Puts every solid particle at its body's pose with v = v_cm + omega x r. poses[b] is body b.
template <int Dim>
void place_rigid_solids(Particles<Dim>& particles, const Domain<Dim>& domain,
                        const std::vector<RigidPose<Dim>>& poses);

// Sums the solid particles' fluid forces per body, and their moments about the body's centre
// (centres[b]; separations by the minimum image on periodic axes).
template <int Dim>
std::vector<RigidLoad<Dim>> rigid_solid_loads(const Particles<Dim>& particles,
                                              const Domain<Dim>& domain,
                                              const std::vector<Vec<Dim>>& centres);

// The PMS force on solid particle i (see the top of this file), from its predicted velocity
// u* = v + dt (nu lap u + g) and its pressure gradient: zero above the waterline; on the
// waterline row (p = 0, like the fluid's top row) the gradient leaves out the dry particles above
// it, which hold p = 0 where the hydrostatic field would continue: with them the row felt half
// the gradient, and a held floating box lost half a row of buoyancy (10% at H = 10 dx).
template <int Dim>
Vec<Dim> pms_force(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                   const Operators<Dim>& op, int i, double rho0, double dt, const Vec<Dim>& u_star,
                   const Vec<Dim>& gravity);

// Particles::surface value of a solid particle above the waterline: p = 0 and no fluid force.
constexpr uint8_t kDrySolid = 2;

// A floating body's particles above the water must not be fluid rows: computed as fluid, the
// emerged part is a mound of water whose weight the projection carries down to the wetted
// surface, and a box of half the fluid's density floated 18% too high. The waterline next to each
// body is taken from the free-surface fluid particles within two supports of it (a least-squares
// line in 2D, its mean height in 3D); solid particles more than half a spacing above it become
// dry (surface = kDrySolid: p = 0, no force), those within half a spacing of it get p = 0 like
// the fluid's own top row (they still carry the pressure gradient below them, as that row does).
// Bodies with no free surface near them are untouched. Call it only where the scene has solids
// (on some process, decomposed): it sweeps the fluid rows all the same. With shared rows
// (sph/row_share.hpp, nb for this process's rows only) the waterline is fitted from all processes'
// points in the one-process order, and the fluid rows' marks are this process's rows'.
template <int Dim>
void mark_dry_solids(Particles<Dim>& particles, const Neighbors<Dim>& nb, const Vec<Dim>& gravity,
                     const RowShare* share = nullptr);

// Removes the particles with drop[i] != 0 (all arrays, order kept).
template <int Dim>
void erase_particles(Particles<Dim>& particles, const std::vector<uint8_t>& drop);

}  // namespace isph
