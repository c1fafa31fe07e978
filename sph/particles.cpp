#include "particles.hpp"

#include <algorithm>

namespace isph {

template <int Dim>
void Particles<Dim>::add(const Vec<Dim>& pos, const Vec<Dim>& vel, int32_t k) {
  if (keep_parts > 1 && next_id % keep_parts != keep_part) {
    ++next_id;
    return;
  }
  x.push_back(pos);
  v.push_back(vel);
  p.push_back(0.0);
  porosity.push_back(1.0);
  solid_velocity.push_back(Vec<Dim>::Zero());
  resistance.push_back(0.0);
  kind.push_back(k);
  id.push_back(next_id++);
  surface.push_back(0);
  normal.push_back(Vec<Dim>::Zero());
  wall_distance.push_back(0.0);
  body.push_back(-1);
  body_offset.push_back(Vec<Dim>::Zero());
  body_normal.push_back(Vec<Dim>::Zero());
  solid_force.push_back(Vec<Dim>::Zero());
}

template <int Dim>
void Particles<Dim>::permute(const std::vector<int>& perm) {
  for_each_array([&](auto& a) {
    std::remove_reference_t<decltype(a)> out(a.size());
    for (std::size_t n = 0; n < perm.size(); ++n) out[n] = a[perm[n]];
    a.swap(out);
  });
}

template <int Dim>
std::size_t Particles<Dim>::count(int32_t k) const {
  return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), k));
}

template struct Particles<2>;
template struct Particles<3>;

}  // namespace isph
