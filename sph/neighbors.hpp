#pragma once
// Neighbour relations in compressed rows, with the pair geometry (r_ij, W_ij, grad W_ij)
// evaluated once per step and reused by every operator.
#include <vector>

#include "domain.hpp"
#include "kernel.hpp"
#include "particles.hpp"

namespace isph {

template <int Dim>
struct Neighbors {
  std::vector<int> offset;    // size N+1; pairs of i are [offset[i], offset[i+1])
  std::vector<int> index;     // j
  std::vector<Vec<Dim>> rij;  // x_i - x_j (minimum image)
  std::vector<double> r;      // |r_ij|
  std::vector<double> w;      // W(r_ij)
  std::vector<Vec<Dim>> dw;   // grad_i W_ij = W'(r) r_ij / r
  double w_self = 0.0;        // W(0)

  std::size_t size() const { return offset.empty() ? 0 : offset.size() - 1; }
  int begin(int i) const { return offset[i]; }
  int end(int i) const { return offset[i + 1]; }
  std::size_t pairs() const { return index.size(); }
};

// Cell-list search. Cells are at least one support radius wide; particles are re-sorted by cell
// so that neighbours sit close in memory.
template <int Dim>
class NeighborSearch {
 public:
  NeighborSearch(const Domain<Dim>& domain, double cutoff);

  // Reorders all particle arrays by cell index (stable). Returns perm: new n holds old perm[n].
  std::vector<int> sort(Particles<Dim>& particles);

  // Builds the full (i->j and j->i) neighbour list with pair geometry, for the rows
  // [first, last) (last < 0: to the end); other rows are left empty (sph/row_share.hpp).
  void build(const Particles<Dim>& particles, const Kernel<Dim>& kernel, Neighbors<Dim>& out,
             int first = 0, int last = -1);

  double cutoff() const { return cutoff_; }

 private:
  void make_grid(const Particles<Dim>& particles);
  int cell_of(const Vec<Dim>& x) const;

  // The pairs each thread found in build(), kept between steps for their capacity.
  struct Candidate {
    int j;
    Vec<Dim> d;
    double r2;
  };
  std::vector<std::vector<Candidate>> found_;

  Domain<Dim> domain_;
  double cutoff_;
  Vec<Dim> origin_;
  Vec<Dim> cell_size_;
  Eigen::Matrix<int, Dim, 1> ncell_;
  std::vector<int> cell_start_;  // size ncells+1, into the cell-sorted order
  std::vector<int> cell_items_;  // particle indices sorted by cell
};

}  // namespace isph
