#include "io/dem_snapshot.hpp"

namespace isphdem {

namespace {
Vec3 lookup(const std::map<int, Vec3>& m, int key) {
  const auto it = m.find(key);
  return it == m.end() ? Vec3{0, 0, 0} : it->second;
}
}  // namespace

HydroLoads hydro_loads(const DemLoads& l) {
  HydroLoads hydro;
  for (std::size_t k = 0; k < l.atom_tags.size(); ++k)
    hydro.atom_force[l.atom_tags[k]] = l.atom_force[k];
  for (std::size_t k = 0; k < l.body_ids.size(); ++k) {
    hydro.body_force[l.body_ids[k]] = l.body_force[k];
    hydro.body_torque[l.body_ids[k]] = l.body_torque[k];
  }
  return hydro;
}

void add_dem_groups(const DemState& state, const HydroLoads& loads, Snapshot& snapshot,
                    const GrainModels* models) {
  const auto& A = state.atoms;
  Group& dem = snapshot.group("dem");
  const std::size_t m = A.size();
  dem.add_generated<double>("position", m, 3,
                            [&](std::size_t i, std::size_t c) { return A[i].x[c]; });
  dem.add_generated<double>("velocity", m, 3,
                            [&](std::size_t i, std::size_t c) { return A[i].v[c]; });
  dem.add_generated<double>("radius", m, 1,
                            [&](std::size_t i, std::size_t) { return A[i].radius; });
  dem.add_generated<int64_t>("id", m, 1,
                             [&](std::size_t i, std::size_t) { return int64_t(A[i].tag); });
  dem.add_generated<int64_t>("body", m, 1,
                             [&](std::size_t i, std::size_t) { return int64_t(A[i].body); });
  dem.add_generated<double>("force_hydro", m, 3, [&](std::size_t i, std::size_t c) {
    return lookup(loads.atom_force, A[i].tag)[c];
  });
  if (models)
    dem.add_generated<int64_t>("model", m, 1, [&](std::size_t i, std::size_t) {
      return int64_t(A[i].body >= 0 ? models->clumps : models->free_spheres);
    });

  const auto& B = state.bodies;
  Group& bodies = snapshot.group("bodies");
  const std::size_t nb = B.size();
  bodies.add_generated<double>("position", nb, 3,
                               [&](std::size_t i, std::size_t c) { return B[i].x[c]; });
  bodies.add_generated<double>("velocity", nb, 3,
                               [&](std::size_t i, std::size_t c) { return B[i].v[c]; });
  bodies.add_generated<double>("omega", nb, 3,
                               [&](std::size_t i, std::size_t c) { return B[i].omega[c]; });
  // Quaternion order (w, x, y, z): body principal frame to space frame.
  bodies.add_generated<double>("quat", nb, 4,
                               [&](std::size_t i, std::size_t c) { return B[i].quat[c]; });
  bodies.add_generated<double>("mass", nb, 1,
                               [&](std::size_t i, std::size_t) { return B[i].mass; });
  bodies.add_generated<double>("volume", nb, 1,
                               [&](std::size_t i, std::size_t) { return B[i].volume; });
  bodies.add_generated<int64_t>("id", nb, 1,
                                [&](std::size_t i, std::size_t) { return int64_t(B[i].id); });
  bodies.add_generated<double>("force_hydro", nb, 3, [&](std::size_t i, std::size_t c) {
    return lookup(loads.body_force, B[i].id)[c];
  });
  bodies.add_generated<double>("torque_hydro", nb, 3, [&](std::size_t i, std::size_t c) {
    return lookup(loads.body_torque, B[i].id)[c];
  });
}

}  // namespace isphdem
