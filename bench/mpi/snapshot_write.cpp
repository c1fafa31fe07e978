// The cost of a fluid snapshot on mpirun's ranks (issue 26): the same N-particle /fluid group
// (2D, the contract's seven datasets) written (a) by the ranks together, each its block of rows
// (parallel HDF5, collective), and (b) by rank 0 alone holding every row (how the output was
// written before). Repeated R times each, alternating, into a scratch directory; prints one CSV
// line (rank 0):
//   ranks, particles, MB per snapshot, collective ms (median), rank-0 ms (median), ratio
// usage: mpirun -np P bench_snapshot_write DIR [N=160000] [R=7]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include "io/snapshot_writer.hpp"

namespace {

// Rows [first, last) of an N-particle fluid, values from the global row.
isphdem::Snapshot fluid_rows(long step, std::size_t first, std::size_t last) {
  isphdem::Snapshot s;
  s.step = step;
  s.time = 1e-3 * step;
  auto& g = s.group("fluid");
  const std::size_t n = last - first;
  auto row = [&](std::size_t i) { return static_cast<double>(first + i); };
  g.add_generated<double>("position", n, 2, [&](auto i, auto c) { return 1e-3 * row(i) + c; });
  g.add_generated<double>("velocity", n, 2, [&](auto i, auto c) { return 1e-6 * row(i) - c; });
  g.add_generated<double>("pressure", n, 1, [&](auto i, auto) { return 1e3 + row(i); });
  g.add_generated<double>("porosity", n, 1, [&](auto, auto) { return 1.0; });
  g.add_generated<std::int32_t>("kind", n, 1, [&](auto, auto) { return 0; });
  g.add_generated<std::int32_t>("free_surface", n, 1, [&](auto, auto) { return 0; });
  g.add_generated<std::int64_t>("id", n, 1, [&](auto i, auto) { return first + i; });
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (argc < 2) {
    if (rank == 0) std::fprintf(stderr, "usage: mpirun -np P bench_snapshot_write DIR [N] [R]\n");
    MPI_Finalize();
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 160000;
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 7;
  const std::size_t first = n * rank / ranks, last = n * (rank + 1) / ranks;
  const isphdem::Snapshot mine = fluid_rows(0, first, last);
  const isphdem::Snapshot whole = rank == 0 ? fluid_rows(0, 0, n) : isphdem::Snapshot{};

  isphdem::SnapshotWriter together(dir / "collective", true, MPI_COMM_WORLD);
  std::unique_ptr<isphdem::SnapshotWriter> alone;
  if (rank == 0) alone = std::make_unique<isphdem::SnapshotWriter>(dir / "rank0");
  std::vector<double> collective, serial;
  for (int r = 0; r < repeats; ++r) {
    isphdem::Snapshot a = mine, b = whole;
    a.step = b.step = r;
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    together.write(a);
    MPI_Barrier(MPI_COMM_WORLD);
    collective.push_back(MPI_Wtime() - t0);
    t0 = MPI_Wtime();
    if (rank == 0) alone->write(b);
    MPI_Barrier(MPI_COMM_WORLD);  // the other ranks wait for rank 0, as they did in a run
    serial.push_back(MPI_Wtime() - t0);
  }
  if (rank == 0) {
    const double mb =
        std::filesystem::file_size(dir / "collective" / isphdem::SnapshotWriter::file_name(0)) /
        1e6;
    std::printf("ranks,particles,mb_per_snapshot,collective_ms,rank0_ms,ratio\n");
    std::printf("%d,%zu,%.2f,%.2f,%.2f,%.3f\n", ranks, n, mb, 1e3 * median(collective),
                1e3 * median(serial), median(collective) / median(serial));
  }
  MPI_Finalize();
  return 0;
}
