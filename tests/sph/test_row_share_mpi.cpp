// Shared rows (sph/row_share.hpp, sph_mpi/block_row_share.hpp) on several ranks: each rank's
// block reaches every rank, and the stages with a pass over neighbours' results or a scatter
// inside them (the shifting's surface normal, the separation of close pairs, the dry tops of
// bodies, the pocket blend) give on every rank, from neighbour lists of the rank's own rows only,
// bit for bit the one-process result.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <random>

#include "block_row_share.hpp"
#include "lattice.hpp"
#include "neighbors.hpp"
#include "pocket_fluid.hpp"
#include "rigid_solids.hpp"
#include "shifting.hpp"

namespace isph {
namespace {

constexpr double kDx = 0.02;

// A jittered lattice with velocities, the same on every rank; three particles in ten are pushed
// onto a neighbour, so that close pairs lie all over the box, block boundaries
// included (the storage is sorted by cell, and blocks are contiguous in it), and one pair at
// each block boundary for certain.
struct Scene {
  Domain<2> domain;
  Particles<2> p;
  Kernel<2> kernel{KernelType::WendlandC2, 1.3 * kDx};
};

Scene crowded_lattice(int parts) {
  Scene s;
  s.domain.lo = Vec<2>(0.0, 0.0);
  s.domain.hi = Vec<2>(0.6, 0.4);
  s.p.spacing = kDx;
  s.p.volume = kDx * kDx;
  fill_box<2>(s.p, s.domain.lo, s.domain.hi, kDx, kFluid);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2 * kDx, 0.2 * kDx), coin(0.0, 1.0);
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    s.p.x[i] += Vec<2>(u(rng), u(rng));
    const double c = coin(rng);
    if (c < 0.3) s.p.x[i][c < 0.15 ? 0 : 1] += 0.75 * kDx;  // onto the neighbour right or above
    s.p.v[i] = Vec<2>(std::sin(7.0 * s.p.x[i][1]), std::cos(5.0 * s.p.x[i][0]));
  }
  NeighborSearch<2>(s.domain, s.kernel.support()).sort(s.p);
  // And the first particle of every block next to the last one of the block before.
  const int n = static_cast<int>(s.p.size());
  for (int part = 1; part < parts; ++part) {
    const int b = block_start(n, part, parts);
    s.p.x[b] = s.p.x[b - 1] + Vec<2>(0.25 * kDx, 0.1 * kDx);
  }
  return s;
}

TEST(RowShareMpi, EveryBlockReachesEveryRank) {
  const BlockRowShare share(MPI_COMM_WORLD);
  const int n = 1001;  // not a multiple of the ranks
  std::vector<Vec<2>> v(n, Vec<2>::Constant(-1.0));
  std::vector<uint8_t> flag(n, 0);
  for (int i = share.first(n); i < share.last(n); ++i) {
    v[i] = Vec<2>(i, 0.5 * i);
    flag[i] = static_cast<uint8_t>(i % 3 + 1);
  }
  share.exchange(v);
  share.exchange(flag);
  int wrong = 0;
  for (int i = 0; i < n; ++i) wrong += v[i] != Vec<2>(i, 0.5 * i) || flag[i] != i % 3 + 1;
  EXPECT_EQ(wrong, 0);
  // Lists in the order of the ranks, of different lengths.
  std::vector<int> mine(share.part() + 1, share.part());
  const std::vector<int> all = share.concatenate(mine);
  std::vector<int> expect;
  for (int r = 0; r < share.parts(); ++r) expect.insert(expect.end(), r + 1, r);
  EXPECT_EQ(all, expect);
  EXPECT_EQ(share.sum(1.5), 1.5 * share.parts());
  EXPECT_EQ(share.max(double(share.part())), share.parts() - 1.0);
}

TEST(RowShareMpi, ShiftsAndClosePairsMatchOneProcessBitForBit) {
  const BlockRowShare share(MPI_COMM_WORLD);
  ASSERT_GT(share.parts(), 1) << "run under mpirun -np 2 or more";
  Scene one = crowded_lattice(share.parts());
  const int n = static_cast<int>(one.p.size());
  NeighborSearch<2> search(one.domain, one.kernel.support());
  Neighbors<2> all_rows, own_rows;
  search.build(one.p, one.kernel, all_rows);
  search.build(one.p, one.kernel, own_rows, share.first(n), share.last(n));

  // Modes as at a free surface: a band of tangential-only rows (their normal reads the
  // neighbours' concentration gradients) across the whole box, the rest free.
  std::vector<uint8_t> mode(n);
  for (int i = 0; i < n; ++i) mode[i] = one.p.x[i][1] > 0.15 && one.p.x[i][1] < 0.25 ? 1 : 2;
  const double dt = 1e-3;  // |v| dt = dx / 20
  ShiftingParams params;
  std::vector<Vec<2>> shift_one, shift_shared;
  compute_shifts(one.p, all_rows, one.kernel, params, dt, mode, shift_one);
  compute_shifts(one.p, own_rows, one.kernel, params, dt, mode, shift_shared, &share);
  share.exchange(shift_shared);
  int differ = 0;
  for (int i = 0; i < n; ++i) differ += shift_one[i] != shift_shared[i];
  EXPECT_EQ(differ, 0) << "shifts that differ from the one-process result";

  Scene shared = crowded_lattice(share.parts());
  const std::vector<Vec<2>> shift_before = shift_one;
  const double min_distance = 0.5 * kDx;
  separate_close_pairs(one.p, all_rows, one.domain, dt, min_distance, shift_one);
  separate_close_pairs(shared.p, own_rows, shared.domain, dt, min_distance, shift_shared, &share);
  int moved = 0, across = 0;
  differ = 0;
  const int first = share.first(n), last = share.last(n);
  for (int i = 0; i < n; ++i) {
    moved += shift_one[i] != shift_before[i];
    differ += shift_one[i] != shift_shared[i] || one.p.v[i] != shared.p.v[i];
    if (i < first || i >= last) continue;
    for (int k = all_rows.begin(i); k < all_rows.end(i); ++k) {
      const int j = all_rows.index[k];
      across += (j < first || j >= last) && all_rows.r[k] < min_distance;
    }
  }
  EXPECT_EQ(differ, 0) << "particles whose shift or velocity differs from the one-process sweep";
  // The scene must test something: pairs were separated, some of them across blocks.
  EXPECT_GT(moved, n / 20);
  EXPECT_GT(share.sum(across), 0.0) << "no close pair across a block boundary";
}

TEST(RowShareMpi, PocketBlendAndDryBodiesMatchOneProcessBitForBit) {
  const BlockRowShare share(MPI_COMM_WORLD);
  ASSERT_GT(share.parts(), 1) << "run under mpirun -np 2 or more";
  // Bodies of two columns of solid particles with one column of fluid between each pair: every
  // such fluid particle sits in a pocket (solid share about 2/3). A band of fluid across the
  // middle, where the blocks meet, is marked free surface: every body's waterline is fitted from
  // points of several blocks, and the bodies' parts above it are dry.
  auto scene = [&] {
    Scene s = crowded_lattice(share.parts());
    for (std::size_t i = 0; i < s.p.size(); ++i) {
      const int column = static_cast<int>(std::floor(s.p.x[i][0] / kDx + 0.5));
      if (column % 3 != 0 && s.p.x[i][1] < 0.39) {
        s.p.kind[i] = kSolid;
        s.p.body[i] = column / 3;
        s.p.v[i] = Vec<2>(0.01, 0.0);
        s.p.solid_force[i] = Vec<2>(0.5, -0.25);
      }
      s.p.surface[i] = s.p.kind[i] == kFluid && s.p.x[i][1] > 0.1 && s.p.x[i][1] < 0.3;
    }
    return s;
  };
  Scene one = scene(), shared = scene();
  const int n = static_cast<int>(one.p.size());
  NeighborSearch<2> search(one.domain, one.kernel.support());
  Neighbors<2> all_rows, own_rows;
  search.build(one.p, one.kernel, all_rows);
  search.build(shared.p, shared.kernel, own_rows, share.first(n), share.last(n));

  const Vec<2> g(0.0, -9.81);
  mark_dry_solids(one.p, all_rows, g);
  mark_dry_solids(shared.p, own_rows, g, &share);
  share.exchange(shared.p.surface);
  int differ = 0, dry = 0;
  for (int i = 0; i < n; ++i) {
    differ += one.p.surface[i] != shared.p.surface[i];
    dry += one.p.surface[i] == kDrySolid;
  }
  EXPECT_EQ(differ, 0) << "surface marks that differ from the one-process result";
  EXPECT_GT(dry, 0) << "no dry solid: the scene tests nothing";

  const int blended_one = follow_enclosing_solids(one.p, all_rows, 0.5, 1000.0, 1e-4);
  const int blended = follow_enclosing_solids(shared.p, own_rows, 0.5, 1000.0, 1e-4, &share);
  share.exchange(shared.p.v);
  differ = 0;
  for (int i = 0; i < n; ++i)
    differ += one.p.v[i] != shared.p.v[i] || one.p.solid_force[i] != shared.p.solid_force[i];
  EXPECT_EQ(blended, blended_one);
  EXPECT_GT(blended_one, n / 10) << "few pockets: the scene tests little";
  EXPECT_EQ(differ, 0) << "velocities or solid forces that differ from the one-process blend";
}

}  // namespace
}  // namespace isph
