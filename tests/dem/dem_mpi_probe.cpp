// MPI check of tag-keyed loads: free spheres (kept apart) in a periodic box are pushed across
// the rank boundary by loads that depend on the tag and change every chunk. After the run every
// sphere's velocity must equal its own impulse / mass, whichever rank it ended on; rank 0 writes
// the final state (%.17g) so that a script can compare runs on 1 and 2 ranks.
// usage: dem_mpi_probe INPUT OUT_FILE   (exit 1 on failure)
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "atom.h"
#include "dem/dem_liggghts_backend.hpp"

namespace {

using isphdem::Vec3;

std::set<int> local_tags(isphdem::LiggghtsBackend& dem) {
  auto* atom = dem.lammps()->atom;
  return std::set<int>(atom->tag, atom->tag + atom->nlocal);
}

int run(const char* input, const char* out) {
  int rank = 0, nprocs = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  isphdem::LiggghtsBackend dem({"-log", "none", "-echo", "none", "-screen", "/dev/null"});
  dem.initialize({input, {}});
  const auto start = local_tags(dem);
  const auto atoms0 = dem.state().atoms;
  // create_atoms numbers atoms differently on 1 and 2 ranks, so loads and output follow each
  // sphere's initial lattice site (key), while the loads are still handed over by tag.
  std::vector<int> tags, key;
  for (const auto& a : atoms0) {
    tags.push_back(a.tag);
    auto site = [&](int d) { return static_cast<int>(std::floor(a.x[d] / 0.0025)); };
    key.push_back(site(0) + 8 * (site(1) + 4 * site(2)));
  }

  const double r = 0.0005, m = 2600.0 * 4.0 / 3.0 * M_PI * r * r * r, dt = dem.timestep();
  const int chunks = 20, n_sub = 100;
  std::vector<Vec3> impulse(tags.size(), Vec3{});
  for (int c = 0; c < chunks; c++) {
    std::vector<Vec3> f(tags.size()), t(tags.size(), Vec3{1e-12, 0, 0});
    for (size_t k = 0; k < tags.size(); k++) {
      // All pushed along +x (through the rank boundary and the periodic one), with small
      // tag-dependent differences that keep them from touching.
      const double s = (1.0 + 0.002 * (key[k] % 5)) * (1.0 + 0.05 * (c % 4));
      f[k] = {1e-3 * s, 1e-6 * (key[k] % 7), -2e-6 * (c % 3)};
      for (int d = 0; d < 3; d++) impulse[k][d] += f[k][d] * n_sub * dt;
    }
    // Only rank 0's loads count (DemBackend contract): the others pass nothing.
    if (rank == 0)
      dem.set_atom_loads(tags, f, t);
    else
      dem.set_atom_loads({}, {}, {});
    dem.advance(n_sub);
  }

  const auto end = local_tags(dem);
  int moved = 0, moved_all = 0;
  for (int tag : end) moved += !start.count(tag);
  MPI_Allreduce(&moved, &moved_all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);

  const auto& s = dem.state();
  double worst = 0;
  for (size_t k = 0; k < s.atoms.size(); k++)
    for (int d = 0; d < 3; d++)
      worst = std::max(
          worst, std::fabs(s.atoms[k].v[d] - impulse[k][d] / m) / std::fabs(impulse[k][0] / m));
  if (rank == 0) {
    std::printf("%d rank(s): %zu spheres, %d changed rank, max relative velocity error %.3e\n",
                nprocs, s.atoms.size(), moved_all, worst);
    std::vector<size_t> order(s.atoms.size());
    for (size_t k = 0; k < order.size(); k++) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return key[i] < key[j]; });
    FILE* f = std::fopen(out, "w");
    for (size_t k : order) {
      const auto& a = s.atoms[k];
      std::fprintf(f, "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", key[k], a.x[0],
                   a.x[1], a.x[2], a.v[0], a.v[1], a.v[2], a.omega[0], a.omega[1], a.omega[2]);
    }
    std::fclose(f);
  }
  if (worst > 1e-9) return 1;
  if (nprocs > 1 && moved_all == 0) {
    if (rank == 0) std::printf("FAIL: no sphere changed rank; the test proves nothing\n");
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rc = 2;
  if (argc == 3) rc = run(argv[1], argv[2]);
  MPI_Finalize();
  return rc;
}
