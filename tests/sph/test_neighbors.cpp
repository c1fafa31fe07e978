// Neighbour lists from the cell search equal a brute-force search, on random and on clustered
// particle sets, with and without periodic axes; pair geometry is consistent.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <random>
#include <set>

#include "neighbors.hpp"

namespace isph {
namespace {

template <int Dim>
Particles<Dim> random_cloud(int n, bool clustered, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 0.04);
  Particles<Dim> p;
  p.spacing = 0.02;
  for (int i = 0; i < n; ++i) {
    Vec<Dim> x;
    for (int a = 0; a < Dim; ++a) x[a] = u(rng);
    if (clustered && i % 2) {  // half of the particles in three tight clusters
      x = Vec<Dim>::Constant(0.2 + 0.3 * (i % 3));
      for (int a = 0; a < Dim; ++a) x[a] = std::clamp(x[a] + g(rng), 0.0, 0.999999);
    }
    p.add(x, Vec<Dim>::Zero(), kFluid);
  }
  return p;
}

template <int Dim>
void compare_with_brute_force(bool clustered, bool periodic) {
  Domain<Dim> dom;
  dom.lo.setZero();
  dom.hi.setOnes();
  for (int a = 0; a < Dim; ++a) dom.periodic[a] = periodic && a == 0;
  Particles<Dim> p = random_cloud<Dim>(Dim == 2 ? 3000 : 4000, clustered, 7);
  const double h = Dim == 2 ? 0.021 : 0.045;
  Kernel<Dim> W(KernelType::WendlandC2, h);
  NeighborSearch<Dim> search(dom, W.support());
  search.sort(p);
  Neighbors<Dim> nb;
  search.build(p, W, nb);

  const int n = static_cast<int>(p.size());
  std::size_t total = 0;
  for (int i = 0; i < n; ++i) {
    std::set<int> expect;
    for (int j = 0; j < n; ++j)
      if (j != i && dom.min_image(p.x[i] - p.x[j]).norm() < W.support()) expect.insert(j);
    std::set<int> got(nb.index.begin() + nb.begin(i), nb.index.begin() + nb.end(i));
    ASSERT_EQ(got.size(), static_cast<std::size_t>(nb.end(i) - nb.begin(i)))
        << "duplicate in row " << i;
    ASSERT_EQ(got, expect) << "row " << i;
    total += got.size();
    for (int k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.index[k];
      const Vec<Dim> d = dom.min_image(p.x[i] - p.x[j]);
      ASSERT_LT((nb.rij[k] - d).norm(), 1e-14);
      ASSERT_DOUBLE_EQ(nb.w[k], W.value(d.norm()));
    }
  }
  EXPECT_GT(total, static_cast<std::size_t>(n));  // the test is not vacuous
}

TEST(Neighbors, RandomMatchesBruteForce2D) { compare_with_brute_force<2>(false, false); }
TEST(Neighbors, ClusteredMatchesBruteForce2D) { compare_with_brute_force<2>(true, false); }
TEST(Neighbors, PeriodicMatchesBruteForce2D) { compare_with_brute_force<2>(false, true); }
TEST(Neighbors, RandomMatchesBruteForce3D) { compare_with_brute_force<3>(false, false); }
TEST(Neighbors, ClusteredPeriodicMatchesBruteForce3D) { compare_with_brute_force<3>(true, true); }

// A block of rows (a rank's share, sph/row_share.hpp), listed by 1 to 3 threads in the one pass
// over the candidates: each of its rows is the whole list's row, in the same order, with the same
// pair geometry; rows outside the block are empty.
TEST(Neighbors, BlockOfRowsOnSeveralThreadsEqualsTheWholeListsRows) {
  Domain<2> dom;
  dom.lo.setZero();
  dom.hi.setOnes();
  dom.periodic[1] = true;
  Particles<2> p = random_cloud<2>(3000, true, 11);
  Kernel<2> W(KernelType::WendlandC2, 0.021);
  NeighborSearch<2> search(dom, W.support());
  search.sort(p);
  Neighbors<2> whole;
  search.build(p, W, whole);
  const int n = static_cast<int>(p.size()), first = 700, last = 2300;
  for (int threads = 1; threads <= 3; ++threads) {
    omp_set_num_threads(threads);
    Neighbors<2> block;
    search.build(p, W, block, first, last);
    ASSERT_EQ(block.size(), whole.size());
    for (int i = 0; i < n; ++i) {
      if (i < first || i >= last) {
        ASSERT_EQ(block.end(i), block.begin(i)) << "row " << i << " outside the block";
        continue;
      }
      ASSERT_EQ(block.end(i) - block.begin(i), whole.end(i) - whole.begin(i)) << "row " << i;
      for (int k = 0; k < whole.end(i) - whole.begin(i); ++k) {
        const int a = block.begin(i) + k, b = whole.begin(i) + k;
        ASSERT_EQ(block.index[a], whole.index[b]);
        ASSERT_EQ(block.rij[a], whole.rij[b]);
        ASSERT_EQ(block.w[a], whole.w[b]);
        ASSERT_EQ(block.dw[a], whole.dw[b]);
      }
    }
    EXPECT_GT(block.pairs(), static_cast<std::size_t>(last - first));
  }
}

TEST(Neighbors, SortKeepsEveryParticle) {
  Particles<2> p = random_cloud<2>(500, true, 3);
  std::vector<int64_t> ids = p.id;
  Domain<2> dom;
  NeighborSearch<2> search(dom, 0.05);
  const auto perm = search.sort(p);
  std::vector<int64_t> after = p.id;
  std::sort(after.begin(), after.end());
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(after, ids);
  for (std::size_t n = 0; n < perm.size(); ++n) EXPECT_EQ(p.id[n], static_cast<int64_t>(perm[n]));
}

TEST(Neighbors, ShortPeriodicBoxIsRejectedWithTheFix) {
  Domain<2> dom;
  dom.periodic = {true, false};
  dom.hi = Vec<2>(0.1, 1.0);
  try {
    NeighborSearch<2> search(dom, 0.05);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("enlarge the domain"), std::string::npos);
  }
}

}  // namespace
}  // namespace isph
