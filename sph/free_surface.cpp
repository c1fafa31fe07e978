#include "free_surface.hpp"

#include <cmath>

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

template <int Dim>
void mark_free_surface(Particles<Dim>& particles, const std::vector<double>& n, double n0,
                       double threshold) {
  const int np = static_cast<int>(particles.size());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < np; ++i)
    particles.surface[i] = particles.kind[i] != kWall && n[i] < threshold * n0;
}

template void number_density<2>(const Neighbors<2>&, std::vector<double>&);
template void number_density<3>(const Neighbors<3>&, std::vector<double>&);
template double reference_number_density<2>(const Kernel<2>&, double);
template double reference_number_density<3>(const Kernel<3>&, double);
template void mark_free_surface<2>(Particles<2>&, const std::vector<double>&, double, double);
template void mark_free_surface<3>(Particles<3>&, const std::vector<double>&, double, double);

}  // namespace isph
