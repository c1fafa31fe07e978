#include "projection_stability.hpp"

namespace isph {

template <int Dim>
double projection_self_ratio(const Particles<Dim>& P, const Neighbors<Dim>& nb,
                             const Operators<Dim>& op, int i, int first, int last) {
  // A wall particle's pressure is the Adami extrapolation of its fluid neighbours': it moves with
  // p_i by the share w_wi = W_wi / sum_f W_wf, which the self terms of G and L take in.
  auto wall_share = [&](int w, double w_wi) {
    if (w < first || w >= last) return 0.0;
    double ws = 0.0;
    for (int m = nb.begin(w); m < nb.end(w); ++m)
      if (P.kind[nb.index[m]] != kWall) ws += nb.w[m];
    return ws > 0.0 ? w_wi / ws : 0.0;
  };
  Vec<Dim> self_grad = Vec<Dim>::Zero();  // d(G p_i) / d p_i, negated
  double cross = 0.0, lap = 0.0;
  for (int k = nb.begin(i); k < nb.end(i); ++k) {
    const int j = nb.index[k];
    if (P.kind[j] == kWall) {
      const double s = wall_share(j, nb.w[k]);
      self_grad += (1.0 - s) * op.grad[k];
      lap -= (1.0 - s) * op.lap[k];
      continue;
    }
    self_grad += op.grad[k];
    lap -= op.lap[k];
    if (P.kind[j] != kFluid) continue;  // solids, the forcing zone: set, not corrected
    Vec<Dim> a_ji = -op.grad[k];
    if (j >= first && j < last)
      for (int m = nb.begin(j); m < nb.end(j); ++m)
        if (nb.index[m] == i) {
          a_ji = op.grad[m];
          break;
        }
    cross += op.grad[k].dot(a_ji);
  }
  if (!(lap < 0.0)) return 0.0;  // no usable Laplacian row: as unstable as it gets
  return (cross + self_grad.squaredNorm()) / lap;
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
    const double r = projection_self_ratio(P, nb, op, i, first, last);
    if (r > min_ratio && r < 2.0 - min_ratio) continue;
    unstable[i] = 1;
    ++count;
  }
  for (int i = first; i < last; ++i)
    if (unstable[i]) P.surface[i] = 1;
  return count;
}

template double projection_self_ratio<2>(const Particles<2>&, const Neighbors<2>&,
                                         const Operators<2>&, int, int, int);
template double projection_self_ratio<3>(const Particles<3>&, const Neighbors<3>&,
                                         const Operators<3>&, int, int, int);
template int mark_unstable_projection_rows<2>(Particles<2>&, const Neighbors<2>&,
                                              const Operators<2>&, int, int, double);
template int mark_unstable_projection_rows<3>(Particles<3>&, const Neighbors<3>&,
                                              const Operators<3>&, int, int, double);

}  // namespace isph
