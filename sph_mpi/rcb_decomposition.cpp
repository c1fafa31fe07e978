#include "rcb_decomposition.hpp"

#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "global_numbering.hpp"
#include "mpi_collectives.hpp"

namespace isph {

template <int Dim>
RcbDecomposition<Dim>::RcbDecomposition(MPI_Comm comm, const Domain<Dim>& domain, double rebalance)
    : comm_(comm), domain_(domain), rebalance_(rebalance) {
  MPI_Comm_size(comm_, &parts_);
  MPI_Comm_rank(comm_, &part_);
}

template <int Dim>
int64_t RcbDecomposition<Dim>::migrate(Particles<Dim>& p, std::vector<double>* carried) {
  if (halo_) throw std::logic_error("RcbDecomposition::migrate with the halo still attached");
  // A dam-break front running out leaves the first cut's boxes unevenly filled.
  int64_t counts[2] = {static_cast<int64_t>(p.size()), static_cast<int64_t>(p.size())};
  MPI_Allreduce(MPI_IN_PLACE, &counts[0], 1, MPI_INT64_T, MPI_MAX, comm_);
  MPI_Allreduce(MPI_IN_PLACE, &counts[1], 1, MPI_INT64_T, MPI_SUM, comm_);
  if (!tree_ || double(counts[0]) > rebalance_ * double(counts[1]) / parts_) {
    tree_ = RcbTree<Dim>::build(comm_, domain_, p.x);
    ++cuts_;
  }
  std::vector<int> owner(p.size());
  int64_t leaving = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    owner[i] = tree_->owner(p.x[i]);
    leaving += owner[i] != part_;
  }
  MPI_Allreduce(MPI_IN_PLACE, &leaving, 1, MPI_INT64_T, MPI_SUM, comm_);
  if (leaving == 0) return 0;
  if (!carried) {
    isph::migrate(comm_, *tree_, p);
    return leaving;
  }
  // The carried values travel as (id, value) to the same owners, and are put back in the order
  // the migrated particles arrive in.
  struct Item {
    int64_t id;
    double value;
  };
  std::vector<std::vector<Item>> to(parts_);
  for (std::size_t i = 0; i < p.size(); ++i) to[owner[i]].push_back({p.id[i], (*carried)[i]});
  std::vector<char> send;
  std::vector<int> items(parts_);
  for (int r = 0; r < parts_; ++r) {
    items[r] = static_cast<int>(to[r].size());
    const char* bytes = reinterpret_cast<const char*>(to[r].data());
    send.insert(send.end(), bytes, bytes + to[r].size() * sizeof(Item));
  }
  std::vector<int> recv_counts;
  const std::vector<char> recv = records::alltoallv(comm_, send, items, sizeof(Item), recv_counts);
  isph::migrate(comm_, *tree_, p);
  std::unordered_map<int64_t, double> value_of;
  for (std::size_t k = 0; k < recv.size() / sizeof(Item); ++k) {
    Item item;
    std::memcpy(&item, recv.data() + k * sizeof(Item), sizeof(Item));
    value_of[item.id] = item.value;
  }
  carried->resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) (*carried)[i] = value_of.at(p.id[i]);
  return leaving;
}

template <int Dim>
void RcbDecomposition<Dim>::add_halo(Particles<Dim>& p, double width) {
  if (halo_) throw std::logic_error("RcbDecomposition::add_halo twice");
  plan_ = isph::add_halo(comm_, *tree_, width, p);
  numbering_ = std::make_shared<GlobalNumbering>(number_globally(comm_, plan_));
  halo_ = true;
}

template <int Dim>
void RcbDecomposition<Dim>::drop_halo(Particles<Dim>& p) {
  if (!halo_) return;
  isph::drop_halo(plan_, p);
  halo_ = false;
}

template <int Dim>
void RcbDecomposition<Dim>::exchange_rows(void* data, std::size_t row_bytes, int n) const {
  if (!halo_ || n != plan_.owned + plan_.halo())
    throw std::logic_error("halo refresh of " + std::to_string(n) + " rows; the halo holds " +
                           std::to_string(plan_.owned) + " owned + " +
                           std::to_string(plan_.halo()) + " halo rows");
  refresh_halo_rows(comm_, plan_, data, row_bytes);
}

template <int Dim>
std::vector<char> RcbDecomposition<Dim>::concatenate_bytes(const std::vector<char>& mine) const {
  return collectives::concatenate(comm_, mine);
}

template <int Dim>
double RcbDecomposition<Dim>::sum(double x) const {
  return collectives::sum(comm_, x);
}

template <int Dim>
void RcbDecomposition<Dim>::sum_in_place(double* data, std::size_t count) const {
  collectives::sum_in_place(comm_, data, count);
}

template <int Dim>
double RcbDecomposition<Dim>::max(double x) const {
  return collectives::max(comm_, x);
}

template class RcbDecomposition<2>;
template class RcbDecomposition<3>;

}  // namespace isph
