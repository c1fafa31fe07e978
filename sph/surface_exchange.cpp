#include "surface_exchange.hpp"

#include <limits>

namespace isph {

namespace {

template <int Dim>
class Exchange {
 public:
  Exchange(Particles<Dim>& P, const Neighbors<Dim>& nb, const Domain<Dim>& domain,
           const Vec<Dim>& up, const SurfaceExchangeParams& params)
      : P_(P),
        nb_(nb),
        domain_(domain),
        up_(up),
        dx_(P.spacing),
        params_(params),
        moved_(P.size(), 0) {}

  SurfaceExchangeCount run() {
    SurfaceExchangeCount count;
    const int n = static_cast<int>(P_.size());
    for (int i = 0; i < n; ++i) {
      if (!on_surface(i)) continue;
      for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
        const int j = nb_.index[k];
        if (j < i || !on_surface(j) || moved_[i]) continue;
        const Vec<Dim> d = sep(P_.x[j], P_.x[i]);
        const double along_up = d.dot(up_);
        const double across = (d - along_up * up_).norm();
        if (across <= params_.gap * dx_ || across > 2.5 * dx_ || std::abs(along_up) > 0.75 * dx_)
          continue;
        const Vec<Dim> mid = P_.x[i] + 0.5 * d;
        // The donor may already sit in the gap, a little below the row (diverging surface
        // flow staggers the two top rows): it is then lifted onto the row.
        const int donor = donor_below(mid, i);
        if (donor < 0 || !empty(mid, i, donor)) continue;
        move(donor, mid);
        P_.v[donor] = 0.5 * (P_.v[i] + P_.v[j]);
        ++count.gaps_filled;
      }
    }
    for (int i = 0; i < n; ++i) {
      if (!on_surface(i) || nearest_surface(i) >= params_.squeeze * dx_) continue;
      const Vec<Dim> below = P_.x[i] - dx_ * up_;
      if (!empty(below, i, -1) || fluid_around(below, i) < 3) continue;
      move(i, below);
      ++count.voids_filled;
    }
    return count;
  }

 private:
  bool on_surface(int i) const { return P_.kind[i] == kFluid && P_.surface[i] && !moved_[i]; }
  Vec<Dim> sep(const Vec<Dim>& a, const Vec<Dim>& b) const { return domain_.min_image(a - b); }

  // Nothing (fluid, wall or solid, nor a particle moved in this pass) within the clearance.
  bool empty(const Vec<Dim>& point, int i, int except) const {
    const double c2 = params_.clearance * params_.clearance * dx_ * dx_;
    if (sep(P_.x[i], point).squaredNorm() < c2) return false;
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (j != except && sep(P_.x[j], point).squaredNorm() < c2) return false;
    }
    for (const auto& x : filled_)
      if (sep(x, point).squaredNorm() < c2) return false;
    return true;
  }

  // Fluid particles within 1.5 spacings of the point: a void inside the water has them, air
  // under a splash or an overturning jet has few.
  int fluid_around(const Vec<Dim>& point, int i) const {
    int count = 0;
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      count += P_.kind[j] == kFluid && sep(P_.x[j], point).norm() < 1.5 * dx_;
    }
    return count;
  }

  int donor_below(const Vec<Dim>& point, int i) const {
    int best = -1;
    double best_d = params_.reach * dx_;
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P_.kind[j] != kFluid || P_.surface[j] || moved_[j]) continue;
      const Vec<Dim> d = sep(P_.x[j], point);
      if (d.dot(up_) > -0.2 * dx_) continue;
      if (d.norm() < best_d) {
        best_d = d.norm();
        best = j;
      }
    }
    return best;
  }

  double nearest_surface(int i) const {
    double best = std::numeric_limits<double>::infinity();
    for (int k = nb_.begin(i); k < nb_.end(i); ++k) {
      const int j = nb_.index[k];
      if (P_.kind[j] == kFluid && P_.surface[j]) best = std::min(best, nb_.r[k]);
    }
    return best;
  }

  void move(int i, const Vec<Dim>& to) {
    P_.x[i] = to;
    domain_.wrap(P_.x[i]);
    moved_[i] = 1;
    filled_.push_back(to);
  }

  Particles<Dim>& P_;
  const Neighbors<Dim>& nb_;
  const Domain<Dim>& domain_;
  Vec<Dim> up_;
  double dx_;
  SurfaceExchangeParams params_;
  std::vector<uint8_t> moved_;
  std::vector<Vec<Dim>> filled_;
};

}  // namespace

template <int Dim>
SurfaceExchangeCount exchange_surface_particles(Particles<Dim>& particles, const Neighbors<Dim>& nb,
                                                const Domain<Dim>& domain, const Vec<Dim>& up,
                                                const SurfaceExchangeParams& params) {
  return Exchange<Dim>(particles, nb, domain, up, params).run();
}

template SurfaceExchangeCount exchange_surface_particles<2>(Particles<2>&, const Neighbors<2>&,
                                                            const Domain<2>&, const Vec<2>&,
                                                            const SurfaceExchangeParams&);
template SurfaceExchangeCount exchange_surface_particles<3>(Particles<3>&, const Neighbors<3>&,
                                                            const Domain<3>&, const Vec<3>&,
                                                            const SurfaceExchangeParams&);

}  // namespace isph
