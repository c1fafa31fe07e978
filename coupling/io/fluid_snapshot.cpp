#include "io/fluid_snapshot.hpp"

namespace isphdem {

template <int Dim>
void add_fluid_group(const isph::Particles<Dim>& p, Snapshot& snapshot) {
  Group& g = snapshot.group("fluid");
  const std::size_t n = p.size();
  // Eigen fixed-size vectors are stored contiguously, Dim doubles each.
  g.add("position", p.x.empty() ? nullptr : p.x[0].data(), n, Dim);
  g.add("velocity", p.v.empty() ? nullptr : p.v[0].data(), n, Dim);
  g.add("pressure", p.p.data(), n);
  g.add("porosity", p.porosity.data(), n);
  g.add("kind", p.kind.data(), n);
  g.add_generated<std::int32_t>("free_surface", n, 1, [&](std::size_t i, std::size_t) {
    return p.kind[i] != isph::kWall && p.surface[i] ? 1 : 0;
  });
  g.add("id", p.id.data(), n);
}

template void add_fluid_group<2>(const isph::Particles<2>&, Snapshot&);
template void add_fluid_group<3>(const isph::Particles<3>&, Snapshot&);

}  // namespace isphdem
