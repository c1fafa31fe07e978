#pragma once
// Recursive coordinate bisection of the fluid over MPI ranks (issue 26, the decomposed fluid):
// the domain is cut, its longest side first, where the particle count splits in proportion to the
// ranks on either side, until every rank has a box of its own. Built collectively from the
// particles each rank holds, rebuilt when the load drifts; the same tree on every rank.
#include <mpi.h>

#include <vector>

#include "domain.hpp"
#include "vec.hpp"

namespace isph {

template <int Dim>
class RcbTree {
 public:
  // Collective over comm. `points`: this rank's particles (any subset; together all of them).
  static RcbTree build(MPI_Comm comm, const Domain<Dim>& domain,
                       const std::vector<Vec<Dim>>& points);

  int ranks() const { return static_cast<int>(lo_.size()); }
  // The rank whose box holds x (x is wrapped into the domain along periodic axes first).
  int owner(Vec<Dim> x) const;
  const Vec<Dim>& lo(int rank) const { return lo_[rank]; }
  const Vec<Dim>& hi(int rank) const { return hi_[rank]; }
  // Shortest distance from x to the rank's box, across periodic boundaries too (0 inside).
  double distance(const Vec<Dim>& x, int rank) const;
  // Shortest distance between two ranks' boxes, across periodic boundaries too (0 touching).
  double box_distance(int a, int b) const;

 private:
  struct Node {
    int axis = -1;  // -1: a leaf, the box of `rank`
    double cut = 0.0;
    int below = -1, above = -1;  // children: x[axis] < cut, and the rest
    int rank = -1;
  };
  Domain<Dim> domain_;
  std::vector<Node> nodes_;
  std::vector<Vec<Dim>> lo_, hi_;
};

}  // namespace isph
