#include "pocket_fluid.hpp"

#include <algorithm>
#include <unordered_map>

namespace isph {

namespace {

// Kernel weights of i's non-wall and solid neighbours, and the weighted sum of the solids'
// velocities: the share and the blend target from one pass over the neighbours.
template <int Dim>
struct SolidSupport {
  double all = 0.0, solid = 0.0;
  Vec<Dim> solid_velocity_sum = Vec<Dim>::Zero();
};

template <int Dim>
SolidSupport<Dim> solid_support(const Particles<Dim>& P, const Neighbors<Dim>& nb, int i) {
  SolidSupport<Dim> s;
  for (int k = nb.begin(i); k < nb.end(i); ++k) {
    const int j = nb.index[k];
    if (P.kind[j] == kWall) continue;
    s.all += nb.w[k];
    if (P.kind[j] != kSolid) continue;
    s.solid += nb.w[k];
    s.solid_velocity_sum += nb.w[k] * P.v[j];
  }
  return s;
}

}  // namespace

template <int Dim>
double solid_share(const Particles<Dim>& P, const Neighbors<Dim>& nb, int i) {
  const SolidSupport<Dim> s = solid_support(P, nb, i);
  return s.all > 0.0 ? s.solid / s.all : 0.0;
}

template <int Dim>
int follow_enclosing_solids(Particles<Dim>& P, const Neighbors<Dim>& nb, double onset, double rho0,
                            double dt, const RowShare* share) {
  // Called only where some process holds solids (IsphSolver::has_solids): a process without
  // any still takes part in the exchanges below.
  const bool decomposed = share && share->decomposed();
  if (!(onset < 1.0)) return 0;
  const int n = static_cast<int>(P.size());
  const int first = share ? share->first(n) : 0, last = share ? share->last(n) : n;
  int blended = 0;
  struct Reaction {
    int j;       // shared rows: the row, the same on every process
    int64_t id;  // decomposed: the solid's id, as its row may be another process's halo copy
    Vec<Dim> force;
  };
  std::vector<Reaction> reactions;  // with shared rows: applied below, in row order
  // Serial: few particles qualify, and the reaction is scattered to shared solid neighbours.
  for (int i = first; i < last; ++i) {
    if (P.kind[i] != kFluid) continue;
    const SolidSupport<Dim> sup = solid_support(P, nb, i);
    if (!(sup.solid > onset * sup.all)) continue;
    const double phi = sup.solid / sup.all;
    const Vec<Dim> vs = sup.solid_velocity_sum / sup.solid;
    const double s = std::min(1.0, (phi - onset) / kPocketRamp);
    const Vec<Dim> dv = -s * (P.v[i] - vs);
    P.v[i] += dv;
    // The particle gained rho0 V dv; its solid neighbours take the opposite.
    const Vec<Dim> reaction = -rho0 * P.volume * dv / dt;
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] != kSolid) continue;
      if (share)
        reactions.push_back({j, P.id[j], nb.w[k] / sup.solid * reaction});
      else
        P.solid_force[j] += nb.w[k] / sup.solid * reaction;
    }
    ++blended;
  }
  if (share) {
    const std::vector<Reaction> all = share->concatenate(reactions);
    if (decomposed) {  // each solid's owner takes its reactions
      std::unordered_map<int64_t, int> owned;
      if (!all.empty())
        for (int i = first; i < last; ++i)
          if (P.kind[i] == kSolid) owned.emplace(P.id[i], i);
      for (const auto& r : all)
        if (const auto it = owned.find(r.id); it != owned.end())
          P.solid_force[it->second] += r.force;
    } else {
      for (const auto& r : all) P.solid_force[r.j] += r.force;
    }
    blended = static_cast<int>(share->sum(blended));
  }
  return blended;
}

template double solid_share<2>(const Particles<2>&, const Neighbors<2>&, int);
template double solid_share<3>(const Particles<3>&, const Neighbors<3>&, int);
template int follow_enclosing_solids<2>(Particles<2>&, const Neighbors<2>&, double, double, double,
                                        const RowShare*);
template int follow_enclosing_solids<3>(Particles<3>&, const Neighbors<3>&, double, double, double,
                                        const RowShare*);

}  // namespace isph
