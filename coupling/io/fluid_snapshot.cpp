#include "io/fluid_snapshot.hpp"

#include <stdexcept>
#include <string>

namespace isphdem {

template <int Dim>
void add_fluid_group(const isph::Particles<Dim>& p, Snapshot& snapshot, std::size_t first,
                     std::size_t last) {
  if (first > last || last > p.size())
    throw std::invalid_argument("fluid rows [" + std::to_string(first) + ", " +
                                std::to_string(last) + ") outside the " + std::to_string(p.size()) +
                                " particles");
  Group& g = snapshot.group("fluid");
  const std::size_t n = last - first;
  // Eigen fixed-size vectors are stored contiguously, Dim doubles each.
  g.add("position", n ? p.x[first].data() : nullptr, n, Dim);
  g.add("velocity", n ? p.v[first].data() : nullptr, n, Dim);
  g.add("pressure", p.p.data() + first, n);
  g.add("porosity", p.porosity.data() + first, n);
  g.add("kind", p.kind.data() + first, n);
  g.add_generated<std::int32_t>("free_surface", n, 1, [&](std::size_t i, std::size_t) {
    return p.kind[first + i] != isph::kWall && p.surface[first + i] ? 1 : 0;
  });
  g.add("id", p.id.data() + first, n);
}

template void add_fluid_group<2>(const isph::Particles<2>&, Snapshot&, std::size_t, std::size_t);
template void add_fluid_group<3>(const isph::Particles<3>&, Snapshot&, std::size_t, std::size_t);

}  // namespace isphdem
