// sph_mpi/ on several ranks (run under mpirun): the RCB tree splits a jittered lattice evenly,
// migration delivers every particle to its owner exactly once with all its data, and the halo is
// exactly the other ranks' particles within its width of the rank's box (across periodic
// boundaries too), refreshed from the owners. Every rank makes every collective call before any
// check, so that a failure on one rank cannot leave the others waiting.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <random>
#include <set>

#include "lattice.hpp"
#include "mpi_world.hpp"
#include "particle_exchange.hpp"
#include "rcb_tree.hpp"

namespace isph {
namespace {

using test::global_sum;
using test::rank;
using test::ranks;

constexpr double kDx = 0.02;

Domain<2> box(bool periodic) {
  Domain<2> d;
  d.lo = Vec<2>(0.0, 0.0);
  d.hi = Vec<2>(1.0, 0.6);
  d.periodic = {periodic, periodic};
  return d;
}

// The same jittered lattice on every rank, dealt out round-robin: each rank starts with
// particles all over the box. p and v carry the particle's id, to see them travel with it.
Particles<2> dealt_lattice(const Domain<2>& d) {
  Particles<2> all;
  all.spacing = kDx;
  all.volume = kDx * kDx;
  fill_box<2>(all, d.lo, d.hi, kDx, kFluid);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3 * kDx, 0.3 * kDx);
  for (std::size_t i = 0; i < all.size(); ++i) {
    all.x[i] += Vec<2>(u(rng), u(rng));
    if (d.periodic[0]) d.wrap(all.x[i]);
    all.p[i] = 0.5 * double(all.id[i]);
    all.v[i] = Vec<2>(double(all.id[i]), -double(all.id[i]));
  }
  std::vector<int> mine;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (int(i) % ranks() == rank()) mine.push_back(int(i));
  all.permute(mine);
  all.for_each_array([&](auto& a) { a.resize(mine.size()); });
  return all;
}

// Everybody's particles (id, position) on every rank.
std::vector<std::pair<long, Vec<2>>> gather_all(const Particles<2>& p, int n) {
  std::vector<double> mine;
  for (int i = 0; i < n; ++i) mine.insert(mine.end(), {double(p.id[i]), p.x[i][0], p.x[i][1]});
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(ranks()), starts(ranks(), 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < ranks(); ++r) starts[r] = starts[r - 1] + counts[r - 1];
  std::vector<double> all(starts.back() + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), starts.data(),
                 MPI_DOUBLE, MPI_COMM_WORLD);
  std::vector<std::pair<long, Vec<2>>> out;
  for (std::size_t k = 0; k < all.size(); k += 3)
    out.push_back({long(all[k]), Vec<2>(all[k + 1], all[k + 2])});
  return out;
}

// Distance from x to [lo, hi], over the periodic images of x: written out here, not the tree's.
double image_distance(const Domain<2>& d, const Vec<2>& x, const Vec<2>& lo, const Vec<2>& hi) {
  double best = 1e300;
  const Vec<2> L = d.length();
  for (int sx = -1; sx <= 1; ++sx)
    for (int sy = -1; sy <= 1; ++sy) {
      if ((sx && !d.periodic[0]) || (sy && !d.periodic[1])) continue;
      const Vec<2> y = x + Vec<2>(sx * L[0], sy * L[1]);
      const Vec<2> c = y.cwiseMax(lo).cwiseMin(hi);
      best = std::min(best, (y - c).norm());
    }
  return best;
}

TEST(DecompositionMpi, RcbBoxesShareTheParticlesEvenly) {
  ASSERT_GT(ranks(), 1) << "run under mpirun -np 2 or more";
  const Domain<2> d = box(false);
  Particles<2> p = dealt_lattice(d);
  const auto tree = RcbTree<2>::build(MPI_COMM_WORLD, d, p.x);
  std::vector<long> count(ranks(), 0);
  int outside = 0;
  for (const auto& x : p.x) {
    const int o = tree.owner(x);
    ++count[o];
    outside += (x.array() < tree.lo(o).array()).any() || (x.array() > tree.hi(o).array()).any();
  }
  MPI_Allreduce(MPI_IN_PLACE, count.data(), ranks(), MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  const long total = global_sum(long(p.size()));
  double area = 0.0;
  for (int r = 0; r < ranks(); ++r) area += (tree.hi(r) - tree.lo(r)).prod();
  const double even = double(total) / ranks();
  std::printf("%d ranks, %ld particles:", ranks(), total);
  for (long c : count) std::printf(" %ld", c);
  std::printf(" (even: %.1f)\n", even);
  for (long c : count) EXPECT_LE(std::abs(c - even), 0.01 * even + 1);
  EXPECT_NEAR(area, d.length().prod(), 1e-12);  // the boxes tile the domain
  EXPECT_EQ(outside, 0);
}

TEST(DecompositionMpi, MigrationDeliversEveryParticleOnceWithItsData) {
  const Domain<2> d = box(false);
  Particles<2> p = dealt_lattice(d);
  const long before = global_sum(long(p.size()));
  const auto tree = RcbTree<2>::build(MPI_COMM_WORLD, d, p.x);
  migrate(MPI_COMM_WORLD, tree, p);
  int foreign = 0, wrong_data = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    foreign += tree.owner(p.x[i]) != rank();
    wrong_data +=
        p.p[i] != 0.5 * double(p.id[i]) || p.v[i][0] != double(p.id[i]) || p.kind[i] != kFluid;
  }
  const auto all = gather_all(p, int(p.size()));
  std::vector<long> ids;
  for (const auto& [id, x] : all) ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  std::vector<long> expected(before);
  for (long k = 0; k < before; ++k) expected[k] = k;
  EXPECT_EQ(foreign, 0);
  EXPECT_EQ(wrong_data, 0);
  EXPECT_EQ(ids, expected);  // each particle exactly once
}

TEST(DecompositionMpi, HaloIsTheOtherRanksParticlesWithinItsWidth) {
  for (const bool periodic : {false, true}) {
    const Domain<2> d = box(periodic);
    Particles<2> p = dealt_lattice(d);
    const auto tree = RcbTree<2>::build(MPI_COMM_WORLD, d, p.x);
    migrate(MPI_COMM_WORLD, tree, p);
    const double width = 2.6 * kDx;
    const HaloPlan plan = add_halo(MPI_COMM_WORLD, tree, width, p);
    const auto all = gather_all(p, plan.owned);
    std::set<long> expected, got, owned;
    for (int i = 0; i < plan.owned; ++i) owned.insert(p.id[i]);
    for (const auto& [id, x] : all)
      if (!owned.count(id) && image_distance(d, x, tree.lo(rank()), tree.hi(rank())) < width)
        expected.insert(id);
    int wrong_copy = 0;
    for (std::size_t i = plan.owned; i < p.size(); ++i) {
      got.insert(p.id[i]);
      wrong_copy += p.p[i] != 0.5 * double(p.id[i]);
    }
    // The owners change their values; the halo follows.
    for (int i = 0; i < plan.owned; ++i) {
      p.p[i] = double(p.id[i]) + 7.0;
      p.v[i] = Vec<2>(3.0, double(p.id[i]));
    }
    refresh_halo(MPI_COMM_WORLD, plan, p.p);
    refresh_halo(MPI_COMM_WORLD, plan, p.v);
    int stale = 0;
    for (std::size_t i = plan.owned; i < p.size(); ++i)
      stale += p.p[i] != double(p.id[i]) + 7.0 || p.v[i] != Vec<2>(3.0, double(p.id[i]));
    const long halo = global_sum(long(got.size()));
    std::printf("%s, %d ranks: halo of %ld particles in all (width %.1f dx)\n",
                periodic ? "periodic" : "walled", ranks(), halo, width / kDx);
    EXPECT_EQ(got, expected);
    EXPECT_GT(halo, 0);
    EXPECT_EQ(wrong_copy, 0);
    EXPECT_EQ(stale, 0);
    drop_halo(plan, p);
    EXPECT_EQ(int(p.size()), plan.owned);
    EXPECT_EQ(int(p.id.size()), plan.owned);
  }
}

}  // namespace
}  // namespace isph
