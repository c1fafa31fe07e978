#include "free_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isph {

template <int Dim>
void number_density(const Neighbors<Dim>& nb, std::vector<double>& n) {
  const int np = static_cast<int>(nb.size());
  n.resize(np);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i) {
    double s = nb.w_self;
    for (int k = nb.begin(i); k < nb.end(i); ++k) s += nb.w[k];
    n[i] = s;
  }
}

template <int Dim>
double reference_number_density(const Kernel<Dim>& kernel, double dx) {
  const int m = static_cast<int>(std::ceil(kernel.support() / dx)) + 1;
  double s = 0.0;
  Eigen::Matrix<int, Dim, 1> c = Eigen::Matrix<int, Dim, 1>::Constant(-m);
  while (true) {
    s += kernel.value(c.template cast<double>().norm() * dx);
    int a = 0;
    while (a < Dim && ++c[a] > m) c[a++] = -m;
    if (a == Dim) break;
  }
  return s;
}

SurfaceDetection surface_detection_from_name(const std::string& name) {
  if (name == "number_density") return SurfaceDetection::NumberDensity;
  if (name == "divergence") return SurfaceDetection::Divergence;
  if (name == "either") return SurfaceDetection::Either;
  throw std::invalid_argument("unknown surface detection '" + name +
                              "': use \"number_density\", \"divergence\" or \"either\"");
}

template <int Dim>
void position_divergence(const Neighbors<Dim>& nb, double volume, std::vector<double>& div) {
  const int np = static_cast<int>(nb.size());
  div.resize(np);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i) {
    double d = 0.0;
    for (int k = nb.begin(i); k < nb.end(i); ++k) d -= nb.rij[k].dot(nb.dw[k]);
    div[i] = volume * d;
  }
}

template <int Dim>
void mark_free_surface(Particles<Dim>& particles, const std::vector<double>& n, double n0,
                       const std::vector<double>& div, const SurfaceCriteria& c) {
  const int np = static_cast<int>(particles.size());
  const double div_min = c.divergence > 0.0 ? c.divergence : (Dim == 2 ? 1.5 : 2.4);
  const bool by_density = c.method != SurfaceDetection::Divergence;
  const bool by_div = c.method != SurfaceDetection::NumberDensity;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i)
    particles.surface[i] =
        particles.kind[i] != kWall &&
        ((by_density && n[i] < c.density_ratio * n0) || (by_div && div[i] < div_min));
}

template <int Dim>
void mark_sparse_as_surface(Particles<Dim>& particles, const Neighbors<Dim>& nb, int min_fluid,
                            int min_all) {
  const int np = static_cast<int>(particles.size());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i) {
    if (particles.kind[i] == kWall || particles.surface[i]) continue;
    int nf = 0;
    for (int k = nb.begin(i); k < nb.end(i); ++k) nf += particles.kind[nb.index[k]] != kWall;
    if (nf < min_fluid || nb.end(i) - nb.begin(i) < min_all) particles.surface[i] = 1;
  }
}

template <int Dim>
void mark_open_side_as_surface(Particles<Dim>& particles, const Neighbors<Dim>& nb,
                               const std::vector<uint8_t>* dry, const Vec<Dim>* up) {
  const int np = static_cast<int>(particles.size());
  const double dx = particles.spacing;
  std::vector<uint8_t> open(np, 0);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i) {
    if (particles.kind[i] == kWall || particles.surface[i]) continue;
    auto ignored = [&](int k) { return dry && (*dry)[nb.index[k]]; };
    Vec<Dim> n;
    if (up) {
      n = *up;
    } else {
      Vec<Dim> g = Vec<Dim>::Zero();
      for (int k = nb.begin(i); k < nb.end(i); ++k)
        if (!ignored(k)) g += nb.dw[k];
      // dw = grad_i W_ij points from i towards j, so its sum points to the crowded side. A
      // symmetric support gives no direction and is interior.
      if (g.norm() * dx * dx * dx < 1e-6 * nb.w_self * dx) continue;
      n = -g.normalized();  // towards the emptier side
    }
    const Vec<Dim> target = dx * n;  // relative to x_i
    bool occupied = false;
    for (int k = nb.begin(i); k < nb.end(i) && !occupied; ++k) {
      if (ignored(k)) continue;
      const Vec<Dim> r = -nb.rij[k];  // x_j - x_i
      occupied = (r - target).norm() < dx && r.dot(n) > 0.5 * r.norm();
    }
    open[i] = !occupied;
  }
  for (int i = 0; i < np; ++i)
    if (open[i]) particles.surface[i] = 1;
}

template <int Dim>
void mark_dry_walls(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                    const Vec<Dim>& gravity, double rho0, std::vector<uint8_t>& dry) {
  const auto& P = particles;
  const int np = static_cast<int>(P.size());
  dry.assign(np, 0);
  if (gravity.squaredNorm() == 0.0) return;
  const Vec<Dim> up = -gravity.normalized();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i) {
    if (P.kind[i] != kWall) continue;
    double ws = 0.0, ps = 0.0, height = 0.0;
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] == kWall) continue;
      ws += nb.w[k];
      ps += nb.w[k] * (P.p[j] + rho0 * gravity.dot(nb.rij[k]));  // r_ij = x_w - x_f
      height += nb.w[k] * up.dot(nb.rij[k]);
    }
    dry[i] = ws > 0.0 && ps < 0.0 && height > 0.25 * P.spacing * ws;
  }
}

template <int Dim>
void surface_depth(const Particles<Dim>& particles, const Neighbors<Dim>& nb, const Vec<Dim>& up,
                   std::vector<double>& depth) {
  const auto& P = particles;
  const int np = static_cast<int>(P.size());
  depth.assign(np, 0.0);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i) {
    if (P.kind[i] == kWall || P.kind[i] == kSolid || !P.surface[i]) continue;
    double ws = 0.0, hs = 0.0;
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] == kWall || P.kind[j] == kSolid || !P.surface[j]) continue;
      ws += nb.w[k];
      hs -= nb.w[k] * up.dot(nb.rij[k]);  // r_ij = x_i - x_j
    }
    if (ws > 0.0) depth[i] = std::max(0.0, hs / ws);
  }
}

template <int Dim>
int reference_neighbor_count(const Kernel<Dim>& kernel, double dx) {
  const int m = static_cast<int>(std::ceil(kernel.support() / dx)) + 1;
  int count = -1;  // the particle itself
  Eigen::Matrix<int, Dim, 1> c = Eigen::Matrix<int, Dim, 1>::Constant(-m);
  while (true) {
    count += c.template cast<double>().norm() * dx < kernel.support();
    int a = 0;
    while (a < Dim && ++c[a] > m) c[a++] = -m;
    if (a == Dim) break;
  }
  return count;
}

template void number_density<2>(const Neighbors<2>&, std::vector<double>&);
template void number_density<3>(const Neighbors<3>&, std::vector<double>&);
template double reference_number_density<2>(const Kernel<2>&, double);
template double reference_number_density<3>(const Kernel<3>&, double);
template void position_divergence<2>(const Neighbors<2>&, double, std::vector<double>&);
template void position_divergence<3>(const Neighbors<3>&, double, std::vector<double>&);
template void mark_sparse_as_surface<2>(Particles<2>&, const Neighbors<2>&, int, int);
template void mark_sparse_as_surface<3>(Particles<3>&, const Neighbors<3>&, int, int);
template void mark_open_side_as_surface<2>(Particles<2>&, const Neighbors<2>&,
                                           const std::vector<uint8_t>*, const Vec<2>*);
template void mark_open_side_as_surface<3>(Particles<3>&, const Neighbors<3>&,
                                           const std::vector<uint8_t>*, const Vec<3>*);
template void mark_dry_walls<2>(const Particles<2>&, const Neighbors<2>&, const Vec<2>&, double,
                                std::vector<uint8_t>&);
template void mark_dry_walls<3>(const Particles<3>&, const Neighbors<3>&, const Vec<3>&, double,
                                std::vector<uint8_t>&);
template void surface_depth<2>(const Particles<2>&, const Neighbors<2>&, const Vec<2>&,
                               std::vector<double>&);
template void surface_depth<3>(const Particles<3>&, const Neighbors<3>&, const Vec<3>&,
                               std::vector<double>&);
template int reference_neighbor_count<2>(const Kernel<2>&, double);
template int reference_neighbor_count<3>(const Kernel<3>&, double);
template void mark_free_surface<2>(Particles<2>&, const std::vector<double>&, double,
                                   const std::vector<double>&, const SurfaceCriteria&);
template void mark_free_surface<3>(Particles<3>&, const std::vector<double>&, double,
                                   const std::vector<double>&, const SurfaceCriteria&);

}  // namespace isph
