#include "rigid_solids.hpp"

#include <stdexcept>
#include <string>

namespace isph {

template <>
Vec<2> rigid_velocity<2>(const AngularVec<2>& omega, const Vec<2>& r) {
  return Vec<2>(-omega[0] * r[1], omega[0] * r[0]);
}
template <>
Vec<3> rigid_velocity<3>(const AngularVec<3>& omega, const Vec<3>& r) {
  return omega.cross(r);
}
template <>
AngularVec<2> moment<2>(const Vec<2>& r, const Vec<2>& f) {
  return AngularVec<2>(r[0] * f[1] - r[1] * f[0]);
}
template <>
AngularVec<3> moment<3>(const Vec<3>& r, const Vec<3>& f) {
  return r.cross(f);
}

template <int Dim>
void add_rigid_body(Particles<Dim>& particles, int body, const std::vector<Vec<Dim>>& x,
                    const RigidPose<Dim>& pose) {
  if (body < 0) throw std::invalid_argument("rigid body index must not be negative");
  for (const auto& xi : x) {
    const Vec<Dim> r = xi - pose.x;
    particles.add(xi, pose.v + rigid_velocity<Dim>(pose.omega, r), kSolid);
    particles.body.back() = body;
    particles.body_offset.back() = pose.rotation.transpose() * r;
  }
}

template <int Dim>
void place_rigid_solids(Particles<Dim>& particles, const Domain<Dim>& domain,
                        const std::vector<RigidPose<Dim>>& poses) {
  const int n = static_cast<int>(particles.size());
  for (int i = 0; i < n; ++i) {
    if (particles.kind[i] != kSolid) continue;
    const int b = particles.body[i];
    if (b < 0 || b >= static_cast<int>(poses.size()))
      throw std::out_of_range("solid particle " + std::to_string(particles.id[i]) +
                              " belongs to rigid body " + std::to_string(b) + " but only " +
                              std::to_string(poses.size()) + " poses were given");
    const RigidPose<Dim>& q = poses[b];
    const Vec<Dim> r = q.rotation * particles.body_offset[i];
    particles.x[i] = q.x + r;
    domain.wrap(particles.x[i]);
    particles.v[i] = q.v + rigid_velocity<Dim>(q.omega, r);
  }
}

template <int Dim>
std::vector<RigidLoad<Dim>> rigid_solid_loads(const Particles<Dim>& particles,
                                              const Domain<Dim>& domain,
                                              const std::vector<Vec<Dim>>& centres) {
  std::vector<RigidLoad<Dim>> loads(centres.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.kind[i] != kSolid) continue;
    const int b = particles.body[i];
    if (b < 0 || b >= static_cast<int>(centres.size()))
      throw std::out_of_range("solid particle " + std::to_string(particles.id[i]) +
                              " belongs to rigid body " + std::to_string(b) + " but only " +
                              std::to_string(centres.size()) + " centres were given");
    const Vec<Dim>& f = particles.solid_force[i];
    loads[b].force += f;
    loads[b].torque += moment<Dim>(domain.min_image(particles.x[i] - centres[b]), f);
  }
  return loads;
}

template <int Dim>
void erase_particles(Particles<Dim>& particles, const std::vector<uint8_t>& drop) {
  if (drop.size() != particles.size())
    throw std::invalid_argument("erase_particles: mask size differs from the particle count");
  particles.for_each_array([&](auto& a) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!drop[i]) a[k++] = a[i];
    a.resize(k);
  });
}

template void add_rigid_body<2>(Particles<2>&, int, const std::vector<Vec<2>>&,
                                const RigidPose<2>&);
template void add_rigid_body<3>(Particles<3>&, int, const std::vector<Vec<3>>&,
                                const RigidPose<3>&);
template void place_rigid_solids<2>(Particles<2>&, const Domain<2>&,
                                    const std::vector<RigidPose<2>>&);
template void place_rigid_solids<3>(Particles<3>&, const Domain<3>&,
                                    const std::vector<RigidPose<3>>&);
template std::vector<RigidLoad<2>> rigid_solid_loads<2>(const Particles<2>&, const Domain<2>&,
                                                        const std::vector<Vec<2>>&);
template std::vector<RigidLoad<3>> rigid_solid_loads<3>(const Particles<3>&, const Domain<3>&,
                                                        const std::vector<Vec<3>>&);
template void erase_particles<2>(Particles<2>&, const std::vector<uint8_t>&);
template void erase_particles<3>(Particles<3>&, const std::vector<uint8_t>&);

}  // namespace isph
