// PMS particles of one multisphere clump, generated once from its member spheres
// (docs/resolved.md).
//
// Volume: the body's DEM volume V is the reference (its mass is rho_s V in LIGGGHTS). A clump gets
// N = round(V / dx^3) particles in 3D and N = round(V / (T dx^2)) in 2D (slab thickness T), so
// that the fluid sees the same solid volume as the DEM -- and as the porosity of the unresolved
// coupling, which also divides solid volume by area x T. Buoyancy is then rho_f g V to half a
// particle. In 2D that makes the section an "equivalent cylinder": a sphere of radius r in a
// slab of thickness T is a disc of area V/T, which equals its great circle only when
// T = 4r/3; for other T the section is the union of the members' circles, eroded (T > 4r/3) or
// dilated (T < 4r/3) uniformly to that area.
//
// Lattice: the particles sit on the fluid lattice (the one through `origin`), so that replacing
// the fluid particles inside the body by solids leaves the particle arrangement -- and the
// number density the PPE stabilisation sees -- exactly as it was. They are the N lattice nodes
// deepest inside the union of the member spheres, except that within +-0.35 dx of the boundary
// the nodes are chosen to keep the particles' centroid on the DEM centre of mass: an offset
// centroid gives buoyancy a spurious torque.
//
// Spheres about one spacing wide (the seed's clumps of dx-sized spheres) get one particle per
// member at the sphere's centre instead: a lattice cannot resolve them, and one particle per
// sphere keeps the clump's shape. Their solid volume is N dx^Dim (x T), which differs from V;
// ResolvedCoupling reports the ratio.
//
// Outline: every lattice node inside the members (or within 0.15 dx of one, which closes the
// interstices of touching dx-wide spheres). For the seed's coarse grains (19 touching 1 mm
// spheres, dx = 1 mm, T = 1 mm) that is 16-21 particles where the DEM volume asks for 10: about
// the seed's one per sphere, but on the lattice. The volume-matched lattice leaves a clear rim
// inside the grain's outline, and between two touching grains a channel one or two spacings
// wide that the DEM says is closed; pore jets ran away there at 2 cm/s
// (examples/internal_erosion_2d). With coupling.pms_volume = "dem" the loads are still those of
// the DEM volume, but the pores are narrower than the slab's solid fraction says
// (docs/resolved.md).
#ifndef ISPHDEM_PMS_GENERATION_HPP
#define ISPHDEM_PMS_GENERATION_HPP

#include <string>
#include <vector>

#include "dem_state.hpp"
#include "domain.hpp"
#include "vec.hpp"

namespace isphdem {

enum class PmsShape {
  Auto,       // per_sphere when every member is at most 1.5 dx wide, else lattice
  Lattice,    // volume-matched lattice nodes inside the members
  PerSphere,  // one particle at each member's centre
  Outline,    // every lattice node inside the members' outline (as many as per-sphere gives)
};

PmsShape pms_shape_from_name(const std::string& name);

struct PmsGenerationSettings {
  double spacing = 0.0;         // dx [m]
  double slab_thickness = 0.0;  // T [m], 2D only
  PmsShape shape = PmsShape::Auto;
};

// Space positions (x-y plane in 2D) of the PMS particles of `body` at its present pose. `members`
// are its atoms; `origin` is any node of the fluid lattice. Throws std::invalid_argument with
// the cause and the fix for unusable input (no members, zero volume, too small for one particle).
template <int Dim>
std::vector<isph::Vec<Dim>> generate_pms_particles(const DemBody& body,
                                                   const std::vector<DemAtom>& members,
                                                   const PmsGenerationSettings& settings,
                                                   const isph::Vec<Dim>& origin);

// Two clumps in contact generate their particles independently, so on a lattice both may take the
// node at their contact (in examples/internal_erosion_2d, two solid particles at distance 0):
// a doubled particle the fitted operators and the pressure rows cannot resolve, where the first
// pore jets of the semi-resolved runs started. Of every pair of particles of different bodies
// closer than half a spacing, the one less deep inside its own member spheres is removed (never
// a body's last particle). `particles[b]` are body b's positions from generate_pms_particles.
// Returns how many were removed.
template <int Dim>
std::size_t remove_shared_pms_nodes(std::vector<std::vector<isph::Vec<Dim>>>& particles,
                                    const std::vector<DemBody>& bodies,
                                    const std::vector<std::vector<DemAtom>>& members,
                                    const isph::Domain<Dim>& domain, double spacing);

// Where a PMS particle lies under the body's surface: its depth below it (m) and the outward
// normal there, in space coordinates.
template <int Dim>
struct PmsSurfacePoint {
  double depth = 0.0;
  isph::Vec<Dim> normal = isph::Vec<Dim>::Zero();
  bool found = false;  // false: no exposed member surface is nearer than the others (a crease)
};

// The body's surface as its member spheres give it (coupling.pms_surface = "spheres"), for the
// no-slip ghosts of the viscous term, instead of the lattice staircase (add_rigid_body's depth
// from the nearest free lattice node: 0.5 dx for every outer particle, whatever the curvature).
// A volume-matched lattice body stands for the level set of the members' depth that encloses
// the DEM volume (2D: the section of area V/T, the members' circles eroded or dilated uniformly,
// see the top of this file); an outline body for the spheres themselves. Each particle's surface
// point is the nearest of the members' (eroded) surfaces along the radius through it that no
// other member covers; its depth and normal are that sphere's. A lattice node chosen from the
// band around the level (see above) may lie just outside it: its depth is then negative. A
// per-sphere body (pms_shape, or auto with sections at most 1.5 dx wide) gets no surface points.
// Periodic separations by `domain`'s minimum image.
template <int Dim>
std::vector<PmsSurfacePoint<Dim>> pms_surface_from_spheres(const DemBody& body,
                                                           const std::vector<DemAtom>& members,
                                                           const PmsGenerationSettings& settings,
                                                           const isph::Domain<Dim>& domain,
                                                           const std::vector<isph::Vec<Dim>>& x);

// The solid volume the fluid sees for n PMS particles: n dx^3, or n dx^2 T in 2D.
template <int Dim>
double pms_volume(std::size_t n, const PmsGenerationSettings& settings);

}  // namespace isphdem

#endif
