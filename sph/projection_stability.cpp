#include "projection_stability.hpp"

namespace isph {

template <int Dim>
double projection_self_ratio(const Particles<Dim>& P, const Neighbors<Dim>& nb,
                             const Operators<Dim>& op, int i) {
  // Walls are held: their pressure follows p_i through the Adami extrapolation by a share only a
  // wall's own neighbour list knows, which a halo row of a decomposed run does not have.
  // a_ji is taken as -a_ij, its value on a symmetric support, for the same reason: one rule for
  // every row keeps the marks the same however the fluid is split.
  Vec<Dim> sum_a = Vec<Dim>::Zero();
  double cross = 0.0, lap = 0.0;
  for (int k = nb.begin(i); k < nb.end(i); ++k) {
    sum_a += op.grad[k];
    lap -= op.lap[k];
    if (P.kind[nb.index[k]] == kFluid) cross -= op.grad[k].squaredNorm();
  }
  if (!(lap < 0.0)) return 0.0;  // no usable Laplacian row: as unstable as it gets
  return (cross + sum_a.squaredNorm()) / lap;
}

template <int Dim>
int mark_unstable_projection_rows(Particles<Dim>& P, const Neighbors<Dim>& nb,
                                  const Operators<Dim>& op, int first, int last, double min_ratio) {
  std::vector<uint8_t> unstable(static_cast<std::size_t>(last), 0);
  int count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (int i = first; i < last; ++i) {
    if (P.kind[i] != kFluid || P.surface[i]) continue;
    bool by_surface = false;
    for (int k = nb.begin(i); k < nb.end(i) && !by_surface; ++k)
      by_surface = P.surface[nb.index[k]];
    if (!by_surface) continue;
    const double r = projection_self_ratio(P, nb, op, i);
    if (r > min_ratio && r < 2.0 - min_ratio) continue;  // damps: |1 - r| < 1
    unstable[i] = 1;
    ++count;
  }
  for (int i = first; i < last; ++i)
    if (unstable[i]) P.surface[i] = 1;
  return count;
}

template double projection_self_ratio<2>(const Particles<2>&, const Neighbors<2>&,
                                         const Operators<2>&, int);
template double projection_self_ratio<3>(const Particles<3>&, const Neighbors<3>&,
                                         const Operators<3>&, int);
template int mark_unstable_projection_rows<2>(Particles<2>&, const Neighbors<2>&,
                                              const Operators<2>&, int, int, double);
template int mark_unstable_projection_rows<3>(Particles<3>&, const Neighbors<3>&,
                                              const Operators<3>&, int, int, double);

}  // namespace isph
