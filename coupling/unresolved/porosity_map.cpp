#include "unresolved/porosity_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace isphdem {

template <int Dim>
double Grain<Dim>::volume() const {
  return 4.0 / 3.0 * M_PI * radius * radius * radius;
}

template <int Dim>
PorosityMap<Dim>::PorosityMap(const PorosityMapSettings& s)
    : settings_(s),
      // A placeholder length lets the checks below give the porosity-map message, not the kernel's.
      kernel_(s.kernel, s.smoothing_length > 0.0 ? s.smoothing_length : 1.0),
      normalisation_(Dim == 2 ? s.slab_thickness : 1.0) {
  if (!(s.smoothing_length > 0.0))
    throw std::invalid_argument("porosity map: smoothing length must be > 0");
  if (!(s.min_porosity > 0.0 && s.min_porosity < 1.0))
    throw std::invalid_argument("porosity map: minimum porosity must be in (0, 1)");
  if (Dim == 2 && !(s.slab_thickness > 0.0))
    throw std::invalid_argument("porosity map: a 2D fluid needs the DEM slab thickness (> 0)");
  if (!(s.smoothing_diameters >= 0.0))
    throw std::invalid_argument("porosity map: smoothing in grain diameters must be >= 0");
}

template <int Dim>
double PorosityMap<Dim>::smoothing_length_of(double radius) const {
  return std::max(settings_.smoothing_length, settings_.smoothing_diameters * 2.0 * radius);
}

template <int Dim>
double PorosityMap<Dim>::support(const std::vector<Grain<Dim>>& grains) const {
  double h = settings_.smoothing_length;
  for (const auto& g : grains) h = std::max(h, smoothing_length_of(g.radius));
  return 2.0 * h;
}

namespace {

// Uniform grid of cell size >= the kernel support over the grains' bounding box: a fluid point
// only needs the 3^Dim cells around its own. The grid covers grains, not fluid, because grains
// are the smaller set and fluid points far from every grain must cost one rejection only.
template <int Dim>
struct GrainGrid {
  isph::Vec<Dim> origin;
  double cell = 0.0;
  Eigen::Matrix<std::int64_t, Dim, 1> dims;
  std::vector<std::size_t> start;  // per cell, into order; size cells + 1
  std::vector<std::size_t> order;  // grain indices sorted by cell, stable

  Eigen::Matrix<std::int64_t, Dim, 1> cell_of(const isph::Vec<Dim>& x) const {
    Eigen::Matrix<std::int64_t, Dim, 1> c;
    for (int d = 0; d < Dim; ++d)
      c[d] = static_cast<std::int64_t>(std::floor((x[d] - origin[d]) / cell));
    return c;
  }
  std::int64_t linear(const Eigen::Matrix<std::int64_t, Dim, 1>& c) const {
    std::int64_t i = 0;
    for (int d = Dim - 1; d >= 0; --d) i = i * dims[d] + c[d];
    return i;
  }
};

template <int Dim>
GrainGrid<Dim> build_grid(const std::vector<Grain<Dim>>& grains, double support) {
  GrainGrid<Dim> g;
  isph::Vec<Dim> lo = grains.front().x, hi = grains.front().x;
  for (const auto& k : grains) {
    lo = lo.cwiseMin(k.x);
    hi = hi.cwiseMax(k.x);
  }
  // A box much larger than the support with few grains would make a huge, empty grid: widen the
  // cells until the grid has at most a few cells per grain.
  g.cell = support;
  const double max_cells = 8.0 * static_cast<double>(grains.size()) + 64.0;
  while (true) {
    double cells = 1.0;
    for (int d = 0; d < Dim; ++d) cells *= std::floor((hi[d] - lo[d]) / g.cell) + 1.0;
    if (cells <= max_cells) break;
    g.cell *= 1.5;
  }
  g.origin = lo;
  for (int d = 0; d < Dim; ++d)
    g.dims[d] = static_cast<std::int64_t>(std::floor((hi[d] - lo[d]) / g.cell)) + 1;
  std::int64_t n = 1;
  for (int d = 0; d < Dim; ++d) n *= g.dims[d];
  std::vector<std::int64_t> cell_of_grain(grains.size());
  g.start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (std::size_t k = 0; k < grains.size(); ++k) {
    auto c = g.cell_of(grains[k].x);
    for (int d = 0; d < Dim; ++d) c[d] = std::min(std::max<std::int64_t>(c[d], 0), g.dims[d] - 1);
    cell_of_grain[k] = g.linear(c);
    ++g.start[static_cast<std::size_t>(cell_of_grain[k]) + 1];
  }
  for (std::size_t c = 1; c < g.start.size(); ++c) g.start[c] += g.start[c - 1];
  g.order.resize(grains.size());
  std::vector<std::size_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t k = 0; k < grains.size(); ++k)
    g.order[fill[static_cast<std::size_t>(cell_of_grain[k])]++] = k;
  return g;
}

}  // namespace

template <int Dim>
PorosityField<Dim> PorosityMap<Dim>::compute(const std::vector<isph::Vec<Dim>>& fluid_x,
                                             const std::vector<Grain<Dim>>& grains) const {
  using V = isph::Vec<Dim>;
  PorosityField<Dim> out;
  const std::size_t n = fluid_x.size();
  out.porosity.assign(n, 1.0);
  out.solid_velocity.assign(n, V::Zero());
  out.diameter.assign(n, 0.0);
  out.weights.offset.assign(n + 1, 0);
  if (grains.empty()) return out;

  // Each grain's own kernel; the common one (bit for bit as before) where it is not widened.
  std::vector<isph::Kernel<Dim>> own;
  std::vector<const isph::Kernel<Dim>*> kernel_of(grains.size(), &kernel_);
  if (settings_.smoothing_diameters > 0.0) {
    own.reserve(grains.size());
    for (std::size_t k = 0; k < grains.size(); ++k) {
      const double h = smoothing_length_of(grains[k].radius);
      if (h == settings_.smoothing_length) continue;
      own.emplace_back(settings_.kernel, h);
      kernel_of[k] = &own.back();
    }
  }
  const double support = this->support(grains);
  const GrainGrid<Dim> grid = build_grid(grains, support);
  for (std::size_t a = 0; a < n; ++a) {
    const V& xa = fluid_x[a];
    const auto ca = grid.cell_of(xa);
    Eigen::Matrix<std::int64_t, Dim, 1> lo, hi;
    bool outside = false;
    for (int d = 0; d < Dim; ++d) {
      lo[d] = std::max<std::int64_t>(ca[d] - 1, 0);
      hi[d] = std::min<std::int64_t>(ca[d] + 1, grid.dims[d] - 1);
      outside = outside || lo[d] > hi[d];
    }
    double solid = 0.0;
    // Surface sum relative to the first grain in range (GrainWeights::surface): it equals the
    // volume sum to the last bit when every grain has one size, so d_32 is then exactly that size.
    double surface = 0.0, r_first = 0.0;
    V vsum = V::Zero();
    if (!outside) {
      Eigen::Matrix<std::int64_t, Dim, 1> c = lo;
      while (true) {
        const auto cell = static_cast<std::size_t>(grid.linear(c));
        for (std::size_t i = grid.start[cell]; i < grid.start[cell + 1]; ++i) {
          const std::size_t k = grid.order[i];
          const double r = (xa - grains[k].x).norm();
          if (r >= support) continue;
          const double w = grains[k].volume() * kernel_of[k]->value(r);
          if (w <= 0.0) continue;
          if (r_first == 0.0) r_first = grains[k].radius;
          const double ws = w * (r_first / grains[k].radius);
          out.weights.grain.push_back(k);
          out.weights.weight.push_back(w);
          out.weights.surface.push_back(ws);
          solid += w;
          surface += ws;
          vsum += w * grains[k].v;
        }
        int d = 0;
        while (d < Dim && ++c[d] > hi[d]) {
          c[d] = lo[d];
          ++d;
        }
        if (d == Dim) break;
      }
    }
    out.weights.offset[a + 1] = out.weights.grain.size();
    if (solid > 0.0) {
      out.solid_velocity[a] = vsum / solid;
      out.diameter[a] = 2.0 * r_first * (solid / surface);
      const double eps = 1.0 - solid / normalisation_;
      if (eps < settings_.min_porosity) ++out.floored;
      out.porosity[a] = std::max(eps, settings_.min_porosity);
    }
  }
  return out;
}

template struct Grain<2>;
template struct Grain<3>;
template class PorosityMap<2>;
template class PorosityMap<3>;

}  // namespace isphdem
