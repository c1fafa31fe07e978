#include "porous_medium.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace isph {

template <int Dim>
void PorousMedium<Dim>::prepare(const Particles<Dim>& P, const Neighbors<Dim>& nb, double dt,
                                const RowShare* share) {
  const int n = static_cast<int>(P.size());
  active_ = false;
  std::string error;
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] == kWall) continue;
    const double eps = P.porosity[i], K = P.resistance[i];
    if ((!(eps > 0.0 && eps <= 1.0) || !(K >= 0.0) || !std::isfinite(K) ||
         !P.solid_velocity[i].allFinite()) &&
        error.empty())
      error = "particle " + std::to_string(P.id[i]) + ": porosity " + std::to_string(eps) +
              ", resistance " + std::to_string(K) +
              " 1/s; porosity must lie in (0, 1] and resistance be finite and >= 0 (check "
              "unresolved.min_porosity and the drag law)";
    if (eps != 1.0 || K != 0.0) active_ = true;
  }
  // Decomposed, the particle is on some processes only: all stop, with the first one's message.
  if (share && share->decomposed()) error = share->first_text(error);
  if (!error.empty()) throw std::invalid_argument(error);
  // Decomposed, another process's particles may be porous: all take the same branch below.
  if (share && share->decomposed()) active_ = share->max(active_ ? 1.0 : 0.0) > 0.0;
  coefficient_.assign(n, 1.0);
  if (!active_) return;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] == kWall) continue;
    const double cr = virtual_mass_coefficient(P.porosity[i]);
    coefficient_[i] = P.porosity[i] / (cr * (1.0 + dt * P.resistance[i] / cr));
  }
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (P.kind[i] != kWall) continue;
    double ws = 0.0, cs = 0.0;
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      if (P.kind[j] == kWall) continue;
      ws += nb.w[k];
      cs += nb.w[k] * coefficient_[j];
    }
    if (ws > 0.0) coefficient_[i] = cs / ws;
  }
  if (share) share->exchange(coefficient_);  // the PPE's pair weights read the neighbours'
}

template <int Dim>
Vec<Dim> PorousMedium<Dim>::predict(const Particles<Dim>& P, int i, double dt, double nu,
                                    double nu_t, const Vec<Dim>& laplacian_v,
                                    const Vec<Dim>& g) const {
  const double eps = P.porosity[i];
  const double cr = virtual_mass_coefficient(eps);
  const double k = P.resistance[i] / cr;
  // (eps/C_r) nu_E = (nu + nu_T)/C_r with nu_E = (nu + nu_T)/eps.
  const Vec<Dim> explicit_part = P.v[i] + dt * ((nu + nu_t) / cr * laplacian_v + eps / cr * g) +
                                 dt * k * eps * P.solid_velocity[i];
  return explicit_part / (1.0 + dt * k);
}

template class PorousMedium<2>;
template class PorousMedium<3>;

}  // namespace isph
