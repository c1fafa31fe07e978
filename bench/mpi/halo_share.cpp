// The decomposed fluid's overheads, measured with sph_mpi/ on the ranks of mpirun (issue 26's
// weak-scaling estimate): a jittered lattice of N particles per rank in a periodic square (weak
// scaling: the box grows with the ranks), cut by the RCB tree, migrated, and given a halo one
// kernel support wide (2.6 dx, Wendland C2 at h = 1.3 dx). Prints one CSV line (rank 0):
//   ranks, particles per rank, halo share mean and max (halo / owned), the time of one halo
//   refresh of a 2D vector array (the largest over ranks, mean of R), of one allreduce of a
//   double, and of one exchange of the shared rows (MPI_Allgatherv of the same array).
// usage: mpirun -np P bench_halo_share [N=40000] [R=50]
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "block_row_share.hpp"
#include "lattice.hpp"
#include "particle_exchange.hpp"
#include "rcb_tree.hpp"

namespace {

template <class F>
double mean_seconds(int repeats, F&& f) {
  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = MPI_Wtime();
  for (int r = 0; r < repeats; ++r) f();
  double t = (MPI_Wtime() - t0) / repeats;
  MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const long per_rank = argc > 1 ? std::atol(argv[1]) : 40000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 50;
  const double dx = 0.005;
  const int side = static_cast<int>(std::lround(std::sqrt(double(per_rank) * ranks)));

  isph::Domain<2> domain;
  domain.lo = isph::Vec<2>(0.0, 0.0);
  domain.hi = isph::Vec<2>(side * dx, side * dx);
  domain.periodic = {true, true};
  isph::Particles<2> p;
  p.spacing = dx;
  p.volume = dx * dx;
  isph::fill_box<2>(p, domain.lo, domain.hi, dx, isph::kFluid);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.2 * dx, 0.2 * dx);
  for (auto& x : p.x) {
    x += isph::Vec<2>(jitter(rng), jitter(rng));
    domain.wrap(x);
  }
  // Each rank starts with a contiguous slice, as after reading a case; migrate sorts it out.
  const std::size_t n = p.size();
  const std::size_t first = n * rank / ranks, last = n * (rank + 1) / ranks;
  std::vector<int> mine;
  for (std::size_t i = first; i < last; ++i) mine.push_back(static_cast<int>(i));
  p.permute(mine);
  p.for_each_array([&](auto& a) { a.resize(mine.size()); });

  const auto tree = isph::RcbTree<2>::build(MPI_COMM_WORLD, domain, p.x);
  isph::migrate(MPI_COMM_WORLD, tree, p);
  const isph::HaloPlan plan = isph::add_halo(MPI_COMM_WORLD, tree, 2.6 * dx, p);
  double share = double(p.size() - plan.owned) / plan.owned, share_max = share, share_mean = share;
  MPI_Allreduce(&share, &share_max, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(&share, &share_mean, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  share_mean /= ranks;

  std::vector<isph::Vec<2>> v(p.size(), isph::Vec<2>(1.0, 2.0));
  const double refresh =
      mean_seconds(repeats, [&] { isph::refresh_halo(MPI_COMM_WORLD, plan, v); });
  double x = 1.0;
  const double allreduce = mean_seconds(
      repeats, [&] { MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD); });
  // The shared rows' exchange of the same array over all particles (every rank holds them all).
  const isph::BlockRowShare rows(MPI_COMM_WORLD);
  std::vector<isph::Vec<2>> all(n, isph::Vec<2>(1.0, 2.0));
  const double gather = mean_seconds(repeats, [&] { rows.exchange(all); });
  if (rank == 0)
    std::printf("%d,%ld,%.4f,%.4f,%.4g,%.4g,%.4g\n", ranks, per_rank, share_mean, share_max,
                1e3 * refresh, 1e6 * allreduce, 1e3 * gather);
  MPI_Finalize();
  return 0;
}
