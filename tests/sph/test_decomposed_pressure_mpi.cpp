// The pressure equation of the decomposed fluid (issue 26), under mpirun: the particles are cut
// into RCB boxes, each rank assembles the rows of the particles it owns over its owned and halo
// particles, and BoomerAMG solves the ranks' rows as one system numbered globally
// (sph_mpi/global_numbering.hpp). The problem is the manufactured one of test_amg_solver.cpp
// (disordered particles, fitted Laplacian, Dirichlet band); every rank also solves the whole
// system alone, as one process would, and each owned particle's pressure must equal that
// solution's at the same id to solver tolerance. Every rank makes every collective call before
// any check, so that a failure on one rank cannot leave the others waiting.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <map>

#include "global_numbering.hpp"
#include "manufactured_pressure.hpp"
#include "mpi_world.hpp"
#include "particle_exchange.hpp"
#include "rcb_tree.hpp"

namespace isph {
namespace {

using test::global_sum;
using test::rank;
using test::ranks;

constexpr double kDx = 0.02;

double global_max(double v) {
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return v;
}

LinearSolverConfig amg(int setup_reuse = 1) {
  LinearSolverConfig c;
  c.preconditioner = "amg";
  c.tolerance = 1e-10;
  c.setup_reuse = setup_reuse;
  return c;
}

// The whole problem's particles dealt out round-robin, then decomposed: RCB boxes, each rank its
// owned particles, then a halo one kernel support wide.
struct Decomposed {
  Particles<2> p;
  HaloPlan plan;
  explicit Decomposed(const Particles<2>& whole, double support) {
    p = whole;
    std::vector<int> mine;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (static_cast<int>(i) % ranks() == rank()) mine.push_back(static_cast<int>(i));
    p.permute(mine);
    p.for_each_array([&](auto& a) { a.resize(mine.size()); });
    const Domain<2> d;  // open: the manufactured box has no periodic axis
    const auto tree = RcbTree<2>::build(MPI_COMM_WORLD, d, p.x);
    migrate(MPI_COMM_WORLD, tree, p);
    plan = add_halo(MPI_COMM_WORLD, tree, support, p);
  }
};

// The manufactured system's rows of the owned particles, assembled over owned + halo; the halo's
// rows stay empty (no neighbour list) and are not solved.
PressureSystem<2> assemble_owned(Particles<2>& p, int owned, const Kernel<2>& W) {
  Neighbors<2> nb;
  NeighborSearch<2> search(Domain<2>(), W.support());
  search.build(p, W, nb, 0, owned);
  std::vector<uint8_t> mode(p.size(), 0);
  std::fill(mode.begin(), mode.begin() + owned, 2);
  Operators<2> op;
  compute_operators(nb, W.h(), p.volume, mode, op);
  PressureSystem<2> sys;
  std::vector<double> rhs(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) rhs[i] = exact_lap(p.x[i]);
  assemble_pressure(p, nb, op, rhs, Vec<2>(Vec<2>::Zero()), 1000.0, W.h(), sys);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.surface[i]) sys.b[i] = exact_p(p.x[i]);
  return sys;
}

// Largest |x_i - reference at id_i| / max |reference| over the owned particles of every rank.
double difference_by_id(const Particles<2>& p, int owned, const Eigen::VectorXd& x,
                        const Particles<2>& whole, const Eigen::VectorXd& reference) {
  std::map<int64_t, int> at;
  for (std::size_t i = 0; i < whole.size(); ++i) at[whole.id[i]] = static_cast<int>(i);
  double d = 0.0;
  for (int i = 0; i < owned; ++i) d = std::max(d, std::abs(x[i] - reference[at.at(p.id[i])]));
  return global_max(d) / reference.cwiseAbs().maxCoeff();
}

TEST(DecomposedPressureMpi, GlobalNumbersAreDistinctAndTheHaloCarriesItsOwners) {
  ManufacturedSystem m(kDx);
  Decomposed dec(m.p, m.box.W.support());
  const GlobalNumbering g = number_globally(MPI_COMM_WORLD, dec.plan);
  // Every rank's (id, number) of its owned particles, to every rank.
  std::vector<int64_t> mine;
  for (int i = 0; i < g.owned; ++i) mine.insert(mine.end(), {dec.p.id[i], g.global[i]});
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(ranks()), starts(ranks(), 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < ranks(); ++r) starts[r] = starts[r - 1] + counts[r - 1];
  std::vector<int64_t> all(starts.back() + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_INT64_T, all.data(), counts.data(), starts.data(),
                 MPI_INT64_T, MPI_COMM_WORLD);
  std::map<int64_t, int64_t> number_of;
  std::vector<int64_t> numbers;
  for (std::size_t k = 0; k < all.size(); k += 2) {
    number_of[all[k]] = all[k + 1];
    numbers.push_back(all[k + 1]);
  }
  std::sort(numbers.begin(), numbers.end());
  std::vector<int64_t> expected(m.p.size());
  for (std::size_t k = 0; k < expected.size(); ++k) expected[k] = static_cast<int64_t>(k);
  int wrong_halo = 0, not_contiguous = 0;
  for (std::size_t i = g.owned; i < dec.p.size(); ++i)
    wrong_halo += g.global[i] != number_of.at(dec.p.id[i]);
  for (int i = 1; i < g.owned; ++i) not_contiguous += g.global[i] != g.global[0] + i;
  EXPECT_EQ(g.total, static_cast<int64_t>(m.p.size()));
  EXPECT_EQ(numbers, expected);  // 0 .. N-1, each once
  EXPECT_EQ(g.global.size(), dec.p.size());
  EXPECT_EQ(wrong_halo, 0);
  EXPECT_EQ(not_contiguous, 0);
}

TEST(DecomposedPressureMpi, OwnedRowsGiveTheWholeSystemsPressure) {
  ManufacturedSystem m(kDx);
  Eigen::VectorXd whole = Eigen::VectorXd::Zero(m.p.size());
  const SolveStats sw = make_linear_solver(amg())->solve(m.sys.A, m.sys.b, whole);
  // ^ on every rank the same whole system: the ranks solve it as one, every rank gets it all.

  const Kernel<2>& W = m.box.W;
  Decomposed dec(m.p, W.support());
  const int owned = dec.plan.owned;
  const PressureSystem<2> sys = assemble_owned(dec.p, owned, W);
  auto solver = make_linear_solver(amg(3));
  solver->number_globally(
      std::make_shared<GlobalNumbering>(number_globally(MPI_COMM_WORLD, dec.plan)));
  constexpr double kUntouched = 12345.0;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(dec.p.size(), kUntouched);
  x.head(owned).setZero();
  const SolveStats s = solver->solve(sys.A, sys.b, x);
  const double diff = difference_by_id(dec.p, owned, x, m.p, whole);
  double err = 0.0;
  for (int i = 0; i < owned; ++i) err = std::max(err, std::abs(x[i] - exact_p(dec.p.x[i])));
  err = global_max(err);
  int halo_touched = 0;
  for (Eigen::Index i = owned; i < x.size(); ++i) halo_touched += x[i] != kUntouched;

  // The same rows with other values (the diagonal of every owned row 5% larger): the Mat is
  // updated in place, the hierarchy kept, and the new solution must match the whole system's.
  SparseMatrix A2 = sys.A;
  for (int k = 0; k < owned; ++k)
    for (SparseMatrix::InnerIterator it(A2, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 1.05;
  SparseMatrix whole_A2 = m.sys.A;
  for (int k = 0; k < whole_A2.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(whole_A2, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 1.05;
  Eigen::VectorXd whole2 = whole;
  make_linear_solver(amg())->solve(whole_A2, m.sys.b, whole2);
  Eigen::VectorXd x2 = x;
  const SolveStats s2 = solver->solve(A2, sys.b, x2);
  const double diff2 = difference_by_id(dec.p, owned, x2, m.p, whole2);
  const double change = difference_by_id(dec.p, owned, x2, m.p, whole);

  const long halo = global_sum(static_cast<long>(dec.p.size()) - owned);
  if (rank() == 0)
    std::printf(
        "%d ranks, N = %zu, halo %ld: whole system %d iterations, owned rows %d (then %d, no new "
        "setup: %s); max |p - p_whole| / max |p| = %.2e (changed values %.2e); error against the "
        "exact solution %.3e\n",
        ranks(), m.p.size(), halo, sw.iterations, s.iterations, s2.iterations,
        s2.setup_seconds == 0.0 ? "yes" : "no", diff, diff2, err);
  ASSERT_TRUE(sw.converged) << sw.reason;
  ASSERT_TRUE(s.converged) << s.reason;
  EXPECT_LE(s.residual, 1e-10);
  EXPECT_LT(diff, 1e-7);
  EXPECT_LT(err, 1e-3);  // the fitted Laplacian's own error at this dx: 3.0e-4 on one process
  EXPECT_EQ(halo_touched, 0);
  ASSERT_TRUE(s2.converged) << s2.reason;
  EXPECT_EQ(s2.setup_seconds, 0.0);
  EXPECT_LT(diff2, 1e-7);
  EXPECT_GT(change, 1e-4);  // it did solve the changed system
}

TEST(DecomposedPressureMpi, AnEigenSolverRefusesADecomposedSystem) {
  LinearSolverConfig c;
  c.preconditioner = "ilu0";
  try {
    make_linear_solver(c)->number_globally(std::make_shared<GlobalNumbering>());
    FAIL() << "ilu0 took a decomposed system";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("solver.preconditioner = \"amg\""), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace isph
