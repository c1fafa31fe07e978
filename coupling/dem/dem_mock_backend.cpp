#include "dem/dem_mock_backend.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace isphdem {

MockDemBackend::MockDemBackend(std::vector<DemAtom> atoms, double dt, double density, Vec3 gravity)
    : dt_(dt), density_(density), gravity_(gravity) {
  if (!(dt > 0.0)) throw std::invalid_argument("MockDemBackend: dt must be > 0");
  state_.atoms = std::move(atoms);
  for (size_t k = 0; k < state_.atoms.size(); k++) {
    if (state_.atoms[k].body != -1)
      throw std::invalid_argument("MockDemBackend: free spheres only (body must be -1)");
    if (!index_.emplace(state_.atoms[k].tag, k).second)
      throw std::invalid_argument("MockDemBackend: duplicate tag " +
                                  std::to_string(state_.atoms[k].tag));
  }
  force_.assign(state_.atoms.size(), Vec3{});
  torque_.assign(state_.atoms.size(), Vec3{});
}

void MockDemBackend::initialize(const DemSetup& setup) {
  setup_ = setup;
  state_.time = 0.0;
}

size_t MockDemBackend::index_of(int tag) const {
  auto it = index_.find(tag);
  if (it == index_.end())
    throw std::invalid_argument("set_atom_loads: no atom has tag " + std::to_string(tag));
  return it->second;
}

double MockDemBackend::mass(int tag) const {
  const double r = state_.atoms[index_of(tag)].radius;
  return density_ * 4.0 / 3.0 * M_PI * r * r * r;
}

double MockDemBackend::moment_of_inertia(int tag) const {
  const double r = state_.atoms[index_of(tag)].radius;
  return 0.4 * mass(tag) * r * r;
}

void MockDemBackend::set_atom_loads(const std::vector<int>& tags, const std::vector<Vec3>& force,
                                    const std::vector<Vec3>& torque) {
  if (force.size() != tags.size() || torque.size() != tags.size())
    throw std::invalid_argument("set_atom_loads: sizes of tags, force and torque differ");
  std::vector<Vec3> f(state_.atoms.size(), Vec3{}), t(state_.atoms.size(), Vec3{});
  for (size_t k = 0; k < tags.size(); k++) {
    const size_t i = index_of(tags[k]);
    f[i] = force[k];
    t[i] = torque[k];
  }
  force_ = std::move(f);
  torque_ = std::move(t);
}

void MockDemBackend::set_body_loads(const std::vector<int>& ids, const std::vector<Vec3>&,
                                    const std::vector<Vec3>&) {
  if (!ids.empty())
    throw std::invalid_argument("set_body_loads: the mock has no bodies (id " +
                                std::to_string(ids.front()) + ")");
}

// Loads and gravity are constant over a step, so x += v dt + a dt^2 / 2, v += a dt is exact.
void MockDemBackend::advance(int n_substeps) {
  if (n_substeps < 1) throw std::invalid_argument("advance: n_substeps must be >= 1");
  for (int s = 0; s < n_substeps; s++) {
    for (size_t i = 0; i < state_.atoms.size(); i++) {
      DemAtom& a = state_.atoms[i];
      const double m = mass(a.tag), inertia = 0.4 * m * a.radius * a.radius;
      for (int c = 0; c < 3; c++) {
        const double acc = force_[i][c] / m + gravity_[c];
        a.x[c] += a.v[c] * dt_ + 0.5 * acc * dt_ * dt_;
        a.v[c] += acc * dt_;
        a.omega[c] += torque_[i][c] / inertia * dt_;
      }
    }
    state_.step++;
  }
  state_.time += n_substeps * dt_;
}

}  // namespace isphdem
