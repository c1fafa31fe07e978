#include "run/fluid_case.hpp"

#include <mpi.h>
#include <omp.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"
#include "io/diagnostics_writer.hpp"
#include "io/fluid_snapshot.hpp"
#include "io/progress_line.hpp"
#include "io/snapshot_writer.hpp"
#include "run/checkpoints.hpp"
#include "run/fluid_checkpoint.hpp"
#include "run/fluid_run.hpp"
#include "run/interrupt.hpp"
#include "run/ranks_notice.hpp"
#include "run/replicated_ranks.hpp"
#include "run/run_loop.hpp"
#include "study/run_result.hpp"

namespace isphdem {

namespace fs = std::filesystem;

// A fluid-only case. On several ranks (mpirun) with solver.preconditioner = "amg" each rank holds
// and steps its own part of the fluid (FluidRun::decompose), the pressure equation one system
// over the ranks; with parallel.decompose = false every rank holds all particles and computes
// its block of rows. The ranks write each snapshot together (each its own rows); rank 0 talks and
// writes diagnostics.csv.
template <int Dim>
int run_fluid_case(const CaseFile& c, const RunArguments& args, RunReport& report) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const bool talk = rank == 0 && !args.quiet;
  const RunSettings settings = parse_run_settings(c);
  // Decomposed from the start: each rank builds only its share of the particles, and no rank
  // ever holds the whole fluid. The checks of the scene then see a rank's share: every rank
  // stops with the first failing rank's message.
  const bool split = FluidRun<Dim>::decomposes(
      settings, c.string("solver.preconditioner", isph::LinearSolverConfig{}.preconditioner),
      ranks);
  FluidScene<Dim> scene;
  agree_on_failure(split, [&] {
    scene = build_fluid_scene<Dim>(c, rank, split ? ranks : 1);
    isph::IsphSolver<Dim>::check_inside(scene.particles, scene.domain);
  });
  FluidRun<Dim> run(std::move(scene), settings);  // collective when split (decomposed at once)
  auto& solver = run.solver();
  const auto& P = solver.particles();
  // The ranks must start from the same fluid, whether or not they then keep only their part.
  if (!split) check_replicas(P, solver.steps());
  const bool decomposed = run.decompose();
  Checkpoints checkpoints(args.out, settings.checkpoint_interval, MPI_COMM_WORLD);
  checkpoints.set_identity(run_identity(case_fingerprint(c.path()), args.overrides));
  RunPosition position;
  if (args.resume) {
    CheckpointArrays saved;
    position = checkpoints.resume(saved);
    restore_fluid(solver, saved);
    if (talk)
      std::printf("isphdem run: resuming from %s (t = %g s, step %ld)\n",
                  checkpoints.resumed_directory().string().c_str(), solver.time(), solver.steps());
  }
  // Over all ranks when decomposed (collective): the counts, the limits and the first step.
  std::array<double, 3> count{double(P.count(isph::kFluid)), double(P.count(isph::kWall)),
                              double(P.size())};
  if (const isph::RowShare* d = solver.decomposition()) d->sum_in_place(count.data(), 3);
  const long particles = long(count[2]);
  const auto l = solver.limits();
  const double first_dt = run.next_dt();

  if (talk) {
    std::printf("isphdem run: %s (%dD)\n  particles: %.0f fluid, %.0f wall; dx = %g m, h = %g m\n",
                c.path().string().c_str(), Dim, count[0], count[1], P.spacing, solver.kernel().h());
    if (settings.fixed_dt)
      std::printf("  time step: fixed %g s (stable limit now %g s, %s)\n", *settings.fixed_dt,
                  l.min(), l.limiting().c_str());
    else
      std::printf("  time step: auto, now %g s (%s limit; CFL %g, viscous %g, force %g s)\n",
                  first_dt, l.limiting().c_str(), l.cfl, l.viscous, l.force);
    std::printf("  output: %s every %g s to t = %g s\n", args.out.string().c_str(),
                settings.output_interval, settings.t_end);
    std::fflush(stdout);
  }
  say_ranks(ranks_notice(ranks, decomposed, solver.config().pressure_solver.preconditioner), rank,
            talk);

  const std::vector<std::string> columns{
      "time",           "step",         "wall_seconds",      "ppe_iterations",
      "max_speed",      "dt",           "ppe_residual",      "surface_particles",
      "kinetic_energy", "fluid_volume", "max_eddy_viscosity"};
  report.check_columns(columns);  // before the writer clears an earlier run's output
  SnapshotWriter writer(args.out, !args.resume, MPI_COMM_WORLD);
  if (args.resume)
    writer.resume_after(checkpoints.resumed_step());
  else
    checkpoints.start_fresh();
  std::unique_ptr<DiagnosticsWriter> diagnostics;
  if (rank == 0) {
    // The case as run, overrides applied, next to the results.
    std::ofstream f(args.out / "case_used.toml");
    f << "# " << c.path().string() << " with the overrides of this run\n" << c.table() << "\n";
    diagnostics = std::make_unique<DiagnosticsWriter>(args.out / "diagnostics.csv", columns,
                                                      args.resume, checkpoints.resumed_step());
  }
  auto snapshot = [&]() {
    if (!decomposed) check_replicas(P, solver.steps());
    write_collectively(rank, [&] {
      Snapshot s;
      s.step = solver.steps();
      s.time = solver.time();
      const auto [first, last] = solver.own_block();
      add_fluid_group(P, s, first, last);
      writer.write(s);
    });
  };

  const double start = omp_get_wtime() - position.wall_seconds;
  // This process's share of a resumed run: what the stage timings cover.
  const double process_start = omp_get_wtime();
  const long steps_before = solver.steps();
  ProgressLine progress(settings.t_end, talk);
  if (!args.resume) snapshot();
  long ppe_total = position.ppe_total;
  auto after_step = [&](const isph::StepStats& st) {
    ppe_total += st.ppe_iterations;
    const long step = solver.steps();
    if (step % settings.diagnostics_every == 0) {
      const double ke = run.kinetic_energy();
      write_on_rank_zero(rank, [&] {
        diagnostics->row({solver.time(), double(step), omp_get_wtime() - start,
                          double(st.ppe_iterations), st.max_speed, st.dt, st.ppe_residual,
                          double(st.surface_particles), ke, st.fluid_volume,
                          st.max_eddy_viscosity});
      });
    }
    progress.update(solver.time(), step);
  };
  auto save = [&](long k) {
    return checkpoints.write(solver.steps(), solver.time(),
                             RunPosition{k, 0, ppe_total, omp_get_wtime() - start},
                             [&](CheckpointArrays& a, const fs::path&) { save_fluid(solver, a); });
  };
  std::string why, cause;
  long k = args.resume ? position.output_index : 1;
  bool finished = false;
  try {
    InterruptHandlers handlers;
    finished = run_to_end(run, settings, 1e-12, after_step, snapshot, progress, rank == 0, args.out,
                          why, cause, k, checkpoints, save);
  } catch (const Interrupted& e) {
    progress.finish();
    report.cost(solver.time(), solver.steps(), particles, omp_get_wtime() - start, ppe_total);
    report.stages(omp_get_wtime() - process_start, fluid_stage_seconds(solver.timings()));
    report.parallel(solver.row_parts(), solver.rows_shared(), decomposed);
    report.interrupted(announce_interruption(e, args.file.string(), args.out.string(),
                                             args.overrides, ranks, rank == 0));
    return e.exit_status();
  }
  report.cost(solver.time(), solver.steps(), particles, omp_get_wtime() - start, ppe_total);
  report.stages(omp_get_wtime() - process_start, fluid_stage_seconds(solver.timings()));
  report.parallel(solver.row_parts(), solver.rows_shared(), decomposed);
  if (!finished) {
    report.stopped(why, cause);
    return 1;
  }

  if (talk) {
    const double wall = omp_get_wtime() - start;
    const auto& t = solver.timings();
    const long steps = solver.steps();
    std::printf(
        "done: t = %g s in %ld steps, %s wall, %.3g particle-steps/s, %.1f PPE iterations/step\n",
        solver.time(), steps, format_duration(wall).c_str(), double(particles) * steps / wall,
        steps ? double(ppe_total) / steps : 0.0);
    std::printf(
        "  time per part: neighbours %.0f%%, operators %.0f%%, assembly %.0f%%, solve %.0f%%, "
        "rest %.0f%%\n",
        100 * t.neighbors() / t.total(), 100 * t.operators() / t.total(),
        100 * t.assembly() / t.total(), 100 * t.solve() / t.total(), 100 * t.rest() / t.total());
    print_fluid_stages(t, steps - steps_before);
    print_ppe_cost(solver, solver.steps() - steps_before);
  }
  return 0;
}

template int run_fluid_case<2>(const CaseFile&, const RunArguments&, RunReport&);
template int run_fluid_case<3>(const CaseFile&, const RunArguments&, RunReport&);

}  // namespace isphdem
