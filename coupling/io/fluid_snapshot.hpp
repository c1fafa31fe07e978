#pragma once
// Fills the /fluid group of the output contract from the particle arrays.
#include "io/snapshot.hpp"
#include "particles.hpp"

namespace isphdem {

template <int Dim>
void add_fluid_group(const isph::Particles<Dim>& p, Snapshot& snapshot);

}  // namespace isphdem
