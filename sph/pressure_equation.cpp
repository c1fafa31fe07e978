#include "pressure_equation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace isph {

template <int Dim>
void remove_net_source(const Particles<Dim>& particles, std::vector<double>& rhs,
                       const RowShare* decomposed) {
  const int all = static_cast<int>(particles.size());
  const int first = decomposed ? decomposed->first(all) : 0;
  const int last = decomposed ? decomposed->last(all) : all;
  double sum = 0.0, n = 0.0, surface = 0.0;
  for (int i = first; i < last && surface == 0.0; ++i) {
    if (particles.kind[i] == kWall) continue;
    surface = particles.surface[i];
    sum += rhs[i];
    n += 1.0;
  }
  if (decomposed) {
    surface = decomposed->max(surface);
    sum = decomposed->sum(sum);
    n = decomposed->sum(n);
  }
  if (surface > 0.0 || n == 0.0) return;  // a Dirichlet row sets the level: nothing to remove
  const double mean = sum / n;
  for (int i = first; i < last; ++i)
    if (particles.kind[i] != kWall) rhs[i] -= mean;
}

template <int Dim>
void assemble_pressure(const Particles<Dim>& particles, const Neighbors<Dim>& nb,
                       const Operators<Dim>& op, const std::vector<double>& rhs,
                       const Vec<Dim>& gravity, double rho0, double h, PressureSystem<Dim>& out,
                       const std::vector<double>* coefficient,
                       const std::vector<double>* surface_depth, const RowShare* decomposed) {
  const int n = static_cast<int>(particles.size());
  // Interior rows are scaled by h^2 so that all rows have O(1) coefficients.
  const double scale = h * h;
  const int first = decomposed ? decomposed->first(n) : 0;
  const int last = decomposed ? decomposed->last(n) : n;

  bool has_dirichlet = false;
  for (int i = first; i < last; ++i)
    if (particles.kind[i] != kWall && particles.surface[i]) has_dirichlet = true;
  if (decomposed) has_dirichlet = decomposed->max(has_dirichlet ? 1.0 : 0.0) > 0.0;
  // The pinned particle is the one with the smallest id, not the first in storage order: the
  // storage is re-sorted by cell every step, and spread_pinned_source can reuse its second
  // solution only while the same particle is pinned (in the closed tank of
  // examples/fluidization_2d the first-in-order choice changed often enough to make that
  // solve the largest part of the pressure cost).
  out.pinned = -1;
  out.pinned_id = -1;
  out.pin_row.clear();
  if (!has_dirichlet) {
    for (int i = first; i < last; ++i)
      if (particles.kind[i] != kWall && op.order[i] > 0 &&
          (out.pinned < 0 || particles.id[i] < particles.id[out.pinned]))
        out.pinned = i;
    out.pinned_id = out.pinned >= 0 ? particles.id[out.pinned] : -1;
    if (decomposed) {
      // Ids are far below 2^53: exact as doubles. The smallest as minus the largest negative.
      const double none = -9.0e15;
      const double best = -decomposed->max(out.pinned >= 0 ? -double(out.pinned_id) : none);
      out.pinned_id = best == -none ? -1 : static_cast<int64_t>(best);
      if (out.pinned >= 0 && particles.id[out.pinned] != out.pinned_id) out.pinned = -1;
    }
  }

  // Build CSR directly: one diagonal plus one entry per neighbour in every row.
  SparseMatrix& A = out.A;
  A.resize(n, n);
  A.resizeNonZeros(nb.pairs() + n);
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  double* val = A.valuePtr();
  outer[0] = 0;
  for (int i = 0; i < n; ++i) outer[i + 1] = outer[i] + 1 + (nb.end(i) - nb.begin(i));
  out.b.resize(n);

#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    const int b = nb.begin(i), e = nb.end(i);
    // Row layout: entries sorted by column, the diagonal inserted in order.
    int pos = outer[i];
    double diag = 0.0;
    double bi = 0.0;
    auto put_neighbors = [&](auto&& coef) {
      bool diag_done = false;
      int diag_pos = -1;
      // Neighbour indices are in cell order, not sorted: sort a small local copy.
      thread_local std::vector<std::pair<int, double>> row;
      row.clear();
      for (int k = b; k < e; ++k) row.emplace_back(nb.index[k], coef(k));
      std::sort(row.begin(), row.end());
      for (const auto& [j, c] : row) {
        if (!diag_done && j > i) {
          diag_pos = pos;
          inner[pos++] = i;
          diag_done = true;
        }
        inner[pos] = j;
        val[pos++] = c;
      }
      if (!diag_done) {
        diag_pos = pos;
        inner[pos++] = i;
      }
      return diag_pos;
    };

    // Interior pair weight: the fitted Laplacian, times the harmonic mean of the coefficients.
    auto interior = [&](int k) {
      if (!coefficient) return op.lap[k];
      const double ci = (*coefficient)[i], cj = (*coefficient)[nb.index[k]];
      return op.lap[k] * 2.0 * ci * cj / (ci + cj);
    };
    const bool wall = particles.kind[i] == kWall;
    if (i == out.pinned) {
      // Keep the interior equation the pin replaces (spread_pinned_source).
      double d = 0.0;
      for (int k = b; k < e; ++k) {
        const double lap = interior(k);
        d -= lap;
        out.pin_row.emplace_back(nb.index[k], lap * scale);
      }
      out.pin_row.emplace_back(i, d * scale);
      out.pin_b = rhs[i] * scale;
    }
    const bool dirichlet = (!wall && particles.surface[i]) || i == out.pinned;
    if (dirichlet || (op.order[i] == 0 && !wall)) {
      const int d = put_neighbors([](int) { return 0.0; });
      val[d] = 1.0;
      // Non-surface rows here (the pin, isolated particles) have depth 0.
      out.b[i] = surface_depth ? rho0 * gravity.norm() * (*surface_depth)[i] : 0.0;
      continue;
    }
    if (wall) {
      double wsum = 0.0;
      Vec<Dim> acc = gravity;  // static walls: a_w = 0
      for (int k = b; k < e; ++k)
        if (particles.kind[nb.index[k]] != kWall) wsum += nb.w[k];
      if (wsum <= 0.0) {
        const int d = put_neighbors([](int) { return 0.0; });
        val[d] = 1.0;
        out.b[i] = 0.0;
        continue;
      }
      const int d = put_neighbors(
          [&](int k) { return particles.kind[nb.index[k]] != kWall ? -nb.w[k] / wsum : 0.0; });
      for (int k = b; k < e; ++k)
        if (particles.kind[nb.index[k]] != kWall) bi += nb.w[k] * acc.dot(nb.rij[k]);
      val[d] = 1.0;
      out.b[i] = rho0 * bi / wsum;
      continue;
    }
    const int d = put_neighbors([&](int k) {
      const double lap = interior(k);
      diag -= lap;
      return lap * scale;
    });
    val[d] = diag * scale;
    out.b[i] = rhs[i] * scale;
  }
}

template <int Dim>
double pinned_lambda(const PressureSystem<Dim>& system, const Eigen::VectorXd& q,
                     const Eigen::VectorXd& p) {
  if (system.pinned < 0 || system.pin_row.empty()) return 0.0;
  double r = system.pin_b, s = 1.0;
  for (const auto& [j, c] : system.pin_row) {
    r -= c * p[j];
    s -= c * q[j];
  }
  if (!(std::abs(s) > 1e-300)) return 0.0;
  return r / s;
}

template <int Dim>
double spread_pinned_source(const PressureSystem<Dim>& system, const Eigen::VectorXd& q,
                            Eigen::VectorXd& p) {
  const double lambda = pinned_lambda(system, q, p);
  if (lambda != 0.0) p -= lambda * q;
  return lambda;
}

template <int Dim>
Eigen::VectorXd uniform_source(const Particles<Dim>& particles, const Operators<Dim>& op,
                               const PressureSystem<Dim>& system) {
  const int n = static_cast<int>(particles.size());
  Eigen::VectorXd e(n);
  for (int i = 0; i < n; ++i)
    e[i] = (particles.kind[i] == kWall || i == system.pinned || particles.surface[i] ||
            op.order[i] == 0)
               ? 0.0
               : 1.0;
  return e;
}

template double spread_pinned_source<2>(const PressureSystem<2>&, const Eigen::VectorXd&,
                                        Eigen::VectorXd&);
template double spread_pinned_source<3>(const PressureSystem<3>&, const Eigen::VectorXd&,
                                        Eigen::VectorXd&);
template double pinned_lambda<2>(const PressureSystem<2>&, const Eigen::VectorXd&,
                                 const Eigen::VectorXd&);
template double pinned_lambda<3>(const PressureSystem<3>&, const Eigen::VectorXd&,
                                 const Eigen::VectorXd&);
template Eigen::VectorXd uniform_source<2>(const Particles<2>&, const Operators<2>&,
                                           const PressureSystem<2>&);
template Eigen::VectorXd uniform_source<3>(const Particles<3>&, const Operators<3>&,
                                           const PressureSystem<3>&);
template void remove_net_source<2>(const Particles<2>&, std::vector<double>&, const RowShare*);
template void remove_net_source<3>(const Particles<3>&, std::vector<double>&, const RowShare*);
template void assemble_pressure<2>(const Particles<2>&, const Neighbors<2>&, const Operators<2>&,
                                   const std::vector<double>&, const Vec<2>&, double, double,
                                   PressureSystem<2>&, const std::vector<double>*,
                                   const std::vector<double>*, const RowShare*);
template void assemble_pressure<3>(const Particles<3>&, const Neighbors<3>&, const Operators<3>&,
                                   const std::vector<double>&, const Vec<3>&, double, double,
                                   PressureSystem<3>&, const std::vector<double>*,
                                   const std::vector<double>*, const RowShare*);

}  // namespace isph
