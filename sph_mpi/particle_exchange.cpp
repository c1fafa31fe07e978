#include "particle_exchange.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace isph {

namespace {

// Indices grouped by destination (stable within a destination) and the count per rank.
std::vector<int> grouped(const std::vector<std::pair<int, int>>& to, int size,
                         std::vector<int>& counts) {
  counts.assign(size, 0);
  for (const auto& [rank, i] : to) ++counts[rank];
  std::vector<int> start(size, 0);
  std::partial_sum(counts.begin(), counts.end() - 1, start.begin() + 1);
  std::vector<int> order(to.size());
  for (const auto& [rank, i] : to) order[start[rank]++] = i;
  return order;
}

}  // namespace

template <int Dim>
void migrate(MPI_Comm comm, const RcbTree<Dim>& tree, Particles<Dim>& p) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<std::pair<int, int>> to(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) to[i] = {tree.owner(p.x[i]), static_cast<int>(i)};
  std::vector<int> counts, recv_counts;
  const std::vector<int> order = grouped(to, size, counts);
  const std::vector<char> recv = records::alltoallv(comm, records::pack(p, order), counts,
                                                    records::record_bytes(p), recv_counts);
  records::unpack(recv, p, 0);
}

template <int Dim>
HaloPlan add_halo(MPI_Comm comm, const RcbTree<Dim>& tree, double width, Particles<Dim>& p) {
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  HaloPlan plan;
  plan.owned = static_cast<int>(p.size());
  // Every owned particle against the boxes within `width` of this rank's box only (an owned
  // particle lies in that box): O(N) per rank for a fixed number of neighbouring boxes.
  std::vector<int> near;
  for (int r = 0; r < size; ++r)
    if (r != rank && tree.box_distance(rank, r) < width) near.push_back(r);
  std::vector<std::pair<int, int>> to;
  for (int i = 0; i < plan.owned; ++i)
    for (const int r : near)
      if (tree.distance(p.x[i], r) < width) to.emplace_back(r, i);
  plan.send_index = grouped(to, size, plan.send_counts);
  const std::vector<char> recv =
      records::alltoallv(comm, records::pack(p, plan.send_index), plan.send_counts,
                         records::record_bytes(p), plan.recv_counts);
  records::unpack(recv, p, plan.owned);
  return plan;
}

void refresh_halo_rows(MPI_Comm comm, const HaloPlan& plan, void* rows, std::size_t row_bytes) {
  char* data = static_cast<char*>(rows);
  std::vector<char> send(plan.send_index.size() * row_bytes);
  for (std::size_t k = 0; k < plan.send_index.size(); ++k)
    std::memcpy(send.data() + k * row_bytes, data + plan.send_index[k] * row_bytes, row_bytes);
  // The counts are the plan's: one MPI_Alltoallv per refresh, no exchange of counts first (the
  // stages refresh some 13 arrays per step).
  records::alltoallv_into(comm, send.data(), plan.send_counts, plan.recv_counts, row_bytes,
                          data + static_cast<std::size_t>(plan.owned) * row_bytes);
}

template void migrate<2>(MPI_Comm, const RcbTree<2>&, Particles<2>&);
template void migrate<3>(MPI_Comm, const RcbTree<3>&, Particles<3>&);
template HaloPlan add_halo<2>(MPI_Comm, const RcbTree<2>&, double, Particles<2>&);
template HaloPlan add_halo<3>(MPI_Comm, const RcbTree<3>&, double, Particles<3>&);

}  // namespace isph
