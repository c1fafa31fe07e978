#pragma once
// Fills the /fluid group of the output contract from the particle arrays.
#include <cstddef>

#include "io/snapshot.hpp"
#include "particles.hpp"

namespace isphdem {

// Rows [first, last) of the storage order: on several ranks each gives the writer its own block
// (io/snapshot_layout.hpp), and the file holds them in rank order.
template <int Dim>
void add_fluid_group(const isph::Particles<Dim>& p, Snapshot& snapshot, std::size_t first,
                     std::size_t last);

}  // namespace isphdem
