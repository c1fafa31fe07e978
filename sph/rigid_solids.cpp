#include "rigid_solids.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
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

namespace {

// Depth below the body surface and outward normal of each particle of one body, from the
// particle set itself: the surface lies half a spacing beyond the outermost particles, as a
// wall's surface lies half a spacing beyond its first layer. The nearest lattice node not taken
// by the body (searched up to kReach spacings) gives the depth; the directions to all nodes at
// that distance give the normal (a staircase corner gets the diagonal). Particles with no free
// node within kReach have no fluid within a kernel support: depth kReach dx, normal zero.
constexpr int kReach = 3;

template <int Dim>
void surface_geometry(const std::vector<Vec<Dim>>& x, double dx, std::vector<double>& depth,
                      std::vector<Vec<Dim>>& normal) {
  using Key = std::array<long, Dim>;
  auto key = [&](const Vec<Dim>& y) {
    Key k;
    for (int a = 0; a < Dim; ++a) k[a] = std::lround((y[a] - x.front()[a]) / dx);
    return k;
  };
  std::set<Key> taken;
  for (const auto& y : x) taken.insert(key(y));
  // Lattice offsets within kReach spacings, nearest first.
  struct Offset {
    Key key;
    Vec<Dim> d;  // in spacings
    double length;
  };
  std::vector<Offset> offsets;
  Key o;
  o.fill(-kReach);
  while (true) {
    Offset off{o, Vec<Dim>::Zero(), 0.0};
    for (int a = 0; a < Dim; ++a) off.d[a] = static_cast<double>(o[a]);
    off.length = off.d.norm();
    if (off.length > 0.0 && off.length <= kReach) offsets.push_back(off);
    int a = 0;
    while (a < Dim && o[a] == kReach) o[a++] = -kReach;
    if (a == Dim) break;
    ++o[a];
  }
  std::stable_sort(offsets.begin(), offsets.end(),
                   [](const Offset& p, const Offset& q) { return p.length < q.length; });
  depth.assign(x.size(), kReach * dx);
  normal.assign(x.size(), Vec<Dim>::Zero());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Key k = key(x[i]);
    double nearest = -1.0;
    Vec<Dim> n = Vec<Dim>::Zero();
    for (const auto& off : offsets) {
      if (nearest >= 0.0 && off.length > nearest + 1e-9) break;
      Key q;
      for (int a = 0; a < Dim; ++a) q[a] = k[a] + off.key[a];
      if (taken.count(q)) continue;
      nearest = off.length;
      n += off.d / off.length;
    }
    if (nearest < 0.0) continue;
    depth[i] = (nearest - 0.5) * dx;
    if (n.squaredNorm() > 0.0) normal[i] = n.normalized();
  }
}

}  // namespace

template <int Dim>
void add_rigid_body(Particles<Dim>& particles, int body, const std::vector<Vec<Dim>>& x,
                    const RigidPose<Dim>& pose) {
  if (body < 0) throw std::invalid_argument("rigid body index must not be negative");
  if (x.empty()) return;
  std::vector<double> depth;
  std::vector<Vec<Dim>> outward;
  surface_geometry(x, particles.spacing, depth, outward);
  // Every particle's arrays are set through back(): add() must store each one.
  if (particles.keep_parts > 1)
    throw std::logic_error("add_rigid_body: the particles keep only a share (keep_parts)");
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec<Dim> r = x[k] - pose.x;
    particles.add(x[k], pose.v + rigid_velocity<Dim>(pose.omega, r), kSolid);
    particles.body.back() = body;
    particles.body_offset.back() = pose.rotation.transpose() * r;
    particles.body_normal.back() = pose.rotation.transpose() * outward[k];
    particles.normal.back() = outward[k];
    particles.wall_distance.back() = depth[k];
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
    particles.normal[i] = q.rotation * particles.body_normal[i];
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
Vec<Dim> pms_force(const Particles<Dim>& P, const Neighbors<Dim>& nb, const Operators<Dim>& op,
                   int i, double rho0, double dt, const Vec<Dim>& u_star, const Vec<Dim>& gravity) {
  if (P.surface[i] == kDrySolid) return Vec<Dim>::Zero();
  Vec<Dim> grad_p = Vec<Dim>::Zero();
  if (!P.surface[i]) {
    grad_p = gradient(nb, op, P.p, i);
  } else {
    // Kernel-corrected gradient (exact for linear fields) over the wet neighbours only.
    Mat<Dim> L = Mat<Dim>::Zero();
    Vec<Dim> s = Vec<Dim>::Zero();
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] == kSolid && P.surface[j] == kDrySolid) continue;
      L.noalias() -= P.volume * nb.rij[k] * nb.dw[k].transpose();
      s += P.volume * (P.p[j] - P.p[i]) * nb.dw[k];
    }
    Eigen::FullPivLU<Mat<Dim>> lu(L);
    grad_p = lu.isInvertible() && lu.rcond() > 0.05 ? Vec<Dim>(lu.inverse().transpose() * s)
                                                    : gradient(nb, op, P.p, i);
  }
  return rho0 * P.volume * ((u_star - P.v[i]) / dt - gravity) - P.volume * grad_p;
}

template <int Dim>
void mark_dry_solids(Particles<Dim>& particles, const Neighbors<Dim>& nb, const Vec<Dim>& gravity,
                     const RowShare* share) {
  auto& P = particles;
  const int n = static_cast<int>(P.size());
  const int first = share ? share->first(n) : 0, last = share ? share->last(n) : n;
  if (gravity.squaredNorm() == 0.0) return;
  int nbodies = 0;
  for (int i = 0; i < n; ++i)
    if (P.kind[i] == kSolid) nbodies = std::max(nbodies, P.body[i] + 1);
  // Called only where some process holds solids (IsphSolver::has_solids): a process without
  // any still takes part in the exchanges below.
  const Vec<Dim> up = -gravity.normalized();
  // Fluid within one support of a body, then free-surface fluid within one support of those.
  std::vector<int> near(n, -1);
  for (int i = first; i < last; ++i) {
    if (P.kind[i] == kSolid || P.kind[i] == kWall) continue;
    for (int k = nb.begin(i); k < nb.end(i) && near[i] < 0; ++k)
      if (P.kind[nb.index[k]] == kSolid) near[i] = P.body[nb.index[k]];
  }
  if (share) share->exchange(near);
  // Positions rather than rows: decomposed, a point's row exists on its own process only.
  struct Point {
    int body;
    Vec<Dim> x;
  };
  std::vector<Point> points;  // in row order
  for (int i = first; i < last; ++i) {
    if (!P.surface[i] || P.kind[i] == kSolid || P.kind[i] == kWall) continue;
    int b = near[i];
    for (int k = nb.begin(i); k < nb.end(i) && b < 0; ++k) b = near[nb.index[k]];
    if (b >= 0) points.push_back({b, P.x[i]});
  }
  if (share) points = share->concatenate(points);
  for (const auto& q : points) nbodies = std::max(nbodies, q.body + 1);
  std::vector<std::vector<Vec<Dim>>> line(nbodies);
  for (const auto& q : points) line[q.body].push_back(q.x);
  // Height of the waterline of body b below/above x: h = a + c s (s horizontal, 2D) or h = a.
  std::vector<double> a(nbodies, 0.0), c(nbodies, 0.0);
  std::vector<Vec<Dim>> origin(nbodies, Vec<Dim>::Zero());
  Vec<Dim> side = Vec<Dim>::Zero();
  if constexpr (Dim == 2) side = Vec<2>(up[1], -up[0]);
  for (int b = 0; b < nbodies; ++b) {
    const auto& L = line[b];
    if (L.empty()) continue;
    Vec<Dim> mean = Vec<Dim>::Zero();
    for (const auto& x : L) mean += x / static_cast<double>(L.size());
    origin[b] = mean;
    a[b] = up.dot(mean);
    if (Dim != 2) continue;
    double sss = 0.0, ssh = 0.0;
    for (const auto& x : L) {
      const double ds = side.dot(x - mean), dh = up.dot(x - mean);
      sss += ds * ds;
      ssh += ds * dh;
    }
    // A slope only from points spread across the body (both sides of it), not from one side.
    if (sss > L.size() * 4.0 * P.spacing * P.spacing) c[b] = ssh / sss;
  }
  const double half = 0.5 * P.spacing;
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] != kSolid) continue;
    const int b = P.body[i];
    if (line[b].empty()) continue;
    const double h = up.dot(P.x[i]) - (a[b] + c[b] * side.dot(P.x[i] - origin[b]));
    if (h > half)
      P.surface[i] = kDrySolid;
    else if (h > -half)
      P.surface[i] = 1;
  }
  // Fluid at the waterline beside a body counted the dry part as kernel support and escaped the
  // free-surface test; as an interior row next to p = 0 it took -600 Pa of suction when the body
  // rose, and blew up. It is free surface where it has dry neighbours and is not below the line.
  // (The solids above are marked in every row, so that these rows read their neighbours' marks.)
  for (int i = first; i < last; ++i) {
    if (P.kind[i] == kSolid || P.kind[i] == kWall || P.surface[i]) continue;
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] != kSolid || P.surface[j] != kDrySolid) continue;
      const int b = P.body[j];
      const double h = up.dot(P.x[i]) - (a[b] + c[b] * side.dot(P.x[i] - origin[b]));
      if (h > -half) P.surface[i] = 1;
      break;
    }
  }
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
template Vec<2> pms_force<2>(const Particles<2>&, const Neighbors<2>&, const Operators<2>&, int,
                             double, double, const Vec<2>&, const Vec<2>&);
template Vec<3> pms_force<3>(const Particles<3>&, const Neighbors<3>&, const Operators<3>&, int,
                             double, double, const Vec<3>&, const Vec<3>&);
template void mark_dry_solids<2>(Particles<2>&, const Neighbors<2>&, const Vec<2>&,
                                 const RowShare*);
template void mark_dry_solids<3>(Particles<3>&, const Neighbors<3>&, const Vec<3>&,
                                 const RowShare*);
template void erase_particles<2>(Particles<2>&, const std::vector<uint8_t>&);
template void erase_particles<3>(Particles<3>&, const std::vector<uint8_t>&);

}  // namespace isph
