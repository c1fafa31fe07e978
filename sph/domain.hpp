#pragma once
// The computational box: bounds and which axes are periodic. Periodicity is handled by the
// minimum-image convention in the neighbour search, so no ghost particles are needed.
#include <array>

#include "vec.hpp"

namespace isph {

template <int Dim>
struct Domain {
  Vec<Dim> lo = Vec<Dim>::Zero();
  Vec<Dim> hi = Vec<Dim>::Ones();
  std::array<bool, Dim> periodic{};

  Vec<Dim> length() const { return hi - lo; }

  // Maps a separation vector to its shortest periodic image.
  Vec<Dim> min_image(Vec<Dim> d) const {
    for (int a = 0; a < Dim; ++a) {
      if (!periodic[a]) continue;
      const double L = hi[a] - lo[a];
      if (d[a] > 0.5 * L)
        d[a] -= L;
      else if (d[a] < -0.5 * L)
        d[a] += L;
    }
    return d;
  }

  // Puts a position back into the box along periodic axes.
  void wrap(Vec<Dim>& x) const {
    for (int a = 0; a < Dim; ++a) {
      if (!periodic[a]) continue;
      const double L = hi[a] - lo[a];
      while (x[a] < lo[a]) x[a] += L;
      while (x[a] >= hi[a]) x[a] -= L;
    }
  }

  // True when x lies inside the box along every non-periodic axis.
  bool contains(const Vec<Dim>& x) const {
    for (int a = 0; a < Dim; ++a)
      if (!periodic[a] && (x[a] < lo[a] || x[a] > hi[a])) return false;
    return true;
  }
};

}  // namespace isph
