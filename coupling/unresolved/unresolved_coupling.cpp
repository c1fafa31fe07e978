#include "unresolved/unresolved_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

#include "format_number.hpp"
#include "unresolved/drag_distribution.hpp"

namespace isphdem {

namespace {

bool mapped(int32_t kind) { return kind == isph::kFluid || kind == isph::kForcing; }

}  // namespace

template <int Dim>
UnresolvedCoupling<Dim>::UnresolvedCoupling(const UnresolvedSettings& settings,
                                            std::shared_ptr<const DragLaw> law)
    : settings_(settings),
      law_(std::move(law)),
      map_(settings.map),
      depth_(Dim == 2 ? settings.map.slab_thickness : 1.0) {
  if (!law_) throw std::invalid_argument("unresolved coupling: no drag law");
  if (settings.self_induced_correction) {
    if (Dim != 3)
      throw std::invalid_argument(
          "unresolved.self_induced_correction is for 3D fluids: in 2D a line force's disturbance "
          "has no finite Stokes limit; remove the key");
    self_induced_ =
        std::make_unique<SelfInducedVelocity>(settings.map.kernel, settings.kinematic_viscosity);
  }
}

template <int Dim>
void UnresolvedCoupling<Dim>::initialize(const DemState& dem, isph::IsphSolver<Dim>& solver) {
  const auto& d = solver.domain();
  double widest = map_.support();
  for (const auto& a : dem.atoms)
    if (maps(a)) widest = std::max(widest, 2.0 * map_.smoothing_length_of(a.radius));
  for (int k = 0; k < Dim; ++k)
    if (d.periodic[k] && widest > d.hi[k] - d.lo[k])
      throw std::runtime_error(
          "the porosity kernel reaches " + isph::format_number(widest) +
          " m, farther than the periodic box is long on axis " + std::to_string(k) + " (" +
          isph::format_number(d.hi[k] - d.lo[k]) +
          " m): lower unresolved.porosity_smoothing_length (or porosity_smoothing_diameters) or "
          "make the box longer");
  check_grain_diameter(dem);
  for (const auto& a : dem.atoms) {
    if (!maps(a)) continue;
    for (int k = 0; k < Dim; ++k)
      if (!d.periodic[k] && (a.x[k] < d.lo[k] || a.x[k] > d.hi[k]))
        throw std::runtime_error(
            "unresolved coupling: grain " + std::to_string(a.tag) +
            " lies outside the fluid domain (axis " + std::to_string(k) +
            "): place the grains inside domain.min/domain.max (in 2D the fluid plane is x-y)");
  }
}

template <int Dim>
void UnresolvedCoupling<Dim>::check_grain_diameter(const DemState& dem) const {
  const double d = settings_.grain_diameter;
  if (!(d > 0.0)) return;
  std::size_t grains = 0, differ = 0;
  std::string named;
  for (const auto& a : dem.atoms) {
    if (!maps(a)) continue;
    ++grains;
    // LIGGGHTS keeps radii in double precision: a parsed 0.0005 doubles to exactly 0.001.
    if (std::abs(2.0 * a.radius - d) <= 1e-9 * d) continue;
    if (++differ <= 3)
      named += (differ > 1 ? ", " : "") + std::string("grain ") + std::to_string(a.tag) + ": " +
               isph::format_number(2.0 * a.radius) + " m";
  }
  if (differ == 0) return;
  throw std::runtime_error(
      "unresolved.grain_diameter = " + isph::format_number(d) + " m, but " +
      std::to_string(differ) + " of the " + std::to_string(grains) + " unresolved grains " +
      (differ == 1 ? "has" : "have") + " another diameter (" + named + (differ > 3 ? ", ..." : "") +
      "): the drag takes each grain's own size from LIGGGHTS, so remove "
      "unresolved.grain_diameter from the case, or give the grains that diameter in the "
      "LIGGGHTS script");
}

template <int Dim>
void UnresolvedCoupling<Dim>::before_fluid_step(const DemState& dem,
                                                isph::IsphSolver<Dim>& solver) {
  grains_.clear();
  for (const auto& a : dem.atoms) {
    if (!maps(a)) continue;
    Grain<Dim> g;
    g.tag = a.tag;
    for (int k = 0; k < Dim; ++k) g.x[k] = a.x[k], g.v[k] = a.v[k];
    g.radius = a.radius;
    solver.domain().wrap(g.x);
    grains_.push_back(g);
  }
  auto& P = solver.particles();
  std::vector<isph::Vec<Dim>> x;
  mapped_ids_.clear();
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (mapped(P.kind[i])) {
      x.push_back(P.x[i]);
      mapped_ids_.push_back(P.id[i]);
      rows.push_back(i);
    }
  // The grain grid knows no periodic images: grains within the porosity support of a periodic
  // face are mirrored across it (across both faces when the support exceeds half the box: a
  // 4 mm support in an 8 mm box gave the bed's mean porosity as 0.60 for 0.48 with one image).
  // Images carry the tag of their grain, so their share of the drag goes to the real grain.
  std::vector<Grain<Dim>> with_images = grains_;
  owner_.resize(grains_.size());
  for (std::size_t g = 0; g < owner_.size(); ++g) owner_[g] = g;
  const auto& dom = solver.domain();
  const double reach = map_.support(grains_);
  for (int k = 0; k < Dim; ++k) {
    if (!dom.periodic[k]) continue;
    const double L = dom.hi[k] - dom.lo[k];
    const std::size_t n = with_images.size();
    for (std::size_t g = 0; g < n; ++g) {
      for (const double shift : {L, -L}) {
        Grain<Dim> im = with_images[g];
        if ((shift > 0 ? im.x[k] - dom.lo[k] : dom.hi[k] - im.x[k]) >= reach) continue;
        im.x[k] += shift;
        with_images.push_back(im);
        owner_.push_back(owner_[g]);
      }
    }
  }
  grains_.swap(with_images);
  field_ = map_.compute(x, grains_);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t i = rows[r];
    const double eps = field_.porosity[r];
    P.porosity[i] = eps;
    P.solid_velocity[i] = eps < 1.0 ? field_.solid_velocity[r] : isph::Vec<Dim>::Zero();
    const double vr = (P.v[i] / eps - P.solid_velocity[i]).norm();
    P.resistance[i] = eps < 1.0 ? law_->coefficients(eps, vr, field_.diameter[r]).total(vr) : 0.0;
  }
  if (self_induced_) correct_for_self_induced_velocity(solver, rows);
}

template <int Dim>
void UnresolvedCoupling<Dim>::correct_for_self_induced_velocity(
    isph::IsphSolver<Dim>& solver, const std::vector<std::size_t>& rows) {
  // Above it a grain's own disturbance is as large as its slip: the correction's 1 / (1 - s)
  // would run away, and the grain is no longer small against the kernel (use a wider one).
  constexpr double kCap = 0.8;
  auto& P = solver.particles();
  const double rho = solver.config().density;
  const double mu = rho * settings_.kinematic_viscosity;
  const auto& w = field_.weights;
  const std::size_t n = grains_.size();
  // Per grain: B = sum share eps rho V K, the drag per unit slip the law gives it; B times the
  // slip it samples, and times 1/eps (the fluid carries Darcy velocities: a disturbance u_D in
  // them is u_D / eps in the interstitial slip); and the others' resistance on the Darcy
  // velocity, rho K per unit volume, kernel-weighted, for the Brinkman screening length
  // sqrt(mu / b). A grain's periodic images are the grain itself, not others.
  constexpr int kSums = Dim + 4;
  std::vector<double> sums(n * kSums, 0.0);
  // A grain's share of a row through all its entries (itself and its periodic images), summed
  // per owner into `own` for the row and cleared after it.
  std::vector<double> own(n, 0.0);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t i = rows[r];
    const double eps = P.porosity[i];
    if (!(eps < 1.0)) continue;
    double surface = 0.0;
    for (std::size_t e = w.offset[r]; e < w.offset[r + 1]; ++e) {
      surface += w.surface[e];
      own[owner_[w.grain[e]]] += w.surface[e];
    }
    const double b = eps * rho * P.resistance[i];
    const isph::Vec<Dim> slip = P.v[i] / eps - P.solid_velocity[i];
    for (std::size_t e = w.offset[r]; e < w.offset[r + 1]; ++e) {
      const double share = w.surface[e] / surface;
      const double others = std::max(0.0, 1.0 - own[owner_[w.grain[e]]] / surface);
      double* g = &sums[w.grain[e] * kSums];
      g[0] += share * b * P.volume;
      for (int a = 0; a < Dim; ++a) g[1 + a] += share * b * P.volume * slip[a];
      g[Dim + 1] += w.weight[e] * rho * P.resistance[i] * others;
      g[Dim + 2] += w.weight[e];
      g[Dim + 3] += share * b * P.volume / eps;
    }
    for (std::size_t e = w.offset[r]; e < w.offset[r + 1]; ++e) own[owner_[w.grain[e]]] = 0.0;
  }
  if (const isph::RowShare* ranks = solver.decomposition())
    if (!sums.empty()) ranks->sum_in_place(sums.data(), sums.size());
  for (std::size_t k = 0; k < n; ++k)  // images into their grain
    if (owner_[k] != k)
      for (int a = 0; a < kSums; ++a) sums[owner_[k] * kSums + a] += sums[k * kSums + a];
  std::vector<double> factor(n, 1.0);
  balance_.max_self_induced = 0.0;
  balance_.self_induced_capped = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (owner_[k] != k) continue;
    const double* g = &sums[k * kSums];
    if (!(g[0] > 0.0)) continue;
    isph::Vec<Dim> slip;
    for (int a = 0; a < Dim; ++a) slip[a] = g[1 + a] / g[0];
    const double background = g[Dim + 2] > 0.0 ? g[Dim + 1] / g[Dim + 2] : 0.0;
    const double screening =
        background > 0.0 ? std::sqrt(mu / background) : std::numeric_limits<double>::infinity();
    const double h = map_.smoothing_length_of(grains_[k].radius);
    const double s = g[0] * self_induced_->inverse_radius(slip.norm(), screening, h) *
                     (g[Dim + 3] / g[0]) / (6.0 * M_PI * mu);
    balance_.max_self_induced = std::max(balance_.max_self_induced, s);
    if (s > kCap) {
      ++balance_.self_induced_capped;
      if (!warned_cap_) {
        warned_cap_ = true;
        std::cerr << "unresolved: grain " << grains_[k].tag << "'s own disturbance is "
                  << isph::format_number(s, 3)
                  << " of its slip, above the correction's cap of 0.8 (its drag is raised at most "
                     "5x): the grain is not small against its porosity kernel; widen it with "
                     "unresolved.porosity_smoothing_diameters (told once)\n";
      }
    }
    factor[k] = 1.0 / (1.0 - std::min(s, kCap));
  }
  for (std::size_t k = 0; k < n; ++k) factor[k] = factor[owner_[k]];
  // Each particle's resistance by its grains' factors, shared as their drag is; the law's
  // Reynolds number at the slip undisturbed by the grains' own wakes.
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t i = rows[r];
    const double eps = P.porosity[i];
    if (!(eps < 1.0)) continue;
    double surface = 0.0, c = 0.0;
    for (std::size_t e = w.offset[r]; e < w.offset[r + 1]; ++e) {
      surface += w.surface[e];
      c += w.surface[e] * factor[w.grain[e]];
    }
    c /= surface;
    const double vr = c * (P.v[i] / eps - P.solid_velocity[i]).norm();
    P.resistance[i] = c * law_->coefficients(eps, vr, field_.diameter[r]).total(vr);
  }
}

template <int Dim>
void UnresolvedCoupling<Dim>::after_fluid_step(const DemState&, const isph::IsphSolver<Dim>& solver,
                                               double, DemLoads& loads) {
  const auto& P = solver.particles();
  const double rho = solver.config().density;
  // Particles were re-sorted inside the step; the map's rows follow the ids.
  std::vector<int> index_of(static_cast<std::size_t>(P.next_id), -1);
  for (std::size_t i = 0; i < P.size(); ++i) index_of[P.id[i]] = static_cast<int>(i);
  const std::size_t rows = mapped_ids_.size();
  std::vector<isph::Vec<Dim>> reaction(rows, isph::Vec<Dim>::Zero());
  std::vector<int> at(rows);
  const UnresolvedBalance<Dim> before = balance_;
  balance_ = {};
  balance_.max_self_induced = before.max_self_induced;
  balance_.self_induced_capped = before.self_induced_capped;
  for (std::size_t r = 0; r < rows; ++r) {
    const int i = index_of[mapped_ids_[r]];
    if (i < 0) throw std::logic_error("unresolved coupling: a mapped particle disappeared");
    at[r] = i;
    const double eps = P.porosity[i];
    // The implicit resistance of the step with the same K, at the final v_D.
    reaction[r] = eps * rho * P.volume * P.resistance[i] * (P.v[i] / eps - P.solid_velocity[i]);
    balance_.fluid_resistance -= depth_ * reaction[r];
  }
  const std::vector<isph::Vec<Dim>> grad_p = solver.pressure_gradient_at(at);
  GrainLoads<Dim> gl = distribute_reactions(field_.weights, grains_, reaction, depth_);
  // grad p at each grain: the kernel average of the particles' gradients over the same weights.
  std::vector<isph::Vec<Dim>> grad_at(grains_.size(), isph::Vec<Dim>::Zero());
  std::vector<double> wsum(grains_.size(), 0.0);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t e = field_.weights.offset[r]; e < field_.weights.offset[r + 1]; ++e) {
      const std::size_t k = field_.weights.grain[e];
      grad_at[k] += field_.weights.weight[e] * grad_p[r];
      wsum[k] += field_.weights.weight[e];
    }
  std::size_t floored = field_.floored;
  if (const isph::RowShare* ranks = solver.decomposition()) {
    // Decomposed, each process distributed its own particles' reactions: every grain takes the
    // shares of all processes (the same sums on every process, keyed by the grains' common order).
    std::vector<double> sums;
    for (std::size_t k = 0; k < grains_.size(); ++k) {
      for (int a = 0; a < Dim; ++a) sums.insert(sums.end(), {gl.force[k][a], grad_at[k][a]});
      sums.push_back(wsum[k]);
    }
    for (int a = 0; a < Dim; ++a) sums.push_back(balance_.fluid_resistance[a]);
    sums.push_back(double(field_.floored));
    if (!sums.empty()) ranks->sum_in_place(sums.data(), sums.size());
    std::size_t at = 0;
    for (std::size_t k = 0; k < grains_.size(); ++k) {
      for (int a = 0; a < Dim; ++a) gl.force[k][a] = sums[at++], grad_at[k][a] = sums[at++];
      wsum[k] = sums[at++];
    }
    for (int a = 0; a < Dim; ++a) balance_.fluid_resistance[a] = sums[at++];
    floored = static_cast<std::size_t>(sums[at]);
  }
  // Images are summed into their grain (same tag) before the pressure force: the real grain and
  // its images see one field from both sides of the periodic face.
  for (std::size_t k = 0; k < grains_.size(); ++k) {
    balance_.grain_drag += gl.force[k];
    const std::size_t o = owner_[k];
    if (o == k) continue;
    gl.force[o] += gl.force[k];
    grad_at[o] += grad_at[k];
    wsum[o] += wsum[k];
  }
  balance_.grains = 0;
  balance_.floored = floored;
  for (std::size_t k = 0; k < grains_.size(); ++k) {
    if (owner_[k] != k) continue;
    ++balance_.grains;
    const isph::Vec<Dim> g =
        wsum[k] > 0.0 ? isph::Vec<Dim>(grad_at[k] / wsum[k]) : isph::Vec<Dim>::Zero();
    const isph::Vec<Dim> fp = pressure_gradient_force<Dim>(g, grains_[k].volume());
    balance_.grain_pressure += fp;
    const isph::Vec<Dim> f = gl.force[k] + fp;
    loads.atom_tags.push_back(grains_[k].tag);
    Vec3 f3{0.0, 0.0, 0.0};
    for (int a = 0; a < Dim; ++a) f3[a] = f[a];
    loads.atom_force.push_back(f3);
    loads.atom_torque.push_back({0.0, 0.0, 0.0});
  }
}

template class UnresolvedCoupling<2>;
template class UnresolvedCoupling<3>;

}  // namespace isphdem
