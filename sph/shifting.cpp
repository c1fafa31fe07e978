#include "shifting.hpp"

namespace isph {

template <int Dim>
void compute_shifts(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                    const Kernel<Dim>& kernel, const ShiftingParams& params, double dt,
                    const std::vector<uint8_t>& mode, std::vector<Vec<Dim>>& shift,
                    const RowShare* share) {
  const int n = static_cast<int>(particles.size());
  shift.assign(n, Vec<Dim>::Zero());
  if (!params.enabled) return;
  const double dx = particles.spacing;
  const double w_dx = kernel.value(dx);
  const double cap = params.max_fraction * dx;

  // Concentration gradient with the anti-clumping term, for every particle that may be shifted
  // or that is a neighbour of one (the surface normal below is smoothed over neighbours).
  std::vector<Vec<Dim>> grad_c(n, Vec<Dim>::Zero());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (particles.kind[i] == kWall) continue;
    Vec<Dim> g = Vec<Dim>::Zero();
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const double q = nb.w[k] / w_dx;
      g += (1.0 + params.tensile_r * q * q * q * q) * nb.dw[k];
    }
    grad_c[i] = particles.volume * g;
  }
  if (share) share->exchange(grad_c);  // the surface normal below reads the neighbours'

#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (!mode[i]) continue;
    const double D = params.coefficient * kernel.h() * particles.v[i].norm() * dt;
    Vec<Dim> dr = -D * grad_c[i];
    if (mode[i] == 1) {
      // Surface normal: grad C smoothed over the kernel. Its truncation part is coherent across
      // neighbours while disorder averages out, so the tangential part of the shift survives.
      Vec<Dim> nrm = nb.w_self * grad_c[i];
      for (int k = nb.begin(i); k < nb.end(i); ++k) nrm += nb.w[k] * grad_c[nb.index[k]];
      const double n2 = nrm.squaredNorm();
      if (n2 > 0.0) dr -= dr.dot(nrm) / n2 * nrm;
    }
    const double len = dr.norm();
    if (len > cap) dr *= cap / len;
    shift[i] = dr;
  }
}

template <int Dim>
void separate_close_pairs(Particles<Dim>& particles, const Neighbors<Dim>& nb,
                          const Domain<Dim>& domain, double dt, double min_distance,
                          std::vector<Vec<Dim>>& shift, const RowShare* share) {
  auto& P = particles;
  const int n = static_cast<int>(P.size());
  // Every correction is computed from the state before the sweep and each particle takes only its
  // own half of each of its pairs: the result does not depend on the order of the pairs, so a
  // process that corrects its own rows (shared rows, or a decomposed fluid with its halo) gets
  // what one process gets. A serial sweep in which each correction saw the last gave results that
  // depended on the order once pairs formed chains (at 0.8 dx, near a disturbed surface).
  const bool parts = share && share->parts() > 1;
  const int lo = parts ? share->first(n) : 0, hi = parts ? share->last(n) : n;
  std::vector<Vec<Dim>> ds(static_cast<std::size_t>(hi - lo), Vec<Dim>::Zero());
  std::vector<Vec<Dim>> dv(ds.size(), Vec<Dim>::Zero());
#pragma omp parallel for schedule(static)
  for (int i = lo; i < hi; ++i) {
    if (P.kind[i] != kFluid) continue;
    const Vec<Dim> xi = P.x[i] + dt * P.v[i] + shift[i];
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] != kFluid) continue;
      const Vec<Dim> d = domain.min_image(xi - (P.x[j] + dt * P.v[j] + shift[j]));
      const double r = d.norm();
      if (r >= min_distance || !(r > 0.0)) continue;
      const Vec<Dim> e = d / r;
      ds[i - lo] += 0.5 * (min_distance - r) * e;
      const double vn = (P.v[i] - P.v[j]).dot(e);
      if (vn < 0.0) dv[i - lo] -= 0.5 * vn * e;
    }
  }
  for (int i = lo; i < hi; ++i) {
    shift[i] += ds[i - lo];
    P.v[i] += dv[i - lo];
  }
  // Shared rows: every process holds shift and v whole again (decomposed: the halo is dropped).
  if (parts && !share->decomposed()) {
    share->exchange(shift);
    share->exchange(P.v);
  }
}

template void separate_close_pairs<2>(Particles<2>&, const Neighbors<2>&, const Domain<2>&, double,
                                      double, std::vector<Vec<2>>&, const RowShare*);
template void separate_close_pairs<3>(Particles<3>&, const Neighbors<3>&, const Domain<3>&, double,
                                      double, std::vector<Vec<3>>&, const RowShare*);

template void compute_shifts<2>(const Particles<2>&, const Neighbors<2>&, const Kernel<2>&,
                                const ShiftingParams&, double, const std::vector<uint8_t>&,
                                std::vector<Vec<2>>&, const RowShare*);
template void compute_shifts<3>(const Particles<3>&, const Neighbors<3>&, const Kernel<3>&,
                                const ShiftingParams&, double, const std::vector<uint8_t>&,
                                std::vector<Vec<3>>&, const RowShare*);

}  // namespace isph
