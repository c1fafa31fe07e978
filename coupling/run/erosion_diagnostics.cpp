#include "run/erosion_diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isphdem {

double bed_height(const DemState& state, const Vec3& up) {
  std::vector<double> h;
  for (const auto& a : state.atoms)
    if (a.body == -1) h.push_back(a.x[0] * up[0] + a.x[1] * up[1] + a.x[2] * up[2]);
  if (h.empty()) return std::nan("");
  std::sort(h.begin(), h.end());
  if (h.size() < 20) return h.back();
  return h[static_cast<std::size_t>(0.95 * double(h.size() - 1))];
}

void set_pore_speeds(ErosionMeasures& m) {
  std::vector<double>& r = m.pore_speed_ratios;
  m.max_pore_speed_ratio = m.pore_speed_p95_ratio = m.mean_pore_speed_ratio = 0.0;
  if (r.empty()) return;
  std::sort(r.begin(), r.end());
  m.max_pore_speed_ratio = r.back();
  const double at = 0.95 * double(r.size() - 1);
  const std::size_t k = static_cast<std::size_t>(at);
  const double f = at - double(k);
  m.pore_speed_p95_ratio = k + 1 < r.size() ? (1 - f) * r[k] + f * r[k + 1] : r[k];
  double sum = 0.0;
  for (double x : r) sum += x;
  m.mean_pore_speed_ratio = sum / double(r.size());
}

template <int Dim>
int ErosionDiagnostics<Dim>::across_axis() const {
  // The horizontal axis of the fluid plane: the first axis with no gravity component.
  for (int a = 0; a < Dim; ++a)
    if (std::abs(up_[a]) < 0.5) return a;
  return 0;
}

template <int Dim>
ErosionDiagnostics<Dim>::ErosionDiagnostics(const DemState& initial, const Vec3& up,
                                            double reference_speed, double grain_density)
    : up_(up),
      reference_speed_(reference_speed > 0 ? reference_speed : 1.0),
      grain_density_(grain_density) {
  const int h = across_axis();
  surface0_ = -std::numeric_limits<double>::infinity();
  bottom0_ = std::numeric_limits<double>::infinity();
  lo0_ = std::numeric_limits<double>::infinity();
  hi0_ = -lo0_;
  for (const auto& a : initial.atoms) {
    surface0_ = std::max(surface0_, height(a.x) + a.radius);
    bottom0_ = std::min(bottom0_, height(a.x) - a.radius);
    lo0_ = std::min(lo0_, a.x[h] - a.radius);
    hi0_ = std::max(hi0_, a.x[h] + a.radius);
  }
  for (const auto& b : initial.bodies) body0_[b.id] = b.x;
}

template <int Dim>
std::vector<double> ErosionDiagnostics<Dim>::state() const {
  std::vector<double> s{surface0_, bottom0_, lo0_, hi0_};
  for (const auto& [id, x] : body0_) s.insert(s.end(), {double(id), x[0], x[1], x[2]});
  return s;
}

template <int Dim>
void ErosionDiagnostics<Dim>::restore(const std::vector<double>& s) {
  if (s.size() < 4 || (s.size() - 4) % 4 != 0)
    throw std::runtime_error("erosion diagnostics: the checkpoint holds no initial layer");
  surface0_ = s[0];
  bottom0_ = s[1];
  lo0_ = s[2];
  hi0_ = s[3];
  body0_.clear();
  for (std::size_t k = 4; k < s.size(); k += 4)
    body0_[int(s[k])] = Vec3{s[k + 1], s[k + 2], s[k + 3]};
}

template <int Dim>
ErosionMeasures ErosionDiagnostics<Dim>::measure(const DemState& dem,
                                                 const isph::Particles<Dim>& fluid) const {
  ErosionMeasures m;
  if (dem.atoms.empty()) return m;
  const int h = across_axis();
  constexpr double kColumn = 2e-3;
  const int columns = std::max(1, static_cast<int>(std::ceil((hi0_ - lo0_) / kColumn)));
  std::vector<double> top(columns, -std::numeric_limits<double>::infinity());
  int fines = 0;
  for (const auto& a : dem.atoms) {
    const double z = height(a.x);
    if (a.body == -1) {
      m.mean_fine_speed += norm(a.v);
      ++fines;
    }
    if (a.body == -1 && z - a.radius > surface0_) {
      ++m.fines_above;
      m.fines_above_mass += grain_density_ * 4.0 / 3.0 * M_PI * a.radius * a.radius * a.radius;
    }
    if (a.body == -1 && (a.x[h] < lo0_ || a.x[h] > hi0_ || z < bottom0_)) ++m.fines_out_of_window;
    const int c = static_cast<int>(std::floor((a.x[h] - lo0_) / kColumn));
    if (c >= 0 && c < columns) top[c] = std::max(top[c], z + a.radius);
  }
  if (fines) m.mean_fine_speed /= fines;
  for (const auto& b : dem.bodies) m.mean_clump_speed += norm(b.v);
  if (!dem.bodies.empty()) m.mean_clump_speed /= double(dem.bodies.size());
  std::vector<double> filled;
  for (double t : top)
    if (std::isfinite(t)) filled.push_back(t);
  if (!filled.empty()) {
    std::nth_element(filled.begin(), filled.begin() + filled.size() / 2, filled.end());
    m.surface_height = filled[filled.size() / 2];
  }
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (fluid.kind[i] != isph::kFluid) continue;
    Vec3 x{0, 0, 0};
    for (int a = 0; a < Dim; ++a) x[a] = fluid.x[i][a];
    const double z = height(x);
    if (z < bottom0_ || z > surface0_ || x[h] < lo0_ || x[h] > hi0_) continue;
    const double eps = fluid.porosity[i] > 0 ? fluid.porosity[i] : 1.0;
    m.pore_speed_ratios.push_back(fluid.v[i].norm() / eps / reference_speed_);
  }
  set_pore_speeds(m);
  int n = 0;
  for (const auto& b : dem.bodies) {
    const auto it = body0_.find(b.id);
    if (it == body0_.end()) continue;
    double d2 = 0;
    for (int a = 0; a < Dim; ++a) d2 += (b.x[a] - it->second[a]) * (b.x[a] - it->second[a]);
    m.skeleton_displacement += std::sqrt(d2);
    ++n;
  }
  if (n) m.skeleton_displacement /= n;
  return m;
}

template <int Dim>
std::vector<std::string> ErosionDiagnostics<Dim>::columns() {
  return {"fines_above_surface",  "fines_above_mass",      "fines_out_of_window",
          "max_pore_speed_ratio", "surface_height",        "skeleton_displacement",
          "pore_speed_p95_ratio", "mean_pore_speed_ratio", "mean_fine_speed",
          "mean_clump_speed"};
}

template <int Dim>
std::vector<double> ErosionDiagnostics<Dim>::row(const ErosionMeasures& m) {
  return {double(m.fines_above),  m.fines_above_mass,      double(m.fines_out_of_window),
          m.max_pore_speed_ratio, m.surface_height,        m.skeleton_displacement,
          m.pore_speed_p95_ratio, m.mean_pore_speed_ratio, m.mean_fine_speed,
          m.mean_clump_speed};
}

template class ErosionDiagnostics<2>;
template class ErosionDiagnostics<3>;

}  // namespace isphdem
