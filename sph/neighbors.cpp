#include "neighbors.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace isph {

template <int Dim>
NeighborSearch<Dim>::NeighborSearch(const Domain<Dim>& domain, double cutoff)
    : domain_(domain), cutoff_(cutoff) {
  if (!(cutoff > 0.0)) throw std::invalid_argument("neighbour cutoff must be positive");
  for (int a = 0; a < Dim; ++a) {
    if (!domain.periodic[a]) continue;
    // The 3^Dim stencil must not visit the same periodic cell twice.
    if (domain.length()[a] < 3.0 * cutoff)
      throw std::invalid_argument("periodic length along axis " + std::to_string(a) + " (" +
                                  std::to_string(domain.length()[a]) +
                                  " m) must be at least 3 kernel supports (" +
                                  std::to_string(3.0 * cutoff) + " m): enlarge the domain");
  }
}

template <int Dim>
void NeighborSearch<Dim>::make_grid(const Particles<Dim>& particles) {
  const std::size_t n = particles.size();
  Vec<Dim> lo = Vec<Dim>::Constant(1e300), hi = Vec<Dim>::Constant(-1e300);
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(particles.x[i]);
    hi = hi.cwiseMax(particles.x[i]);
  }
  long total = 1;
  for (int a = 0; a < Dim; ++a) {
    if (domain_.periodic[a]) {
      origin_[a] = domain_.lo[a];
      ncell_[a] = static_cast<int>(std::floor(domain_.length()[a] / cutoff_));
      cell_size_[a] = domain_.length()[a] / ncell_[a];
    } else {
      if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]))
        throw std::runtime_error("non-finite particle position in neighbour search");
      origin_[a] = lo[a];
      ncell_[a] = std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / cutoff_)) + 1);
      cell_size_[a] = cutoff_;
    }
    total *= ncell_[a];
  }
  if (total > 200'000'000L)
    throw std::runtime_error(
        "neighbour grid too large (" + std::to_string(total) +
        " cells): particles are spread far apart; check for escaped particles");

  std::vector<int> cell(n);
  cell_start_.assign(total + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = cell_of(particles.x[i]);
    ++cell_start_[cell[i] + 1];
  }
  for (long c = 0; c < total; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(n);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) cell_items_[fill[cell[i]]++] = static_cast<int>(i);
}

template <int Dim>
int NeighborSearch<Dim>::cell_of(const Vec<Dim>& x) const {
  int idx = 0;
  for (int a = Dim - 1; a >= 0; --a) {
    int c = static_cast<int>(std::floor((x[a] - origin_[a]) / cell_size_[a]));
    c = std::min(std::max(c, 0), ncell_[a] - 1);
    idx = idx * ncell_[a] + c;
  }
  return idx;
}

template <int Dim>
std::vector<int> NeighborSearch<Dim>::sort(Particles<Dim>& particles) {
  make_grid(particles);
  std::vector<int> perm = cell_items_;
  particles.permute(perm);
  // Cell lists now refer to the old order; build() makes them again.
  return perm;
}

template <int Dim>
void NeighborSearch<Dim>::build(const Particles<Dim>& particles, const Kernel<Dim>& kernel,
                                Neighbors<Dim>& out, int first, int last) {
  make_grid(particles);
  const int n = static_cast<int>(particles.size());
  if (last < 0) last = n;
  const double rc2 = cutoff_ * cutoff_;

  // Visits every j within the cutoff of i (excluding i) with the minimum-image separation.
  auto visit = [&](int i, auto&& f) {
    const Vec<Dim>& xi = particles.x[i];
    Eigen::Matrix<int, Dim, 1> ci;
    for (int a = 0; a < Dim; ++a)
      ci[a] =
          std::min(std::max(static_cast<int>(std::floor((xi[a] - origin_[a]) / cell_size_[a])), 0),
                   ncell_[a] - 1);
    const int stencil = Dim == 2 ? 9 : 27;
    for (int s = 0; s < stencil; ++s) {
      int rem = s, idx = 0, stride = 1;
      bool inside = true;
      for (int a = 0; a < Dim; ++a) {
        int c = ci[a] + (rem % 3) - 1;
        rem /= 3;
        if (c < 0 || c >= ncell_[a]) {
          if (!domain_.periodic[a]) {
            inside = false;
            break;
          }
          c = (c + ncell_[a]) % ncell_[a];
        }
        idx += c * stride;
        stride *= ncell_[a];
      }
      if (!inside) continue;
      for (int k = cell_start_[idx]; k < cell_start_[idx + 1]; ++k) {
        const int j = cell_items_[k];
        if (j == i) continue;
        const Vec<Dim> d = domain_.min_image(xi - particles.x[j]);
        const double r2 = d.squaredNorm();
        if (r2 < rc2) f(j, d, r2);
      }
    }
  };

  out.offset.assign(n + 1, 0);
#pragma omp parallel for schedule(static)
  for (int i = first; i < last; ++i) {
    int count = 0;
    visit(i, [&](int, const Vec<Dim>&, double) { ++count; });
    out.offset[i + 1] = count;
  }
  for (int i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
  const std::size_t m = out.offset[n];
  out.index.resize(m);
  out.rij.resize(m);
  out.r.resize(m);
  out.w.resize(m);
  out.dw.resize(m);
  out.w_self = kernel.value(0.0);
#pragma omp parallel for schedule(static)
  for (int i = first; i < last; ++i) {
    int k = out.offset[i];
    visit(i, [&](int j, const Vec<Dim>& d, double r2) {
      const double r = std::sqrt(r2);
      out.index[k] = j;
      out.rij[k] = d;
      out.r[k] = r;
      out.w[k] = kernel.value(r);
      out.dw[k] = r > 0.0 ? Vec<Dim>(kernel.derivative(r) / r * d) : Vec<Dim>::Zero();
      ++k;
    });
  }
}

template class NeighborSearch<2>;
template class NeighborSearch<3>;

}  // namespace isph
