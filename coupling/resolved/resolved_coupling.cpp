#include "resolved/resolved_coupling.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "format_number.hpp"

namespace isphdem {

namespace {

std::string num(double v) { return isph::format_number(v); }

Eigen::Matrix3d rotation_of(const Quat& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

template <int Dim>
isph::Vec<Dim> in_plane(const Vec3& a) {
  isph::Vec<Dim> v;
  for (int k = 0; k < Dim; ++k) v[k] = a[k];
  return v;
}

}  // namespace

template <int Dim>
ResolvedCoupling<Dim>::ResolvedCoupling(const ResolvedSettings& settings) : settings_(settings) {
  if (!(settings.spacing > 0.0))
    throw std::invalid_argument("resolved coupling: the particle spacing must be positive");
  if (!(settings.fluid_density > 0.0))
    throw std::invalid_argument("resolved coupling: the fluid density must be positive");
  if (Dim == 2 && !(settings.slab_thickness > 0.0))
    throw std::invalid_argument(
        "resolved coupling: a 2D fluid needs coupling.slab_thickness, the thickness of the "
        "quasi-2D DEM slab in z (DESIGN.md decision 4)");
  if (!(settings.overlap > 0.0 && settings.overlap < 1.0))
    throw std::invalid_argument("resolved coupling: overlap must lie in (0, 1) spacings, got " +
                                num(settings.overlap));
}

template <int Dim>
std::string ResolvedCoupling<Dim>::name_of(int body_id) {
  return body_id < 0 ? "free sphere (atom " + std::to_string(-body_id) + ")"
                     : "multisphere body " + std::to_string(body_id);
}

template <int Dim>
std::vector<DemBody> ResolvedCoupling<Dim>::resolved_bodies(const DemState& dem) const {
  std::vector<DemBody> bodies = dem.bodies;
  if (!settings_.free_spheres) return bodies;
  for (const auto& a : dem.atoms) {
    if (a.body != -1) continue;
    DemBody b;
    b.id = -a.tag;
    b.x = a.x;
    b.v = a.v;
    b.omega = a.omega;
    b.volume = 4.0 / 3.0 * M_PI * a.radius * a.radius * a.radius;
    b.members = {a.tag};
    bodies.push_back(std::move(b));
  }
  return bodies;
}

template <int Dim>
int ResolvedCoupling<Dim>::index_of(int body_id) const {
  const auto it = index_.find(body_id);
  if (it == index_.end())
    throw std::runtime_error("resolved coupling: " + name_of(body_id) +
                             " did not exist when the coupling started; grains inserted later "
                             "are not resolved yet: insert all grains before the coupled run");
  return it->second;
}

template <int Dim>
isph::RigidPose<Dim> ResolvedCoupling<Dim>::pose(const DemBody& body) const {
  const int b = index_of(body.id);
  // Rotation since initialize(): offsets are kept in the space frame of that moment, so the
  // principal-axis order LIGGGHTS chose (a planar clump's normal may be any of them) does not
  // matter, and in 2D the relative rotation is one about z.
  const Eigen::Matrix3d rel = rotation_of(body.quat) * initial_rotation_[b].transpose();
  if (Dim == 2 && std::abs(rel(2, 2) - 1.0) > 1e-6)
    throw std::runtime_error("resolved coupling: " + name_of(body.id) +
                             " rotated out of the x-y plane (cos = " + num(rel(2, 2)) +
                             "): a 2D fluid needs planar clumps; add 'fix ID all couple/isph "
                             "planar z Z0' to the LIGGGHTS script");
  isph::RigidPose<Dim> p;
  p.x = in_plane<Dim>(body.x);
  p.rotation = rel.topLeftCorner<Dim, Dim>();
  p.v = in_plane<Dim>(body.v);
  if constexpr (Dim == 2)
    p.omega[0] = body.omega[2];
  else
    p.omega = Eigen::Vector3d(body.omega[0], body.omega[1], body.omega[2]);
  return p;
}

template <int Dim>
void ResolvedCoupling<Dim>::initialize(const DemState& dem, isph::IsphSolver<Dim>& solver) {
  auto& P = solver.particles();
  const double dx = settings_.spacing;
  if (std::abs(P.spacing - dx) > 1e-9 * dx)
    throw std::invalid_argument("resolved coupling: spacing " + num(dx) +
                                " differs from the fluid's particles.spacing " + num(P.spacing));
  if (std::abs(solver.config().density - settings_.fluid_density) > 1e-9 * settings_.fluid_density)
    throw std::invalid_argument("resolved coupling: fluid density " + num(settings_.fluid_density) +
                                " differs from the solver's " + num(solver.config().density));
  if (!info_.empty()) throw std::logic_error("resolved coupling: initialize() called twice");
  // Every process adds every body's particles and finds their lattice in the whole fluid: the
  // fluid is decomposed after this, with the solids in it (IsphSolver::decompose).
  if (solver.decomposed())
    throw std::logic_error("resolved coupling: initialize() after the fluid was decomposed");
  if (P.count(isph::kSolid) > 0)
    throw std::invalid_argument(
        "resolved coupling: the fluid scene already has solid particles; PMS particles are made "
        "from the DEM clumps only");

  std::map<int, const DemAtom*> atom_by_tag;
  for (const auto& a : dem.atoms) atom_by_tag[a.tag] = &a;
  PmsGenerationSettings gen{dx, settings_.slab_thickness, settings_.shape};
  const auto& domain = solver.domain();
  const std::vector<DemBody> bodies = resolved_bodies(dem);

  std::vector<std::vector<DemAtom>> members_of(bodies.size());
  std::vector<std::vector<isph::Vec<Dim>>> positions(bodies.size());
  for (std::size_t bi = 0; bi < bodies.size(); ++bi) {
    const DemBody& body = bodies[bi];
    std::vector<DemAtom>& members = members_of[bi];
    for (int tag : body.members) {
      const auto it = atom_by_tag.find(tag);
      if (it == atom_by_tag.end())
        throw std::invalid_argument("resolved coupling: member atom " + std::to_string(tag) +
                                    " of " + name_of(body.id) + " is missing from the DEM state");
      members.push_back(*it->second);
    }
    // The fluid lattice node nearest to the body: PMS particles are put on the same lattice.
    const isph::Vec<Dim> cm = in_plane<Dim>(body.x);
    isph::Vec<Dim> origin = domain.lo + isph::Vec<Dim>::Constant(0.5 * dx);
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != isph::kFluid) continue;
      const double d = domain.min_image(P.x[i] - cm).norm();
      if (d < best) {
        best = d;
        origin = P.x[i];
      }
    }
    positions[bi] = generate_pms_particles<Dim>(body, members, gen, origin);
  }
  const std::size_t shared =
      remove_shared_pms_nodes<Dim>(positions, bodies, members_of, domain, dx);
  if (shared > 0 && settings_.report)
    std::printf(
        "resolved coupling: %zu PMS particles dropped where touching bodies took the same "
        "lattice node\n",
        shared);

  for (std::size_t bi = 0; bi < bodies.size(); ++bi) {
    const DemBody& body = bodies[bi];
    const std::vector<isph::Vec<Dim>>& x = positions[bi];
    const isph::Vec<Dim> cm = in_plane<Dim>(body.x);
    for (const auto& xi : x)
      if (!domain.contains(xi))
        throw std::invalid_argument("resolved coupling: " + name_of(body.id) +
                                    " reaches outside the fluid domain: move it inside or "
                                    "enlarge domain.min/domain.max");

    // Walls closer than half a spacing would share nodes with the body.
    std::vector<uint8_t> drop(P.size(), 0);
    const double wall_gap = 0.5 * dx * (1.0 - 1e-9), overlap = settings_.overlap * dx;
    // Only particles near the body's bounding box are compared with its particles (a scene has
    // many clumps and many more fluid particles).
    isph::Vec<Dim> lo = x.front(), hi = x.front();
    for (const auto& xi : x) {
      lo = lo.cwiseMin(xi);
      hi = hi.cwiseMax(xi);
    }
    const isph::Vec<Dim> box_centre = 0.5 * (lo + hi);
    const isph::Vec<Dim> box_half = 0.5 * (hi - lo) + isph::Vec<Dim>::Constant(dx);
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] == isph::kSolid) continue;
      if ((domain.min_image(P.x[i] - box_centre).cwiseAbs() - box_half).maxCoeff() > 0.0) continue;
      const double limit = P.kind[i] == isph::kWall ? wall_gap : overlap;
      for (const auto& xi : x) {
        if (domain.min_image(P.x[i] - xi).squaredNorm() >= limit * limit) continue;
        if (P.kind[i] == isph::kWall) {
          std::ostringstream s;
          s << "resolved coupling: " << name_of(body.id) << " overlaps the wall particle at ("
            << P.x[i].transpose() << "): start the clump at least half a spacing (" << 0.5 * dx
            << " m) from walls";
          throw std::invalid_argument(s.str());
        }
        drop[i] = 1;
        break;
      }
    }
    for (auto d : drop) removed_ += d;
    isph::erase_particles(P, drop);

    const int b = static_cast<int>(info_.size());
    if (!index_.emplace(body.id, b).second)
      throw std::invalid_argument("resolved coupling: body id " + std::to_string(body.id) +
                                  " appears twice in the DEM state");
    initial_rotation_.push_back(rotation_of(body.quat));
    isph::Vec<Dim> centroid = isph::Vec<Dim>::Zero();
    for (const auto& xi : x) centroid += (xi - cm) / static_cast<double>(x.size());
    centroid_offset_.push_back(centroid);
    const std::size_t first = P.size();
    isph::add_rigid_body<Dim>(P, b, x, pose(body));  // offsets from unwrapped positions
    for (std::size_t i = first; i < P.size(); ++i) domain.wrap(P.x[i]);
    if (settings_.surface_from_spheres) {
      const auto surface = pms_surface_from_spheres<Dim>(body, members_of[bi], gen, domain, x);
      const Eigen::Matrix<double, Dim, Dim> to_body = pose(body).rotation.transpose();
      for (std::size_t k = 0; k < x.size(); ++k) {
        if (!surface[k].found) continue;  // in a crease between members: the lattice's estimate
        const std::size_t i = first + k;
        P.wall_distance[i] = surface[k].depth;
        P.normal[i] = surface[k].normal;
        P.body_normal[i] = to_body * surface[k].normal;
      }
    }
    BodyInfo info;
    info.id = body.id;
    info.particles = x.size();
    info.dem_volume = body.volume;
    info.fluid_volume = pms_volume<Dim>(x.size(), gen);
    // 2D loads are per unit depth; the slab is T deep.
    info.scale = Dim == 2 ? settings_.slab_thickness : 1.0;
    if (settings_.dem_volume) {
      if (!(body.volume > 0.0))
        throw std::invalid_argument("resolved coupling: " + name_of(body.id) + " has volume " +
                                    num(body.volume) +
                                    ": give the particle template a volume (use_volume), or set "
                                    "coupling.pms_volume = \"particles\"");
      info.scale *= body.volume / info.fluid_volume;
    }
    info_.push_back(info);
    if (body.id >= 0 && settings_.report)  // one line per clump; fines may be thousands
      std::printf(
          "resolved coupling: body %d: %zu PMS particles, solid volume seen by the fluid %.6g "
          "m^3 = %.4f x the DEM volume\n",
          body.id, x.size(), info.fluid_volume,
          body.volume > 0.0 ? info.fluid_volume / body.volume : 0.0);
  }
  if (bodies.size() > dem.bodies.size() && settings_.report)
    std::printf("resolved coupling: %zu free spheres resolved, %zu PMS particles in all\n",
                bodies.size() - dem.bodies.size(), P.count(isph::kSolid));
}

template <int Dim>
void ResolvedCoupling<Dim>::move_particles(const DemState& dem, isph::IsphSolver<Dim>& solver) {
  std::vector<isph::RigidPose<Dim>> poses(info_.size());
  std::vector<uint8_t> seen(info_.size(), 0);
  for (const DemBody& body : resolved_bodies(dem)) {
    const int b = index_of(body.id);
    poses[b] = pose(body);
    seen[b] = 1;
  }
  for (std::size_t b = 0; b < info_.size(); ++b)
    if (!seen[b])
      throw std::runtime_error("resolved coupling: " + name_of(info_[b].id) +
                               " vanished from the DEM state (deleted or left the DEM domain); "
                               "keep grains inside the DEM box");
  isph::place_rigid_solids(solver.particles(), solver.domain(), poses);
}

template <int Dim>
void ResolvedCoupling<Dim>::after_fluid_step(const DemState& dem,
                                             const isph::IsphSolver<Dim>& solver, double /*dt*/,
                                             DemLoads& loads) {
  // Moments about the PMS particles' centroid, which stands for the centre of mass: the lattice
  // can place it only to within ~dx/(2N) of it, and that offset times the buoyancy turned a
  // neutral L-shaped clump by 0.03 rad in 0.5 s. For a uniform body the DEM's centre of mass is
  // its centroid, so the lever arms are those of the DEM body.
  std::vector<isph::Vec<Dim>> centres(info_.size(), isph::Vec<Dim>::Zero());
  for (const DemBody& body : resolved_bodies(dem)) {
    const int b = index_of(body.id);
    centres[b] = in_plane<Dim>(body.x) + pose(body).rotation * centroid_offset_[b];
  }
  auto sums = isph::rigid_solid_loads(solver.particles(), solver.domain(), centres);
  if (const isph::RowShare* ranks = solver.decomposition()) {
    // Each process summed its own particles: every body takes the shares of all processes (the
    // same sums on every process, in the bodies' common order).
    std::vector<double> all;
    for (const auto& l : sums) {
      all.insert(all.end(), l.force.data(), l.force.data() + Dim);
      all.insert(all.end(), l.torque.data(), l.torque.data() + l.torque.size());
    }
    if (!all.empty()) ranks->sum_in_place(all.data(), all.size());
    std::size_t at = 0;
    for (auto& l : sums) {
      for (int k = 0; k < Dim; ++k) l.force[k] = all[at++];
      for (Eigen::Index k = 0; k < l.torque.size(); ++k) l.torque[k] = all[at++];
    }
  }
  for (std::size_t b = 0; b < info_.size(); ++b) {
    const double scale = info_[b].scale;
    Vec3 f{0.0, 0.0, 0.0}, t{0.0, 0.0, 0.0};
    for (int k = 0; k < Dim; ++k) f[k] = scale * sums[b].force[k];
    if constexpr (Dim == 2)
      t[2] = scale * sums[b].torque[0];
    else
      for (int k = 0; k < 3; ++k) t[k] = scale * sums[b].torque[k];
    if (info_[b].id < 0) {  // a free sphere: its atom takes the load
      loads.atom_tags.push_back(-info_[b].id);
      loads.atom_force.push_back(f);
      loads.atom_torque.push_back(t);
      continue;
    }
    loads.body_ids.push_back(info_[b].id);
    loads.body_force.push_back(f);
    loads.body_torque.push_back(t);
  }
}

template <int Dim>
void ResolvedCoupling<Dim>::save(StageState& state) const {
  auto& bodies = state["bodies"];  // per body: id, particles, dem_volume, fluid_volume, scale,
  bodies.clear();                  // the 9 entries of the initial rotation, the centroid offset
  for (std::size_t b = 0; b < info_.size(); ++b) {
    const BodyInfo& i = info_[b];
    bodies.insert(bodies.end(),
                  {double(i.id), double(i.particles), i.dem_volume, i.fluid_volume, i.scale});
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) bodies.push_back(initial_rotation_[b](r, c));
    for (int a = 0; a < Dim; ++a) bodies.push_back(centroid_offset_[b][a]);
  }
  state["removed"] = {double(removed_)};
}

template <int Dim>
void ResolvedCoupling<Dim>::restore(const StageState& state) {
  constexpr std::size_t per_body = 5 + 9 + Dim;
  const auto bodies = state.find("bodies"), removed = state.find("removed");
  if (bodies == state.end() || removed == state.end() || removed->second.size() != 1 ||
      bodies->second.size() % per_body != 0)
    throw std::runtime_error("resolved coupling: the checkpoint holds no bodies of this dimension");
  const std::vector<double>& v = bodies->second;
  info_.clear();
  index_.clear();
  initial_rotation_.clear();
  centroid_offset_.clear();
  for (std::size_t at = 0; at < v.size(); at += per_body) {
    BodyInfo i;
    i.id = int(v[at]);
    i.particles = std::size_t(v[at + 1]);
    i.dem_volume = v[at + 2];
    i.fluid_volume = v[at + 3];
    i.scale = v[at + 4];
    index_[i.id] = int(info_.size());
    info_.push_back(i);
    Eigen::Matrix3d r;
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) r(row, c) = v[at + 5 + 3 * row + c];
    initial_rotation_.push_back(r);
    isph::Vec<Dim> offset;
    for (int a = 0; a < Dim; ++a) offset[a] = v[at + 14 + a];
    centroid_offset_.push_back(offset);
  }
  removed_ = std::size_t(removed->second[0]);
}

template class ResolvedCoupling<2>;
template class ResolvedCoupling<3>;

}  // namespace isphdem
