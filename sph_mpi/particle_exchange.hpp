#pragma once
// Moving the decomposed fluid between ranks (issue 26): each rank holds the particles its
// RcbTree box owns, followed by a halo, read-only copies of other ranks' particles within a
// kernel support or more of its box, so that every kernel sum over an owned particle is complete
// on its rank. Positions stay wrapped into the domain; the neighbour search takes the periodic
// images, as on one rank. All collective over comm.
#include <mpi.h>

#include <vector>

#include "particle_records.hpp"
#include "particles.hpp"
#include "rcb_tree.hpp"

namespace isph {

// Sends every particle (all its arrays) to the rank whose box holds it. Call without a halo.
template <int Dim>
void migrate(MPI_Comm comm, const RcbTree<Dim>& tree, Particles<Dim>& p);

// Which owned particles went to which rank as halo, and where the halo starts.
struct HaloPlan {
  int owned = 0;                 // particles [0, owned) are this rank's; the halo follows
  std::vector<int> send_index;   // owned particles sent, grouped by destination rank
  std::vector<int> send_counts;  // per rank
  std::vector<int> recv_counts;  // per rank, in the order the halo holds them
  int halo() const {
    int h = 0;
    for (int c : recv_counts) h += c;
    return h;
  }
};

// Appends the halo: every particle of another rank closer than `width` to this rank's box.
template <int Dim>
HaloPlan add_halo(MPI_Comm comm, const RcbTree<Dim>& tree, double width, Particles<Dim>& p);

// The owners' current values of one per-particle array into the halo's copies: `rows` holds
// owned + halo rows of row_bytes bytes each.
void refresh_halo_rows(MPI_Comm comm, const HaloPlan& plan, void* rows, std::size_t row_bytes);

template <class T>
void refresh_halo(MPI_Comm comm, const HaloPlan& plan, std::vector<T>& values) {
  values.resize(plan.owned + plan.halo());
  refresh_halo_rows(comm, plan, values.data(), sizeof(T));
}

// Back to the owned particles alone.
template <int Dim>
void drop_halo(const HaloPlan& plan, Particles<Dim>& p) {
  p.for_each_array([&](auto& a) { a.resize(plan.owned); });
}

}  // namespace isph
