#include "surface_remesh.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>

namespace isph {

template <int Dim>
double highest_fluid(const Particles<Dim>& particles, const Vec<Dim>& up) {
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.kind[i] == kFluid) top = std::max(top, up.dot(particles.x[i]));
  return top;
}

namespace {

// The tangential positions of the fluid particles within half a spacing of `top`.
template <int Dim>
std::vector<Vec<Dim>> columns_under(const Particles<Dim>& P, const Vec<Dim>& up, double top) {
  std::vector<Vec<Dim>> columns;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == kFluid && up.dot(P.x[i]) > top - 0.5 * P.spacing)
      columns.push_back(P.x[i] - up.dot(P.x[i]) * up);
  return columns;
}

// What the remesh reads and writes of a fluid particle, gathered over processes.
template <int Dim>
struct FluidRecord {
  int64_t id;
  Vec<Dim> x, v;
  double p, porosity;
};

}  // namespace

template <int Dim>
std::vector<Vec<Dim>> surface_columns(const Particles<Dim>& particles, const Vec<Dim>& up) {
  return columns_under(particles, up, highest_fluid(particles, up));
}

template <int Dim>
double remesh_surface_rows(Particles<Dim>& particles, const Kernel<Dim>& kernel, const Vec<Dim>& up,
                           const std::vector<Vec<Dim>>& columns, int rows) {
  auto& P = particles;
  const double dx = P.spacing;
  const std::size_t nc = columns.size();
  std::vector<int> fluid;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == kFluid) fluid.push_back(static_cast<int>(i));
  const std::size_t m = std::min(fluid.size(), nc * static_cast<std::size_t>(rows));
  auto height = [&](int i) { return up.dot(P.x[i]); };
  std::partial_sort(fluid.begin(), fluid.begin() + m, fluid.end(),
                    [&](int a, int b) { return height(a) > height(b); });
  double mean = 0.0;
  for (std::size_t k = 0; k < m; ++k) mean += height(fluid[k]);
  mean /= static_cast<double>(m);
  const double top = mean + 0.5 * (rows - 1) * dx;

  // The fluid's values before the move, from the particles within reach of the zone.
  const double reach = top - rows * dx - kernel.support();
  std::vector<int> source;
  for (int i : fluid)
    if (height(i) > reach) source.push_back(i);
  std::vector<Vec<Dim>> x0(source.size()), v0(source.size());
  std::vector<double> p0(source.size()), phi0(source.size());
  for (std::size_t k = 0; k < source.size(); ++k) {
    x0[k] = P.x[source[k]];
    v0[k] = P.v[source[k]];
    p0[k] = P.p[source[k]];
    phi0[k] = P.porosity[source[k]];
  }

  // Row by row (highest particles to the top row), each particle to a column in the order of the
  // columns' tangential coordinates, so that particles move as little as the order allows.
  std::vector<int> order(nc);
  std::iota(order.begin(), order.end(), 0);
  auto key = [](const Vec<Dim>& a, const Vec<Dim>& b) {
    for (int d = 0; d < Dim; ++d)
      if (a[d] != b[d]) return a[d] < b[d];
    return false;
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(columns[a], columns[b]); });
  for (int r = 0; r < rows && static_cast<std::size_t>(r) * nc < m; ++r) {
    const auto first = fluid.begin() + r * nc;
    const auto last = fluid.begin() + std::min(m, (r + 1) * nc);
    std::sort(first, last,
              [&](int a, int b) { return key(P.x[a] - height(a) * up, P.x[b] - height(b) * up); });
    for (auto it = first; it != last; ++it) {
      const int i = *it;
      P.x[i] = columns[order[it - first]] + (top - r * dx) * up;
      double ws = 0.0, p = 0.0, phi = 0.0;
      Vec<Dim> v = Vec<Dim>::Zero();
      for (std::size_t k = 0; k < source.size(); ++k) {
        const double d = (P.x[i] - x0[k]).norm();
        if (d >= kernel.support()) continue;
        const double w = kernel.value(d);
        ws += w;
        v += w * v0[k];
        p += w * p0[k];
        phi += w * phi0[k];
      }
      if (ws > 0.0) {
        P.v[i] = v / ws;
        P.p[i] = p / ws;
        P.porosity[i] = phi / ws;
      }
    }
  }
  return top;
}

template <int Dim>
std::vector<Vec<Dim>> surface_columns_shared(const Particles<Dim>& particles, const Vec<Dim>& up,
                                             const RowShare& share) {
  return share.concatenate(columns_under(particles, up, share.max(highest_fluid(particles, up))));
}

template <int Dim>
double remesh_surface_rows_shared(Particles<Dim>& particles, const Kernel<Dim>& kernel,
                                  const Vec<Dim>& up, const std::vector<Vec<Dim>>& columns,
                                  int rows, const RowShare& share) {
  auto& P = particles;
  const double dx = P.spacing;
  const double top = share.max(highest_fluid(P, up));
  double fluid_here = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) fluid_here += P.kind[i] == kFluid;
  const double fluid_total = share.sum(fluid_here);
  const std::size_t m = std::min<std::size_t>(static_cast<std::size_t>(fluid_total),
                                              columns.size() * static_cast<std::size_t>(rows));
  // Gather the fluid above `floor`, deeper until it holds the m highest particles and every
  // particle the remeshed rows interpolate from (those above the new rows' reach).
  double depth = (rows + 4) * dx + 2.0 * kernel.support();
  std::vector<FluidRecord<Dim>> all;
  double floor = top;
  for (;;) {
    floor = top - depth;
    std::vector<FluidRecord<Dim>> mine;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == kFluid && up.dot(P.x[i]) > floor)
        mine.push_back({P.id[i], P.x[i], P.v[i], P.p[i], P.porosity[i]});
    all = share.concatenate(mine);
    if (all.size() >= static_cast<std::size_t>(fluid_total)) break;  // every fluid particle
    if (all.size() >= m) {
      std::vector<double> h(all.size());
      for (std::size_t k = 0; k < all.size(); ++k) h[k] = up.dot(all[k].x);
      std::nth_element(h.begin(), h.begin() + (m - 1), h.end(), std::greater<double>());
      double mean = 0.0;
      for (std::size_t k = 0; k < m; ++k) mean += h[k];
      mean /= static_cast<double>(m);
      const double reach = mean + 0.5 * (rows - 1) * dx - rows * dx - kernel.support();
      if (reach > floor) break;
    }
    depth *= 2.0;
  }
  // Every process the same particles in the same order, whatever the decomposition.
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  Particles<Dim> gathered;
  gathered.spacing = dx;
  for (const auto& r : all) {
    gathered.x.push_back(r.x);
    gathered.v.push_back(r.v);
    gathered.p.push_back(r.p);
    gathered.porosity.push_back(r.porosity);
    gathered.kind.push_back(kFluid);
    gathered.id.push_back(r.id);
  }
  const double new_top = remesh_surface_rows(gathered, kernel, up, columns, rows);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != kFluid || !(up.dot(P.x[i]) > floor)) continue;
    const auto it = std::lower_bound(gathered.id.begin(), gathered.id.end(), P.id[i]);
    const std::size_t k = static_cast<std::size_t>(it - gathered.id.begin());
    P.x[i] = gathered.x[k];
    P.v[i] = gathered.v[k];
    P.p[i] = gathered.p[k];
    P.porosity[i] = gathered.porosity[k];
  }
  return new_top;
}

template double highest_fluid<2>(const Particles<2>&, const Vec<2>&);
template double highest_fluid<3>(const Particles<3>&, const Vec<3>&);
template std::vector<Vec<2>> surface_columns<2>(const Particles<2>&, const Vec<2>&);
template std::vector<Vec<3>> surface_columns<3>(const Particles<3>&, const Vec<3>&);
template double remesh_surface_rows<2>(Particles<2>&, const Kernel<2>&, const Vec<2>&,
                                       const std::vector<Vec<2>>&, int);
template double remesh_surface_rows<3>(Particles<3>&, const Kernel<3>&, const Vec<3>&,
                                       const std::vector<Vec<3>>&, int);

template double remesh_surface_rows_shared<2>(Particles<2>&, const Kernel<2>&, const Vec<2>&,
                                              const std::vector<Vec<2>>&, int, const RowShare&);
template double remesh_surface_rows_shared<3>(Particles<3>&, const Kernel<3>&, const Vec<3>&,
                                              const std::vector<Vec<3>>&, int, const RowShare&);
template std::vector<Vec<2>> surface_columns_shared<2>(const Particles<2>&, const Vec<2>&,
                                                       const RowShare&);
template std::vector<Vec<3>> surface_columns_shared<3>(const Particles<3>&, const Vec<3>&,
                                                       const RowShare&);

}  // namespace isph
