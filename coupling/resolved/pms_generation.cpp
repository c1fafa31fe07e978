#include "resolved/pms_generation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "format_number.hpp"

namespace isphdem {

namespace {

struct Sphere {
  Vec3 c;
  double r;
};

std::string num(double v) { return isph::format_number(v); }

// A node this far (in spacings) outside every member still counts as inside the grain's filled
// outline: it closes the interstices of touching dx-wide spheres (0.077 dx outside the nearest
// in a hexagonal packing) without growing the outline by more than a small rim.
constexpr double kOutlineSlack = 0.15;

template <int Dim>
isph::Vec<Dim> in_plane(const Vec3& a) {
  isph::Vec<Dim> v;
  for (int k = 0; k < Dim; ++k) v[k] = a[k];
  return v;
}

// The members as the fluid sees them: spheres in 3D; in 2D the circles cut by the mid-plane of
// the slab (the body's centre plane), whose radius shrinks with a member's offset from it.
template <int Dim>
std::vector<Sphere> member_sections(const DemBody& body, const std::vector<DemAtom>& members) {
  std::vector<Sphere> s;
  for (const auto& a : members) {
    double r = a.radius;
    if (Dim == 2) {
      const double dz = a.x[2] - body.x[2];
      r = std::sqrt(std::max(a.radius * a.radius - dz * dz, 0.0));
    }
    if (r > 0.0) s.push_back({a.x, r});
  }
  return s;
}

// How far x lies inside the union of the spheres (negative outside); separations taken with
// the domain's minimum image (a default domain: none).
template <int Dim>
double depth_in(const std::vector<Sphere>& spheres, const isph::Vec<Dim>& x,
                const isph::Domain<Dim>& domain = {}) {
  double d = -std::numeric_limits<double>::max();
  for (const auto& s : spheres)
    d = std::max(d, s.r - domain.min_image(x - in_plane<Dim>(s.c)).norm());
  return d;
}

// The shape a body gets: `auto` is per_sphere when every member's section is at most 1.5 dx wide.
PmsShape decided_shape(const std::vector<Sphere>& sections, PmsShape shape, double dx) {
  if (shape != PmsShape::Auto) return shape;
  double max_diameter = 0.0;
  for (const auto& s : sections) max_diameter = std::max(max_diameter, 2.0 * s.r);
  return max_diameter <= 1.5 * dx ? PmsShape::PerSphere : PmsShape::Lattice;
}

}  // namespace

PmsShape pms_shape_from_name(const std::string& name) {
  if (name == "auto") return PmsShape::Auto;
  if (name == "lattice") return PmsShape::Lattice;
  if (name == "per_sphere") return PmsShape::PerSphere;
  if (name == "outline") return PmsShape::Outline;
  throw std::invalid_argument("unknown PMS shape '" + name +
                              "': use \"auto\", \"lattice\", \"outline\" or \"per_sphere\"");
}

template <int Dim>
double pms_volume(std::size_t n, const PmsGenerationSettings& settings) {
  return static_cast<double>(n) * std::pow(settings.spacing, Dim) *
         (Dim == 2 ? settings.slab_thickness : 1.0);
}

template <int Dim>
std::vector<isph::Vec<Dim>> generate_pms_particles(const DemBody& body,
                                                   const std::vector<DemAtom>& members,
                                                   const PmsGenerationSettings& settings,
                                                   const isph::Vec<Dim>& origin) {
  using V = isph::Vec<Dim>;
  const double dx = settings.spacing;
  const std::string who = "resolved coupling: multisphere body " + std::to_string(body.id);
  if (!(dx > 0.0)) throw std::invalid_argument(who + ": the particle spacing must be positive");
  if (Dim == 2 && !(settings.slab_thickness > 0.0))
    throw std::invalid_argument(who +
                                ": a 2D fluid needs the slab thickness of the quasi-2D DEM "
                                "(coupling.slab_thickness, DESIGN.md decision 4)");
  if (members.empty()) throw std::invalid_argument(who + " has no member spheres in the DEM state");
  const std::vector<Sphere> spheres = member_sections<Dim>(body, members);
  if (spheres.empty())
    throw std::invalid_argument(who +
                                ": no member sphere cuts the slab mid-plane; put the clump in "
                                "the plane (fix couple/isph planar z Z0)");
  const V cm = in_plane<Dim>(body.x);

  const PmsShape shape = decided_shape(spheres, settings.shape, dx);
  if (shape == PmsShape::PerSphere) {
    std::vector<V> x;
    for (const auto& s : spheres) x.push_back(in_plane<Dim>(s.c));
    return x;
  }

  if (!(body.volume > 0.0))
    throw std::invalid_argument(who + " has volume " + num(body.volume) +
                                ": give the particle template a volume (LIGGGHTS "
                                "particletemplate/multisphere ... use_volume)");
  const double target = body.volume / pms_volume<Dim>(1, settings);
  const std::size_t n = static_cast<std::size_t>(std::llround(target));
  if (n < 1 && shape != PmsShape::Outline)
    throw std::invalid_argument(
        who + " (volume " + num(body.volume) + " m^3) holds " + num(target) +
        " particles at spacing " + num(dx) +
        ": refine particles.spacing, or use coupling.pms_shape = \"per_sphere\" or the unresolved "
        "coupling for grains this small");

  // Candidate nodes: the members' bounding box, widened until it holds clearly more than n nodes
  // (a thin slab dilates the section beyond the spheres).
  V lo = V::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& s : spheres) {
    const V c = in_plane<Dim>(s.c);
    lo = lo.cwiseMin(c - V::Constant(s.r));
    hi = hi.cwiseMax(c + V::Constant(s.r));
  }
  struct Node {
    V x;
    double depth;
  };
  std::vector<Node> nodes;
  for (double margin = 2.0 * dx;; margin *= 2.0) {
    nodes.clear();
    Eigen::Matrix<long, Dim, 1> k0, k1;
    for (int a = 0; a < Dim; ++a) {
      k0[a] = static_cast<long>(std::floor((lo[a] - margin - origin[a]) / dx));
      k1[a] = static_cast<long>(std::ceil((hi[a] + margin - origin[a]) / dx));
    }
    Eigen::Matrix<long, Dim, 1> k = k0;
    while (true) {
      V x;
      for (int a = 0; a < Dim; ++a) x[a] = origin[a] + static_cast<double>(k[a]) * dx;
      nodes.push_back({x, depth_in<Dim>(spheres, x)});
      int a = 0;
      while (a < Dim && ++k[a] > k1[a]) {
        k[a] = k0[a];
        ++a;
      }
      if (a == Dim) break;
    }
    if (nodes.size() >= 2 * n) break;
  }
  std::sort(nodes.begin(), nodes.end(),
            [](const Node& a, const Node& b) { return a.depth > b.depth; });

  if (shape == PmsShape::Outline) {
    std::vector<V> out;
    for (const auto& node : nodes)
      if (node.depth >= -kOutlineSlack * dx) out.push_back(node.x);
    if (out.empty())
      throw std::invalid_argument(who +
                                  ": no lattice node lies inside its spheres; refine "
                                  "particles.spacing or use coupling.pms_shape = \"lattice\"");
    return out;
  }

  // The nodes clearly inside the level set that holds n nodes are kept; the rest are chosen
  // among the nodes within a band of +-0.35 dx around it (the lattice makes that boundary ragged
  // by half a spacing anyway), each time the one that brings the particles' centroid closest
  // to the centre of mass.
  const double cut = nodes[n - 1].depth, band = 0.35 * dx;
  std::vector<V> out;
  V sum = V::Zero();
  std::vector<std::size_t> pool;
  for (std::size_t j = 0; j < nodes.size() && nodes[j].depth >= cut - band; ++j) {
    if (nodes[j].depth > cut + band) {
      out.push_back(nodes[j].x);
      sum += nodes[j].x - cm;
    } else {
      pool.push_back(j);
    }
  }
  std::vector<uint8_t> used(pool.size(), 0);
  for (std::size_t picked = out.size(); picked < n; ++picked) {
    std::size_t best = 0;
    double best_norm = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < pool.size(); ++j) {
      if (used[j]) continue;
      const double m = (sum + nodes[pool[j]].x - cm).norm();
      if (m < best_norm - 1e-12 * dx) {
        best_norm = m;
        best = j;
      }
    }
    used[best] = 1;
    sum += nodes[pool[best]].x - cm;
  }
  // Greedy picks can leave a residual the last few nodes could not cancel: swap a kept band node
  // for a free one while that brings the centroid closer.
  // Half a spacing is the lattice's resolution of the sum (centroid within dx / 2N).
  for (int pass = 0; pass < 50 && sum.norm() > 0.5 * dx; ++pass) {
    double best_norm = sum.norm() - 1e-6 * dx;
    std::size_t bi = pool.size(), bj = pool.size();
    for (std::size_t i = 0; i < pool.size(); ++i) {
      if (!used[i]) continue;
      for (std::size_t j = 0; j < pool.size(); ++j) {
        if (used[j]) continue;
        const double m = (sum - nodes[pool[i]].x + nodes[pool[j]].x).norm();
        if (m < best_norm) {
          best_norm = m;
          bi = i;
          bj = j;
        }
      }
    }
    if (bi == pool.size()) break;
    used[bi] = 0;
    used[bj] = 1;
    sum += nodes[pool[bj]].x - nodes[pool[bi]].x;
  }
  for (std::size_t j = 0; j < pool.size(); ++j)
    if (used[j]) out.push_back(nodes[pool[j]].x);
  return out;
}

namespace {

// The depth level whose set {depth_in >= level} holds `target` (area in 2D, volume in 3D),
// counted on a grid of dx/8 (2D) or dx/4 (3D) cells over the members' box.
template <int Dim>
double volume_level(const std::vector<Sphere>& spheres, double target, double dx) {
  using V = isph::Vec<Dim>;
  const double cell = dx / (Dim == 2 ? 8.0 : 4.0);
  V lo = V::Constant(std::numeric_limits<double>::max()), hi = -lo;
  double r_max = 0.0;
  for (const auto& s : spheres) {
    lo = lo.cwiseMin(in_plane<Dim>(s.c) - V::Constant(s.r));
    hi = hi.cwiseMax(in_plane<Dim>(s.c) + V::Constant(s.r));
    r_max = std::max(r_max, s.r);
  }
  const std::size_t n = static_cast<std::size_t>(std::llround(target / std::pow(cell, Dim)));
  if (n == 0) return 0.0;
  std::vector<double> depth;
  // Widened until the box holds twice the target: a thin slab dilates the section beyond it.
  for (double margin = r_max; depth.size() < 2 * n; margin *= 2.0) {
    depth.clear();
    Eigen::Matrix<long, Dim, 1> count;
    for (int a = 0; a < Dim; ++a)
      count[a] = static_cast<long>(std::ceil((hi[a] - lo[a] + 2.0 * margin) / cell));
    Eigen::Matrix<long, Dim, 1> k = Eigen::Matrix<long, Dim, 1>::Zero();
    while (true) {
      V p;
      for (int a = 0; a < Dim; ++a)
        p[a] = lo[a] - margin + (static_cast<double>(k[a]) + 0.5) * cell;
      depth.push_back(depth_in<Dim>(spheres, p));
      int a = 0;
      while (a < Dim && ++k[a] >= count[a]) {
        k[a] = 0;
        ++a;
      }
      if (a == Dim) break;
    }
  }
  std::nth_element(depth.begin(), depth.begin() + (n - 1), depth.end(), std::greater<double>());
  return depth[n - 1];
}

}  // namespace

template <int Dim>
std::vector<PmsSurfacePoint<Dim>> pms_surface_from_spheres(const DemBody& body,
                                                           const std::vector<DemAtom>& members,
                                                           const PmsGenerationSettings& settings,
                                                           const isph::Domain<Dim>& domain,
                                                           const std::vector<isph::Vec<Dim>>& x) {
  using V = isph::Vec<Dim>;
  const std::vector<Sphere> spheres = member_sections<Dim>(body, members);
  double level = 0.0;
  if (settings.shape != PmsShape::Outline && body.volume > 0.0)
    level = volume_level<Dim>(spheres, body.volume / (Dim == 2 ? settings.slab_thickness : 1.0),
                              settings.spacing);
  std::vector<PmsSurfacePoint<Dim>> out(x.size());
  // Particles at the members' centres are off the lattice and stand for the spheres themselves:
  // no surface point (the lattice's estimate stays).
  if (decided_shape(spheres, settings.shape, settings.spacing) == PmsShape::PerSphere) return out;
  for (std::size_t i = 0; i < x.size(); ++i) {
    double nearest = std::numeric_limits<double>::max();
    for (const auto& s : spheres) {
      const double radius = s.r - level;
      if (radius <= 0.0) continue;
      const V r = domain.min_image(x[i] - in_plane<Dim>(s.c));
      const double dist = r.norm();
      if (dist == 0.0) continue;
      const V n = r / dist;
      // The point of this member's surface on the radius through x; covered by another member,
      // it is not the body's surface.
      const V surface = in_plane<Dim>(s.c) + radius * n;
      if (depth_in<Dim>(spheres, surface, domain) > level + 1e-9 * radius) continue;
      const double depth = radius - dist;
      if (std::abs(depth) < nearest) {
        nearest = std::abs(depth);
        out[i] = {depth, n, true};
      }
    }
  }
  return out;
}

template <int Dim>
std::size_t remove_shared_pms_nodes(std::vector<std::vector<isph::Vec<Dim>>>& particles,
                                    const std::vector<DemBody>& bodies,
                                    const std::vector<std::vector<DemAtom>>& members,
                                    const isph::Domain<Dim>& domain, double spacing) {
  using V = isph::Vec<Dim>;
  struct Ref {
    std::size_t body, k;
  };
  // Cells of half a spacing: a close pair lies in the same or a neighbouring cell.
  const double cell = 0.5 * spacing;
  auto key = [&](const V& x) {
    std::array<long, 3> c{0, 0, 0};
    for (int a = 0; a < Dim; ++a)
      c[a] = static_cast<long>(std::floor((x[a] - domain.lo[a]) / cell));
    return c;
  };
  std::map<std::array<long, 3>, std::vector<Ref>> grid;
  for (std::size_t b = 0; b < particles.size(); ++b)
    for (std::size_t k = 0; k < particles[b].size(); ++k)
      grid[key(particles[b][k])].push_back({b, k});
  std::vector<std::vector<Sphere>> sections;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    sections.push_back(member_sections<Dim>(bodies[b], members[b]));
  std::vector<std::vector<uint8_t>> drop(particles.size());
  std::vector<std::size_t> left(particles.size());
  for (std::size_t b = 0; b < particles.size(); ++b) {
    drop[b].assign(particles[b].size(), 0);
    left[b] = particles[b].size();
  }
  const double limit2 = cell * cell;
  std::size_t removed = 0;
  for (const auto& [c, refs] : grid) {
    for (const Ref& r : refs) {
      if (drop[r.body][r.k]) continue;
      const V& x = particles[r.body][r.k];
      const long span = Dim == 3 ? 1 : 0;
      for (long i = -1; i <= 1; ++i)
        for (long j = -1; j <= 1; ++j)
          for (long l = -span; l <= span; ++l) {
            const auto it = grid.find({c[0] + i, c[1] + j, c[2] + l});
            if (it == grid.end()) continue;
            for (const Ref& o : it->second) {
              if (o.body == r.body || drop[o.body][o.k] || drop[r.body][r.k]) continue;
              const V& y = particles[o.body][o.k];
              if (domain.min_image(x - y).squaredNorm() >= limit2) continue;
              // Keep the deeper one, unless that would empty the other body.
              bool drop_r = depth_in<Dim>(sections[r.body], x, domain) <
                            depth_in<Dim>(sections[o.body], y, domain);
              if (drop_r && left[r.body] == 1) drop_r = false;
              if (!drop_r && left[o.body] == 1) continue;
              const Ref& gone = drop_r ? r : o;
              drop[gone.body][gone.k] = 1;
              --left[gone.body];
              ++removed;
            }
          }
    }
  }
  for (std::size_t b = 0; b < particles.size(); ++b) {
    std::vector<V> kept;
    for (std::size_t k = 0; k < particles[b].size(); ++k)
      if (!drop[b][k]) kept.push_back(particles[b][k]);
    particles[b] = std::move(kept);
  }
  return removed;
}

template std::size_t remove_shared_pms_nodes<2>(std::vector<std::vector<isph::Vec<2>>>&,
                                                const std::vector<DemBody>&,
                                                const std::vector<std::vector<DemAtom>>&,
                                                const isph::Domain<2>&, double);
template std::size_t remove_shared_pms_nodes<3>(std::vector<std::vector<isph::Vec<3>>>&,
                                                const std::vector<DemBody>&,
                                                const std::vector<std::vector<DemAtom>>&,
                                                const isph::Domain<3>&, double);
template double pms_volume<2>(std::size_t, const PmsGenerationSettings&);
template double pms_volume<3>(std::size_t, const PmsGenerationSettings&);
template std::vector<isph::Vec<2>> generate_pms_particles<2>(const DemBody&,
                                                             const std::vector<DemAtom>&,
                                                             const PmsGenerationSettings&,
                                                             const isph::Vec<2>&);
template std::vector<isph::Vec<3>> generate_pms_particles<3>(const DemBody&,
                                                             const std::vector<DemAtom>&,
                                                             const PmsGenerationSettings&,
                                                             const isph::Vec<3>&);
template std::vector<PmsSurfacePoint<2>> pms_surface_from_spheres<2>(
    const DemBody&, const std::vector<DemAtom>&, const PmsGenerationSettings&,
    const isph::Domain<2>&, const std::vector<isph::Vec<2>>&);
template std::vector<PmsSurfacePoint<3>> pms_surface_from_spheres<3>(
    const DemBody&, const std::vector<DemAtom>&, const PmsGenerationSettings&,
    const isph::Domain<3>&, const std::vector<isph::Vec<3>>&);

}  // namespace isphdem
