#include "rcb_tree.hpp"

#include <algorithm>
#include <cmath>

namespace isph {

namespace {

// Enough halvings of a cut's interval to place it between two particles 1e-12 of the box apart.
constexpr int kBisections = 48;

}  // namespace

template <int Dim>
RcbTree<Dim> RcbTree<Dim>::build(MPI_Comm comm, const Domain<Dim>& domain,
                                 const std::vector<Vec<Dim>>& points) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  RcbTree t;
  t.domain_ = domain;
  t.lo_.assign(size, domain.lo);
  t.hi_.assign(size, domain.hi);
  struct Open {
    int node, first, end;  // ranks [first, end)
    Vec<Dim> lo, hi;
  };
  t.nodes_.push_back({});
  std::vector<Open> open{{0, 0, size, domain.lo, domain.hi}};
  std::vector<int> at(points.size(), 0);  // each point's node
  // One level of the tree per pass: every rank takes part in every node's reductions, so all
  // ranks make the same calls and build the same tree.
  while (!open.empty()) {
    std::vector<Open> split, next;
    for (const Open& o : open) {
      if (o.end - o.first == 1) {
        t.nodes_[o.node].rank = o.first;
        t.lo_[o.first] = o.lo;
        t.hi_[o.first] = o.hi;
      } else {
        split.push_back(o);
      }
    }
    const int n = static_cast<int>(split.size());
    if (n == 0) break;
    std::vector<int> axis(n), slot(t.nodes_.size(), -1);
    std::vector<double> lo(n), hi(n), share(n);
    for (int k = 0; k < n; ++k) {
      const Open& o = split[k];
      Vec<Dim> extent = o.hi - o.lo;
      extent.maxCoeff(&axis[k]);
      lo[k] = o.lo[axis[k]];
      hi[k] = o.hi[axis[k]];
      share[k] = double((o.end - o.first) / 2) / (o.end - o.first);
      slot[o.node] = k;
    }
    std::vector<double> total(n, 0.0), below(n);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (slot[at[i]] >= 0) total[slot[at[i]]] += 1.0;
    MPI_Allreduce(MPI_IN_PLACE, total.data(), n, MPI_DOUBLE, MPI_SUM, comm);
    // The smallest cut with at least `share` of the node's particles below it.
    for (int it = 0; it < kBisections; ++it) {
      std::fill(below.begin(), below.end(), 0.0);
      for (std::size_t i = 0; i < points.size(); ++i) {
        const int k = slot[at[i]];
        if (k >= 0 && points[i][axis[k]] < 0.5 * (lo[k] + hi[k])) below[k] += 1.0;
      }
      MPI_Allreduce(MPI_IN_PLACE, below.data(), n, MPI_DOUBLE, MPI_SUM, comm);
      for (int k = 0; k < n; ++k) {
        const double mid = 0.5 * (lo[k] + hi[k]);
        if (below[k] >= share[k] * total[k])
          hi[k] = mid;
        else
          lo[k] = mid;
      }
    }
    for (int k = 0; k < n; ++k) {
      const Open& o = split[k];
      // An empty node is cut in the middle.
      const double cut = total[k] > 0.0 ? hi[k] : 0.5 * (o.lo[axis[k]] + o.hi[axis[k]]);
      const int middle = o.first + (o.end - o.first) / 2;
      const int b = static_cast<int>(t.nodes_.size());
      t.nodes_.push_back({});
      t.nodes_.push_back({});
      Node& node = t.nodes_[o.node];
      node.axis = axis[k];
      node.cut = cut;
      node.below = b;
      node.above = b + 1;
      Vec<Dim> split_hi = o.hi, split_lo = o.lo;
      split_hi[axis[k]] = cut;
      split_lo[axis[k]] = cut;
      next.push_back({b, o.first, middle, o.lo, split_hi});
      next.push_back({b + 1, middle, o.end, split_lo, o.hi});
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Node& node = t.nodes_[at[i]];
      if (node.axis >= 0) at[i] = points[i][node.axis] < node.cut ? node.below : node.above;
    }
    open = std::move(next);
  }
  return t;
}

template <int Dim>
int RcbTree<Dim>::owner(Vec<Dim> x) const {
  domain_.wrap(x);
  int k = 0;
  while (nodes_[k].axis >= 0)
    k = x[nodes_[k].axis] < nodes_[k].cut ? nodes_[k].below : nodes_[k].above;
  return nodes_[k].rank;
}

template <int Dim>
double RcbTree<Dim>::distance(const Vec<Dim>& x, int rank) const {
  double d2 = 0.0;
  for (int a = 0; a < Dim; ++a) {
    auto gap = [&](double y) { return std::max({lo_[rank][a] - y, y - hi_[rank][a], 0.0}); };
    double g = gap(x[a]);
    if (domain_.periodic[a]) {
      const double L = domain_.hi[a] - domain_.lo[a];
      g = std::min({g, gap(x[a] - L), gap(x[a] + L)});
    }
    d2 += g * g;
  }
  return std::sqrt(d2);
}

template <int Dim>
double RcbTree<Dim>::box_distance(int a, int b) const {
  double d2 = 0.0;
  for (int k = 0; k < Dim; ++k) {
    auto gap = [&](double shift) {
      return std::max({lo_[b][k] + shift - hi_[a][k], lo_[a][k] - hi_[b][k] - shift, 0.0});
    };
    double g = gap(0.0);
    if (domain_.periodic[k]) {
      const double L = domain_.hi[k] - domain_.lo[k];
      g = std::min({g, gap(-L), gap(L)});
    }
    d2 += g * g;
  }
  return std::sqrt(d2);
}

template class RcbTree<2>;
template class RcbTree<3>;

}  // namespace isph
