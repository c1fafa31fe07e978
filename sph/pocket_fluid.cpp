#include "pocket_fluid.hpp"

#include <algorithm>

namespace isph {

template <int Dim>
double solid_share(const Particles<Dim>& P, const Neighbors<Dim>& nb, int i) {
  double solid = 0.0, all = 0.0;
  for (int k = nb.begin(i); k < nb.end(i); ++k) {
    const int j = nb.index[k];
    if (P.kind[j] == kWall) continue;
    all += nb.w[k];
    if (P.kind[j] == kSolid) solid += nb.w[k];
  }
  return all > 0.0 ? solid / all : 0.0;
}

template <int Dim>
int follow_enclosing_solids(Particles<Dim>& P, const Neighbors<Dim>& nb, double onset, double rho0,
                            double dt) {
  if (!(onset < 1.0)) return 0;
  const int n = static_cast<int>(P.size());
  int blended = 0;
  // Serial: few particles qualify, and the reaction is scattered to shared solid neighbours.
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] != kFluid) continue;
    const double phi = solid_share(P, nb, i);
    if (phi <= onset) continue;
    double ws = 0.0;
    Vec<Dim> vs = Vec<Dim>::Zero();
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] != kSolid) continue;
      ws += nb.w[k];
      vs += nb.w[k] * P.v[j];
    }
    vs /= ws;
    const double s = std::min(1.0, (phi - onset) / kPocketRamp);
    const Vec<Dim> dv = -s * (P.v[i] - vs);
    P.v[i] += dv;
    // The particle gained rho0 V dv; its solid neighbours take the opposite.
    const Vec<Dim> reaction = -rho0 * P.volume * dv / dt;
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] == kSolid) P.solid_force[j] += nb.w[k] / ws * reaction;
    }
    ++blended;
  }
  return blended;
}

template double solid_share<2>(const Particles<2>&, const Neighbors<2>&, int);
template double solid_share<3>(const Particles<3>&, const Neighbors<3>&, int);
template int follow_enclosing_solids<2>(Particles<2>&, const Neighbors<2>&, double, double, double);
template int follow_enclosing_solids<3>(Particles<3>&, const Neighbors<3>&, double, double, double);

}  // namespace isph
