#pragma once
// Small scenes for the resolved-coupling tests: a hydrostatic tank from the shipped example, a
// clump built as the DEM would report it, and a rigid-body integrator standing in for LIGGGHTS
// (DESIGN.md decision 4: quasi-2D bodies move in x-y and rotate about z).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"
#include "resolved/resolved_coupling.hpp"

namespace isphdem::resolved_test {

inline std::string example(const std::string& name) {
  return std::string(ISPHDEM_SOURCE_DIR) + "/examples/" + name + "/case.toml";
}

// The fluid scene of a shipped fluid-only example, with --set-style overrides.
template <int Dim>
FluidScene<Dim> example_scene(const std::string& name, const std::vector<std::string>& overrides) {
  auto keys = fluid_scene_keys();
  const auto r = run_settings_keys();
  keys.insert(keys.end(), r.begin(), r.end());
  keys.push_back("reference.*");  // error metrics of `isphdem run`: not read here
  return build_fluid_scene<Dim>(CaseFile::load(example(name), overrides, keys));
}

template <int Dim>
FluidScene<Dim> tank(const std::vector<std::string>& overrides) {
  return example_scene<Dim>("hydrostatic_2d", overrides);
}

// --set overrides of taylor_green_2d for a periodic 2D box [0, Lx] x [0, Ly] full of fluid at
// rest, of viscosity nu, driven by the body force g along x (Stokes arrays, channels).
inline std::vector<std::string> periodic_box_2d(double Lx, double Ly, double dx, double nu,
                                                double g) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", nu);
  const std::string box = "[" + std::to_string(Lx) + "," + std::to_string(Ly) + "]";
  return {"case.dimension=2",
          std::string("fluid.viscosity=") + buf,
          "initial.velocity=\"rest\"",
          "particles.spacing=" + std::to_string(dx),
          "domain.min=[0,0]",
          "domain.max=" + box,
          "domain.periodic=[true,true]",
          "fluid.blocks=[{min=[0,0],max=" + box + "}]",
          "fluid.gravity=[" + std::to_string(g) + ",0]"};
}

// A clump of equal spheres (centres in space, radius r, density rho_s); members do not overlap,
// so V = sum of sphere volumes. Inertia about the centre of mass, principal axes = space axes
// (exact for the symmetric arrangements used here).
inline DemState clump(const std::vector<Vec3>& centres, double r, double rho_s) {
  DemState s;
  DemBody b;
  b.id = 1;
  const double vs = 4.0 / 3.0 * M_PI * r * r * r;
  Vec3 cm{0, 0, 0};
  for (const auto& c : centres)
    for (int k = 0; k < 3; ++k) cm[k] += c[k] / centres.size();
  b.x = cm;
  b.volume = vs * centres.size();
  b.mass = rho_s * b.volume;
  const double ms = rho_s * vs;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    DemAtom a;
    a.tag = static_cast<int>(i) + 1;
    a.x = centres[i];
    a.radius = r;
    a.body = b.id;
    s.atoms.push_back(a);
    b.members.push_back(a.tag);
    Vec3 d{centres[i][0] - cm[0], centres[i][1] - cm[1], centres[i][2] - cm[2]};
    const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for (int k = 0; k < 3; ++k) b.inertia[k] += 0.4 * ms * r * r + ms * (d2 - d[k] * d[k]);
  }
  b.axes = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  s.bodies.push_back(b);
  return s;
}

// The resolved stage's settings for a held body of radius a in a periodic array: PMS particles
// on the fluid lattice, the body's volume the particles' own (no DEM volume), and in 2D a slab
// T = 4a/3, in which a sphere's section is the disc of radius a.
inline ResolvedSettings held_body_settings(double dx, double rho, double a) {
  ResolvedSettings set;
  set.spacing = dx;
  set.fluid_density = rho;
  set.slab_thickness = 4.0 * a / 3.0;
  set.shape = PmsShape::Lattice;
  set.dem_volume = false;
  return set;
}

// Quasi-2D rigid-body step (what fix multisphere + fix couple/isph planar z do): semi-implicit
// Euler with gravity g and the hydrodynamic loads; members follow the body.
inline void integrate_planar(DemState& s, const DemLoads& loads, double gy, double dt) {
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    DemBody& b = s.bodies[k];
    const Vec3& f = loads.body_force[k];
    b.v[0] += dt * f[0] / b.mass;
    b.v[1] += dt * (f[1] / b.mass + gy);
    b.omega[2] += dt * loads.body_torque[k][2] / b.inertia[2];
    const double dtheta = dt * b.omega[2];
    const double c = std::cos(dtheta), sn = std::sin(dtheta);
    for (auto& a : s.atoms) {
      if (a.body != b.id) continue;
      const double rx = a.x[0] - b.x[0], ry = a.x[1] - b.x[1];
      a.x[0] = b.x[0] + dt * b.v[0] + c * rx - sn * ry;
      a.x[1] = b.x[1] + dt * b.v[1] + sn * rx + c * ry;
    }
    b.x[0] += dt * b.v[0];
    b.x[1] += dt * b.v[1];
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(Eigen::AngleAxisd(dtheta, Eigen::Vector3d::UnitZ())) *
        Eigen::Quaterniond(b.quat[0], b.quat[1], b.quat[2], b.quat[3]);
    b.quat = {q.w(), q.x(), q.y(), q.z()};
  }
}

}  // namespace isphdem::resolved_test
