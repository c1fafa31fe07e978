#include "surface_ghosts.hpp"

#include <cmath>
#include <cstdlib>

namespace isph {

template <int Dim>
void place_surface_ghosts(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                          const Domain<Dim>& domain, int layers, double clearance,
                          const Vec<Dim>& gravity, double rho0, SurfaceGhosts<Dim>& out) {
  const auto& P = particles;
  const int n = static_cast<int>(P.size());
  const double dx = P.spacing;
  out.real = P.size();
  out.parent.clear();
  out.x.clear();
  out.pressure.clear();
  out.dv.clear();
  out.has_ghost.assign(n, 0);
  out.normal.assign(n, Vec<Dim>::Zero());
  const double c2 = clearance * clearance;
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] != kFluid || !P.surface[i]) continue;
    Vec<Dim> nrm = Vec<Dim>::Zero();
    for (int k = nb.begin(i); k < nb.end(i); ++k) nrm -= nb.dw[k];
    // An isolated particle (a splash drop) has no side that is out of the water.
    if (!(nrm.norm() > 1e-12 * nb.w_self / dx)) continue;
    nrm.normalize();
    if (std::getenv("GHOST_UP") && gravity.squaredNorm() > 0.0) nrm = -gravity.normalized();
    for (int layer = 1; layer <= layers; ++layer) {
      Vec<Dim> y = P.x[i] + layer * dx * nrm;
      if (!domain.contains(y)) break;
      // The neighbours of i cover every particle within the clearance of its first two ghosts
      // (support 2.6 dx with Wendland at h = 1.3 dx).
      bool blocked = false;
      for (int k = nb.begin(i); k < nb.end(i) && !blocked; ++k)
        blocked = domain.min_image(y - P.x[nb.index[k]]).squaredNorm() < c2;
      if (blocked) break;
      domain.wrap(y);
      out.parent.push_back(i);
      out.x.push_back(y);
      out.pressure.push_back(rho0 * gravity.dot((layer - 0.5) * dx * nrm));
      out.dv.push_back(Vec<Dim>::Zero());
      out.has_ghost[i] = 1;
      out.normal[i] = nrm;
    }
  }
}

template <int Dim>
void append_surface_ghosts(const SurfaceGhosts<Dim>& ghosts, Particles<Dim>& particles) {
  auto& P = particles;
  const int64_t next_id = P.next_id;
  for (std::size_t g = 0; g < ghosts.x.size(); ++g) {
    const int i = ghosts.parent[g];
    P.add(ghosts.x[g], P.v[i] + ghosts.dv[g], kGhost);
    P.p.back() = ghosts.pressure[g];
    P.porosity.back() = P.porosity[i];
    P.surface.back() = 1;
  }
  P.next_id = next_id;  // ghosts live for one step and must not use up ids
  for (std::size_t i = 0; i < ghosts.real; ++i)
    if (ghosts.has_ghost[i]) P.surface[i] = 0;
}

template <int Dim>
void remove_surface_ghosts(std::size_t real, Particles<Dim>& particles, Neighbors<Dim>& nb,
                           Operators<Dim>& op) {
  if (particles.size() == real) return;
  particles.for_each_array([&](auto& a) { a.resize(real); });
  const int n = static_cast<int>(real);
  int out = 0;
  for (int i = 0; i < n; ++i) {
    const int b = nb.offset[i], e = nb.offset[i + 1];
    nb.offset[i] = out;
    for (int k = b; k < e; ++k) {
      if (nb.index[k] >= n) continue;
      nb.index[out] = nb.index[k];
      nb.rij[out] = nb.rij[k];
      nb.r[out] = nb.r[k];
      nb.w[out] = nb.w[k];
      nb.dw[out] = nb.dw[k];
      op.grad[out] = op.grad[k];
      op.lap[out] = op.lap[k];
      ++out;
    }
  }
  nb.offset.resize(n + 1);
  nb.offset[n] = out;
  for (auto* a : {&nb.r, &nb.w}) a->resize(out);
  nb.index.resize(out);
  nb.rij.resize(out);
  nb.dw.resize(out);
  op.grad.resize(out);
  op.lap.resize(out);
  op.order.resize(n);
}

template void place_surface_ghosts<2>(const Particles<2>&, const Neighbors<2>&, const Domain<2>&,
                                      int, double, const Vec<2>&, double, SurfaceGhosts<2>&);
template void place_surface_ghosts<3>(const Particles<3>&, const Neighbors<3>&, const Domain<3>&,
                                      int, double, const Vec<3>&, double, SurfaceGhosts<3>&);
template void append_surface_ghosts<2>(const SurfaceGhosts<2>&, Particles<2>&);
template void append_surface_ghosts<3>(const SurfaceGhosts<3>&, Particles<3>&);
template void remove_surface_ghosts<2>(std::size_t, Particles<2>&, Neighbors<2>&, Operators<2>&);
template void remove_surface_ghosts<3>(std::size_t, Particles<3>&, Neighbors<3>&, Operators<3>&);

}  // namespace isph
