#include "lattice.hpp"

#include <cmath>

namespace isph {

namespace {

// Calls f for every lattice point lo + (k + 1/2) dx inside [lo, hi].
template <int Dim, class F>
void for_lattice(const Vec<Dim>& lo, const Vec<Dim>& hi, double dx, F&& f) {
  Eigen::Matrix<long, Dim, 1> count;
  for (int a = 0; a < Dim; ++a)
    count[a] = std::max(0L, static_cast<long>(std::floor((hi[a] - lo[a]) / dx + 1e-9)));
  Eigen::Matrix<long, Dim, 1> k = Eigen::Matrix<long, Dim, 1>::Zero();
  for (int a = 0; a < Dim; ++a)
    if (count[a] == 0) return;
  while (true) {
    Vec<Dim> x;
    for (int a = 0; a < Dim; ++a) x[a] = lo[a] + (k[a] + 0.5) * dx;
    f(x);
    int a = 0;
    while (a < Dim && ++k[a] >= count[a]) k[a++] = 0;
    if (a == Dim) break;
  }
}

}  // namespace

template <int Dim>
std::size_t fill_box(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi, double dx,
                     int32_t kind, const std::function<bool(const Vec<Dim>&)>& keep) {
  const std::size_t before = particles.size();
  for_lattice<Dim>(lo, hi, dx, [&](const Vec<Dim>& x) {
    if (!keep || keep(x)) particles.add(x, Vec<Dim>::Zero(), kind);
  });
  return particles.size() - before;
}

template <int Dim>
std::size_t add_wall_shell(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi,
                           double dx, int layers, const std::array<bool, 2 * Dim>& closed) {
  Vec<Dim> elo = lo, ehi = hi;
  for (int a = 0; a < Dim; ++a) {
    if (closed[2 * a]) elo[a] -= layers * dx;
    if (closed[2 * a + 1]) ehi[a] += layers * dx;
  }
  const double eps = 1e-9 * dx;
  const std::size_t first = particles.size();
  const std::size_t added = fill_box<Dim>(particles, elo, ehi, dx, kWall, [&](const Vec<Dim>& x) {
    for (int a = 0; a < Dim; ++a)
      if (x[a] < lo[a] - eps || x[a] > hi[a] + eps) return true;
    return false;
  });
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec<Dim>& x = particles.x[i];
    const Vec<Dim> q = x.cwiseMax(lo).cwiseMin(hi);  // nearest point of the box
    const double d = (q - x).norm();
    particles.wall_distance[i] = d;
    particles.normal[i] = (q - x) / d;
  }
  return added;
}

template <int Dim>
std::size_t add_wall_block(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi,
                           double dx) {
  const std::size_t first = particles.size();
  const std::size_t added = fill_box<Dim>(particles, lo, hi, dx, kWall);
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec<Dim>& x = particles.x[i];
    double best = 1e300;
    for (int a = 0; a < Dim; ++a)
      for (int side = 0; side < 2; ++side) {
        const double d = side ? hi[a] - x[a] : x[a] - lo[a];
        if (d >= best) continue;
        best = d;
        particles.normal[i] = Vec<Dim>::Unit(a) * (side ? 1.0 : -1.0);
      }
    particles.wall_distance[i] = best;
  }
  return added;
}

template std::size_t fill_box<2>(Particles<2>&, const Vec<2>&, const Vec<2>&, double, int32_t,
                                 const std::function<bool(const Vec<2>&)>&);
template std::size_t fill_box<3>(Particles<3>&, const Vec<3>&, const Vec<3>&, double, int32_t,
                                 const std::function<bool(const Vec<3>&)>&);
template std::size_t add_wall_block<2>(Particles<2>&, const Vec<2>&, const Vec<2>&, double);
template std::size_t add_wall_block<3>(Particles<3>&, const Vec<3>&, const Vec<3>&, double);
template std::size_t add_wall_shell<2>(Particles<2>&, const Vec<2>&, const Vec<2>&, double, int,
                                       const std::array<bool, 4>&);
template std::size_t add_wall_shell<3>(Particles<3>&, const Vec<3>&, const Vec<3>&, double, int,
                                       const std::array<bool, 6>&);

}  // namespace isph
