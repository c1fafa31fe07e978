// The pressure equation recovers a manufactured solution, with the error shrinking under
// refinement; walls reproduce a hydrostatic pressure exactly.
#include <gtest/gtest.h>

#include <random>

#include "free_surface.hpp"
#include "lattice.hpp"
#include "linear_solver.hpp"
#include "manufactured_pressure.hpp"
#include "pressure_equation.hpp"

namespace isph {
namespace {

double manufactured_error(double dx) {
  ManufacturedSystem m(dx);
  const auto& p = m.p;
  const int n = static_cast<int>(p.size());
  auto& sys = m.sys;
  EXPECT_EQ(sys.pinned, -1);
  auto solver = make_linear_solver({});
  Eigen::VectorXd sol = Eigen::VectorXd::Zero(n);
  const SolveStats s = solver->solve(sys.A, sys.b, sol);
  EXPECT_TRUE(s.converged) << "residual " << s.residual;
  double err = 0, norm = 0;
  for (int i = 0; i < n; ++i) {
    err = std::max(err, std::abs(sol[i] - exact_p(p.x[i])));
    norm = std::max(norm, std::abs(exact_p(p.x[i])));
  }
  std::printf("dx=%g: N=%d, BiCGSTAB %d iterations, max relative error %.3e\n", dx, n, s.iterations,
              err / norm);
  return err / norm;
}

TEST(PressureEquation, ManufacturedSolutionConverges) {
  const double coarse = manufactured_error(0.04);
  const double fine = manufactured_error(0.02);
  const double finer = manufactured_error(0.01);
  std::printf("observed orders: %.2f, %.2f\n", std::log2(coarse / fine), std::log2(fine / finer));
  EXPECT_LT(finer, 2e-3);
  EXPECT_LT(fine, 0.7 * coarse);
  EXPECT_LT(finer, 0.7 * fine);
}

// A still water column in a walled box with p = 0 at the top row: the solution of the assembled
// system (with zero divergence) is exactly hydrostatic, walls included.
TEST(PressureEquation, WallRowsGiveExactHydrostatics) {
  const double dx = 0.05, H = 1.0, rho = 1000.0, g = 9.81;
  Particles<2> p;
  p.spacing = dx;
  p.volume = dx * dx;
  fill_box<2>(p, Vec<2>::Zero(), Vec<2>(0.5, H), dx, kFluid);
  add_wall_shell<2>(p, Vec<2>::Zero(), Vec<2>(0.5, H), dx, 3, {true, true, true, false});
  Kernel<2> W(KernelType::WendlandC2, 1.3 * dx);
  Domain<2> dom;
  dom.lo = Vec<2>(-1, -1);
  dom.hi = Vec<2>(2, 2);
  NeighborSearch<2> search(dom, W.support());
  search.sort(p);
  Neighbors<2> nb;
  search.build(p, W, nb);
  Operators<2> op;
  std::vector<uint8_t> mode(p.size());  // quadratic fit for fluid, nothing for walls
  for (std::size_t i = 0; i < p.size(); ++i) mode[i] = p.kind[i] != kWall ? 2 : 0;
  compute_operators(nb, W.h(), p.volume, mode, op);
  const double top = H - 0.5 * dx;
  for (std::size_t i = 0; i < p.size(); ++i)
    p.surface[i] = p.kind[i] == kFluid && p.x[i][1] > top - 1e-9;
  std::vector<double> rhs(p.size(), 0.0);
  PressureSystem<2> sys;
  assemble_pressure(p, nb, op, rhs, Vec<2>(0, -g), rho, W.h(), sys);
  Eigen::VectorXd sol = Eigen::VectorXd::Zero(p.size());
  LinearSolverConfig tight;  // solve far below the asserted error, so the test checks the rows
  tight.tolerance = 1e-13;
  auto solver = make_linear_solver(tight);
  ASSERT_TRUE(solver->solve(sys.A, sys.b, sol).converged);
  double err = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] == kWall && p.x[i][1] > top) continue;  // walls beside the surface row
    bool has_fluid = false;
    for (int k = nb.begin(i); k < nb.end(i); ++k) has_fluid |= p.kind[nb.index[k]] != kWall;
    if (!has_fluid) continue;
    err = std::max(err, std::abs(sol[i] - rho * g * (top - p.x[i][1])) / (rho * g * H));
  }
  std::printf("max relative error against rho g (H - y), walls included: %.2e\n", err);
  EXPECT_LT(err, 1e-8);
}

// A periodic box has no Dirichlet row: one particle is pinned. With disordered particles the
// fitted Laplacian is not symmetric, so removing the mean source leaves an excess the pinned row
// alone absorbs (a point source in a real run). spread_pinned_source must turn that into the
// same shift lambda of every row's source, the pinned row's own equation included.
TEST(PressureEquation, PinnedRowExcessIsSpreadUniformly) {
  DisorderedBox box(0.05, 0.25, 11, true);
  const auto& p = box.p;
  const auto& W = box.W;
  const auto& nb = box.nb;
  const auto& op = box.op;
  const int n = static_cast<int>(p.size());
  std::vector<double> rhs(n);
  std::mt19937 rng(12);
  std::normal_distribution<double> g(0.0, 1.0);
  for (auto& r : rhs) r = g(rng);
  remove_net_source(p, rhs);
  PressureSystem<2> sys;
  assemble_pressure(p, nb, op, rhs, Vec<2>(Vec<2>::Zero()), 1000.0, W.h(), sys);
  ASSERT_GE(sys.pinned, 0);
  ASSERT_EQ(sys.pin_row.size(),
            static_cast<std::size_t>(nb.end(sys.pinned) - nb.begin(sys.pinned) + 1));
  LinearSolverConfig tight;
  tight.tolerance = 1e-13;
  auto solver = make_linear_solver(tight);
  Eigen::VectorXd sol = Eigen::VectorXd::Zero(n), q = Eigen::VectorXd::Zero(n);
  ASSERT_TRUE(solver->solve(sys.A, sys.b, sol).converged);
  auto pin_residual = [&](const Eigen::VectorXd& x) {
    double r = sys.pin_b;
    for (const auto& [j, c] : sys.pin_row) r -= c * x[j];
    return r;
  };
  const double before = pin_residual(sol);
  const SolveStats sq = solver->solve(sys.A, uniform_source(p, op, sys), q);
  ASSERT_LT(sq.residual, 1e-11) << sq.iterations << " iterations";
  const double lambda = spread_pinned_source(sys, q, sol);
  // Interior residual of every row, the pinned one through its kept equation.
  const Eigen::VectorXd r = sys.A * sol - sys.b;
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double ri = i == sys.pinned ? -pin_residual(sol) : r[i];
    worst = std::max(worst, std::abs(ri + lambda));
  }
  const double scale = sys.b.cwiseAbs().maxCoeff();
  std::printf(
      "pinned row absorbed %.3e (|b| max %.3e); spread: lambda = %.3e = %.3f x that / N, "
      "rows off the uniform shift by %.2e at most\n",
      before, scale, lambda, lambda * n / before, worst);
  EXPECT_GT(std::abs(before), 1e-3 * scale) << "the scene should leave an excess at the pin";
  EXPECT_LT(worst, 1e-9 * scale);
  EXPECT_LT(std::abs(lambda), 1e-2 * std::abs(before)) << "spread, not moved elsewhere whole";
}

}  // namespace
}  // namespace isph
