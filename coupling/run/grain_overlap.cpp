#include "run/grain_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace isphdem {

GrainOverlap deepest_overlap(const DemState& state) {
  GrainOverlap deepest;
  const auto& atoms = state.atoms;
  if (atoms.size() < 2) return deepest;
  double rmax = 0.0;
  for (const auto& a : atoms) rmax = std::max(rmax, a.radius);
  if (!(rmax > 0.0)) return deepest;
  // Cells of the largest diameter: every touching pair is in the same or a neighbouring cell.
  const double cell = 2.0 * rmax;
  auto key = [](long i, long j, long k) {
    return (static_cast<unsigned long>(i) * 73856093UL) ^
           (static_cast<unsigned long>(j) * 19349663UL) ^
           (static_cast<unsigned long>(k) * 83492791UL);
  };
  auto index = [&](double x) { return static_cast<long>(std::floor(x / cell)); };
  std::unordered_multimap<unsigned long, int> cells;
  cells.reserve(atoms.size());
  for (std::size_t n = 0; n < atoms.size(); ++n)
    cells.emplace(key(index(atoms[n].x[0]), index(atoms[n].x[1]), index(atoms[n].x[2])), int(n));
  for (std::size_t n = 0; n < atoms.size(); ++n) {
    const DemAtom& a = atoms[n];
    const long ci = index(a.x[0]), cj = index(a.x[1]), ck = index(a.x[2]);
    for (long di = -1; di <= 1; ++di)
      for (long dj = -1; dj <= 1; ++dj)
        for (long dk = -1; dk <= 1; ++dk) {
          const auto range = cells.equal_range(key(ci + di, cj + dj, ck + dk));
          for (auto it = range.first; it != range.second; ++it) {
            if (it->second <= int(n)) continue;  // each pair once (and hash collisions harmless)
            const DemAtom& b = atoms[it->second];
            if (a.body >= 0 && a.body == b.body) continue;
            double d2 = 0.0;
            for (int c = 0; c < 3; ++c) d2 += (a.x[c] - b.x[c]) * (a.x[c] - b.x[c]);
            const double overlap = a.radius + b.radius - std::sqrt(d2);
            if (overlap <= 0.0) continue;
            const double relative = overlap / std::min(a.radius, b.radius);
            if (relative > deepest.relative) deepest = {relative, a.tag, b.tag};
          }
        }
  }
  return deepest;
}

}  // namespace isphdem
