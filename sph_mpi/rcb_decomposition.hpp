#pragma once
// The fluid decomposed over the ranks of a communicator by recursive coordinate bisection
// (sph/decomposition.hpp): migration to the owners of the RCB boxes, the tree re-cut when the
// largest rank holds more than `rebalance` times the mean, the halo and its refreshes, and the
// global numbering of the pressure equation. Every call is collective over the communicator.
#include <mpi.h>

#include <memory>
#include <optional>

#include "decomposition.hpp"
#include "domain.hpp"
#include "particle_exchange.hpp"
#include "rcb_tree.hpp"

namespace isph {

template <int Dim>
class RcbDecomposition : public Decomposition<Dim> {
 public:
  RcbDecomposition(MPI_Comm comm, const Domain<Dim>& domain, double rebalance = 1.1);

  int parts() const override { return parts_; }
  int part() const override { return part_; }
  int first(int /*n*/) const override { return 0; }
  int last(int n) const override { return halo_ ? plan_.owned : n; }

  int64_t migrate(Particles<Dim>& p, std::vector<double>* carried) override;
  void add_halo(Particles<Dim>& p, double width) override;
  void drop_halo(Particles<Dim>& p) override;
  std::shared_ptr<const GlobalNumbering> numbering() const override { return numbering_; }

  void exchange_rows(void* data, std::size_t row_bytes, int n) const override;
  std::vector<char> concatenate_bytes(const std::vector<char>& mine) const override;
  double sum(double x) const override;
  void sum_in_place(double* data, std::size_t count) const override;
  double max(double x) const override;

  // How often the boxes were cut (the first cut included).
  int cuts() const { return cuts_; }
  const RcbTree<Dim>& tree() const { return *tree_; }

 private:
  MPI_Comm comm_;
  Domain<Dim> domain_;
  double rebalance_;
  int parts_ = 1, part_ = 0;
  std::optional<RcbTree<Dim>> tree_;
  int cuts_ = 0;
  bool halo_ = false;
  HaloPlan plan_;
  std::shared_ptr<const GlobalNumbering> numbering_;
};

}  // namespace isph
