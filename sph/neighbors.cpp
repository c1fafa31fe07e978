#include "neighbors.hpp"

#include <omp.h>

#include <algorithm>
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

  // Raw pointers: through the vectors the compiler reloaded every array's address for each
  // candidate, since the pairs written may alias them.
  const Vec<Dim>* const X = particles.x.data();
  const int* const items = cell_items_.data();
  const int* const starts = cell_start_.data();
  const bool periodic =
      std::any_of(domain_.periodic.begin(), domain_.periodic.end(), [](bool p) { return p; });
  // Appends to `buf` (from `used` on) every j within the cutoff of i (excluding i) with the
  // minimum-image separation. Every candidate is written and only those inside are kept: a
  // branch on the distance test mispredicted for about one candidate in three.
  auto visit = [&](int i, std::vector<Candidate>& buf, std::size_t& used) {
    const Vec<Dim> xi = X[i];
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
      const int begin = starts[idx], end = starts[idx + 1];
      if (used + std::size_t(end - begin) > buf.size())
        buf.resize(std::max(2 * buf.size(), used + std::size_t(end - begin)));
      Candidate* const b = buf.data();
      for (int k = begin; k < end; ++k) {
        const int j = items[k];
        const Vec<Dim> d = periodic ? domain_.min_image(xi - X[j]) : Vec<Dim>(xi - X[j]);
        const double r2 = d.squaredNorm();
        b[used] = {j, d, r2};
        used += (r2 < rc2) & (j != i);
      }
    }
  };

  // One pass over the candidates: each thread lists the pairs of its own block of rows, then
  // copies them to their place once every block's length is known. (Counting first and visiting
  // again did every distance test twice: 2.4 of the erosion tank's 12.6 ms fluid step went to
  // this search, bench/fluid/profile.md.)
  out.offset.assign(n + 1, 0);
  const int threads = omp_get_max_threads();
  found_.resize(std::max<std::size_t>(found_.size(), threads));
  std::vector<int> block_first(threads, last);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    std::vector<Candidate>& mine = found_[t];
    std::size_t used = 0;
#pragma omp for schedule(static)
    for (int i = first; i < last; ++i) {
      if (block_first[t] == last) block_first[t] = i;
      const std::size_t before = used;
      visit(i, mine, used);
      out.offset[i + 1] = static_cast<int>(used - before);
    }
#pragma omp barrier
#pragma omp single
    {
      for (int i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
      const std::size_t m = out.offset[n];
      out.index.resize(m);
      out.rij.resize(m);
      out.r.resize(m);
      out.w.resize(m);
      out.dw.resize(m);
      out.w_self = kernel.value(0.0);
    }
    if (used > 0) {
      const std::size_t k0 = out.offset[block_first[t]];
      int* const index = out.index.data() + k0;
      Vec<Dim>* const rij = out.rij.data() + k0;
      double* const r = out.r.data() + k0;
      double* const w = out.w.data() + k0;
      Vec<Dim>* const dw = out.dw.data() + k0;
      const Candidate* const c = mine.data();
      for (std::size_t p = 0; p < used; ++p) {
        const double rp = std::sqrt(c[p].r2);
        index[p] = c[p].j;
        rij[p] = c[p].d;
        r[p] = rp;
        w[p] = kernel.value(rp);
        dw[p] = rp > 0.0 ? Vec<Dim>(kernel.derivative(rp) / rp * c[p].d) : Vec<Dim>::Zero();
      }
    }
  }
}

template class NeighborSearch<2>;
template class NeighborSearch<3>;

}  // namespace isph
