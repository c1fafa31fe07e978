#pragma once
// The manufactured pressure problem the PPE tests share: p = sin(pi x) cosh(y/2) + x y on the
// unit square of disordered particles, with its Laplacian as the source.
#include <random>

#include "lattice.hpp"
#include "neighbors.hpp"
#include "operators.hpp"
#include "pressure_equation.hpp"

namespace isph {

inline double exact_p(const Vec<2>& x) {
  return std::sin(M_PI * x[0]) * std::cosh(0.5 * x[1]) + x[0] * x[1];
}
inline double exact_lap(const Vec<2>& x) {
  return (-M_PI * M_PI + 0.25) * std::sin(M_PI * x[0]) * std::cosh(0.5 * x[1]);
}

// The unit square of fluid particles, each moved by up to `jitter` spacings; neighbours and
// fitted operators built.
struct DisorderedBox {
  Particles<2> p;
  Kernel<2> W;
  Neighbors<2> nb;
  Operators<2> op;
  DisorderedBox(double dx, double jitter, unsigned seed, bool periodic)
      : W(KernelType::WendlandC2, 1.3 * dx) {
    p.spacing = dx;
    p.volume = dx * dx;
    fill_box<2>(p, Vec<2>::Zero(), Vec<2>::Ones(), dx, kFluid);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
    for (auto& x : p.x) x += Vec<2>(u(rng), u(rng));
    Domain<2> dom;
    if (periodic) {
      dom.lo = Vec<2>::Zero();
      dom.hi = Vec<2>::Ones();
      dom.periodic = {true, true};
      for (auto& x : p.x) dom.wrap(x);
    }
    NeighborSearch<2> search(dom, W.support());
    search.sort(p);
    search.build(p, W, nb);
    compute_operators(nb, W.h(), p.volume, {}, op);
  }
};

// Its pressure system: particles moved by up to 0.2 spacings, a Dirichlet band of two layers
// carrying the exact value, the source the exact Laplacian.
struct ManufacturedSystem {
  PressureSystem<2> sys;
  DisorderedBox box;
  const Particles<2>& p = box.p;
  explicit ManufacturedSystem(double dx) : box(dx, 0.2, 5, false) {
    auto& q = box.p;
    const int n = static_cast<int>(q.size());
    std::vector<double> rhs(n);
    for (int i = 0; i < n; ++i) {
      const auto& x = q.x[i];
      q.surface[i] = (x.array() < 2 * dx).any() || (x.array() > 1 - 2 * dx).any();
      rhs[i] = exact_lap(x);
    }
    assemble_pressure(q, box.nb, box.op, rhs, Vec<2>(Vec<2>::Zero()), 1000.0, box.W.h(), sys);
    for (int i = 0; i < n; ++i)
      if (q.surface[i]) sys.b[i] = exact_p(q.x[i]);
  }
};

}  // namespace isph
