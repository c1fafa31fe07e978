#include "run/dem_only_run.hpp"

#include <mpi.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "case/run_settings.hpp"
#include "dem/dem_case_config.hpp"
#include "dem/dem_run_case.hpp"
#include "io/dem_snapshot.hpp"
#include "io/diagnostics_writer.hpp"
#include "io/progress_line.hpp"
#include "io/snapshot_writer.hpp"

namespace isphdem {

namespace fs = std::filesystem;

int run_dem_only(const CaseFile& c, const fs::path& out, bool quiet, RunReport& report) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const auto* table = c.table()["dem"].as_table();
  if (!table) throw CaseError("'dem' must be a table: [dem] with script and substeps");
  DemCaseConfig dem;
  try {
    dem = parse_dem_table(*table, c.directory());
  } catch (const std::runtime_error& e) {
    throw CaseError(e.what());
  }
  const RunSettings settings = parse_run_settings(c);
  const std::vector<std::string> columns{"time",      "step",  "wall_seconds", "ppe_iterations",
                                         "max_speed", "atoms", "bodies"};
  report.check_columns(columns);  // every rank, before anything in `out` is replaced
  std::unique_ptr<SnapshotWriter> writer;
  std::unique_ptr<DiagnosticsWriter> diagnostics;
  if (rank == 0) {
    writer = std::make_unique<SnapshotWriter>(out);
    diagnostics = std::make_unique<DiagnosticsWriter>(out / "diagnostics.csv", columns);
    if (!quiet)
      std::printf("isphdem run: %s (DEM only: %s, %d substeps per chunk) to t = %g s\n",
                  c.path().string().c_str(), dem.script.string().c_str(), dem.substeps,
                  settings.t_end);
  }
  const double start = omp_get_wtime();
  double next_output = 0.0;
  ProgressLine progress(settings.t_end, !quiet && rank == 0);
  DemRunOptions options;
  options.out_dir = out;
  options.fluid_dt = settings.fixed_dt;
  double t_reached = 0.0;
  long chunks = 0, atoms = 0;
  options.after_chunk = [&](DemBackend& backend, long chunk) {
    const double t = chunk * dem.substeps * backend.timestep();
    t_reached = t;
    chunks = chunk;
    const bool last = t >= settings.t_end * (1.0 - 1e-12);
    if (t < next_output * (1.0 - 1e-9) && !last) {
      if (rank == 0) progress.update(t, chunk);
      return;
    }
    const DemState state = backend.state();  // collective
    atoms = long(state.atoms.size());
    while (next_output <= t * (1.0 + 1e-9)) next_output += settings.output_interval;
    if (rank != 0) return;
    Snapshot snap;
    snap.step = state.step;
    snap.time = t;
    add_dem_groups(state, HydroLoads{}, snap);
    writer->write(snap);
    double vmax = 0.0;
    for (const auto& a : state.atoms) vmax = std::max(vmax, norm(a.v));
    diagnostics->row({t, double(state.step), omp_get_wtime() - start, 0.0, vmax,
                      double(state.atoms.size()), double(state.bodies.size())});
    progress.update(t, chunk);
  };
  int rc = 0;
  try {
    rc = run_dem_case(dem, settings.t_end, options);
  } catch (const std::runtime_error& e) {
    progress.finish();
    throw CaseError(e.what());
  }
  progress.finish();
  // Steps are DEM chunks of dem.substeps; no pressure solve.
  report.cost(t_reached, chunks, atoms, omp_get_wtime() - start, 0);
  if (rank == 0 && !quiet)
    std::printf("done: DEM-only run in %s wall\n",
                format_duration(omp_get_wtime() - start).c_str());
  return rc;
}

}  // namespace isphdem
