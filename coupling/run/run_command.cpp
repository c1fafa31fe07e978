#include "run/run_command.hpp"

#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/coupling_table.hpp"
#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"
#include "case/verb_arguments.hpp"
#include "dem/dem_case_config.hpp"
#include "dem/dem_communicator.hpp"
#include "dem/dem_liggghts_backend.hpp"
#include "dem/dem_run_case.hpp"
#include "io/dem_snapshot.hpp"
#include "io/diagnostics_writer.hpp"
#include "io/fluid_snapshot.hpp"
#include "io/progress_line.hpp"
#include "io/rank_agreement.hpp"
#include "io/snapshot_writer.hpp"
#include "run/auto_model.hpp"
#include "run/case_keys.hpp"
#include "run/checkpoints.hpp"
#include "run/coupled_run.hpp"
#include "run/coupling_stages.hpp"
#include "run/dem_only_run.hpp"
#include "run/erosion_diagnostics.hpp"
#include "run/fluid_case.hpp"
#include "run/fluid_checkpoint.hpp"
#include "run/fluid_run.hpp"
#include "run/interrupt.hpp"
#include "run/ranks_notice.hpp"
#include "run/replicated_ranks.hpp"
#include "run/run_loop.hpp"
#include "run/run_report.hpp"
#include "study/run_result.hpp"
#include "unresolved/unresolved_coupling.hpp"

namespace isphdem {

namespace fs = std::filesystem;

namespace {

// The fluid's stages and the coupled step's own parts (RunResult::stage_seconds).
std::vector<std::pair<std::string, double>> coupled_stage_seconds(const CoupledTimings& c,
                                                                  const isph::StepTimings& f) {
  auto s = fluid_stage_seconds(f);
  s.emplace_back("coupling", c.coupling);
  s.emplace_back(c.staggered ? "dem_wait" : "dem", c.staggered ? c.dem_wait : c.dem);
  return s;
}

// The staggered DEM's own seconds, on its thread beside the others.
std::vector<std::pair<std::string, double>> dem_beside(const CoupledTimings& c) {
  if (!c.staggered) return {};
  return {{"dem_beside", c.dem}};
}

const char* kUsage =
    "usage: isphdem run CASE.toml --out DIR [--set key=value ...] [--quiet] [--resume]\n"
    "  --out DIR        output directory (snap_<step>.h5, *.xdmf, diagnostics.csv, result.json);\n"
    "                   results of an earlier run there are replaced\n"
    "  --set key=value  override a case key, e.g. --set time.end=0.2 (repeatable)\n"
    "  --quiet          no progress line and no summary\n"
    "  --resume         continue from the newest checkpoint in DIR (same case, --set and ranks;\n"
    "                   time.end may be later)\n";

using Arguments = RunArguments;

// LIGGGHTS's restart in a coupled run's checkpoint directory.
const char* const kDemRestart = "dem.restart";
// coupling.model as a checkpoint stores it ("coupled_model": the index here), for "auto".
const char* const kModels[] = {"unresolved", "resolved", "semi-resolved"};

// The arrays of `a` whose names start with `prefix`, without it.
StageState with_prefix(const CheckpointArrays& a, const std::string& prefix) {
  StageState s;
  for (const auto& [name, v] : a.reals)
    if (name.compare(0, prefix.size(), prefix) == 0) s[name.substr(prefix.size())] = v;
  return s;
}

DemCaseConfig dem_config(const CaseFile& c) {
  const auto* table = c.table()["dem"].as_table();
  if (!table) throw CaseError("'dem' must be a table: [dem] with script and substeps");
  try {
    return parse_dem_table(*table, c.directory());
  } catch (const std::runtime_error& e) {
    throw CaseError(e.what());
  }
}

// A case with [fluid] and [dem]: fine grains (free spheres) coupled unresolved, clumps resolved.
// The DEM state is gathered to every rank; the fluid (PMS bodies' particles included) is
// decomposed over the ranks as in a fluid-only case. The ranks write each snapshot together, the
// grains from rank 0.
template <int Dim>
int run_coupled(const CaseFile& given, const Arguments& args, RunReport& report) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const bool talk = rank == 0 && !args.quiet;
  const RunSettings settings = [&] {
    RunSettings s = parse_run_settings(given);
    s.coupled = true;
    return s;
  }();
  const DemCaseConfig dem = dem_config(given);
  // Checked here as well as in CoupledRun so that it stops before LIGGGHTS writes its screen.
  if (!settings.fixed_dt)
    throw CaseError(
        "a coupled case needs a fixed fluid step: set time.dt = [dem] substeps x the "
        "script's DEM timestep (not \"auto\")");
  FluidScene<Dim> scene = build_fluid_scene<Dim>(given);
  const double dt = settings.fixed_dt.value_or(0.0), dx = scene.particles.spacing;
  // Built before LIGGGHTS starts, so that a bad coupling key stops the run first; "auto" needs
  // the grains, so its stages come after.
  const bool choose = coupling_model(given) == "auto";
  const AutoThresholds thresholds = choose ? auto_thresholds(given) : AutoThresholds{};
  std::vector<std::unique_ptr<CouplingStage<Dim>>> stages;
  if (!choose) stages = make_coupling_stages<Dim>(given, scene, dt, rank == 0 && !args.resume);
  Vec3 up{0.0, 0.0, 0.0};
  {
    isph::Vec<Dim> g = scene.config.gravity;
    if (g.norm() == 0.0) g[Dim - 1] = -1.0;
    for (int a = 0; a < Dim; ++a) up[a] = -g[a] / g.norm();
  }
  // Checked on every rank before LIGGGHTS starts and before anything in OUT is replaced.
  std::vector<std::string> columns{"time",
                                   "step",
                                   "wall_seconds",
                                   "ppe_iterations",
                                   "max_speed",
                                   "dt",
                                   "atoms",
                                   "bed_height",
                                   "max_grain_speed",
                                   "max_body_speed",
                                   "min_porosity",
                                   "floored_porosity",
                                   "drag_total_up",
                                   "fluid_resistance_up",
                                   "hydro_force_x",
                                   "hydro_force_y",
                                   "hydro_force_z",
                                   "max_overlap",
                                   "dem_seconds",
                                   "coupling_seconds",
                                   "fluid_seconds"};
  for (const auto& e : ErosionDiagnostics<Dim>::columns()) columns.push_back(e);
  report.check_columns(columns);
  if (rank == 0) fs::create_directories(args.out);
  // Staggered, LIGGGHTS's collectives run beside the fluid's: on a communicator of their own.
  // Declared before the backend, so that it is freed after it.
  const DemCommunicator dem_comm(dem.exchange == DemExchange::staggered);
  LiggghtsBackend backend(dem.liggghts_args(args.out), dem_comm.get());
  // Resumed: the fluid and the run's loop from this rank's file, the grains from LIGGGHTS's
  // restart in the checkpoint, read where the script reads its own.
  Checkpoints checkpoints(args.out, settings.checkpoint_interval, MPI_COMM_WORLD);
  checkpoints.set_identity(run_identity(case_fingerprint(given.path()), args.overrides));
  RunPosition position;
  CheckpointArrays saved;
  if (args.resume) {
    position = checkpoints.resume(saved);
    backend.resume_from((checkpoints.resumed_directory() / kDemRestart).string(),
                        saved.real("solver_time"));
  }
  backend.initialize({dem.script, {}});
  // Run on without grains, the fluid alone would pass for a coupled result. Seen on 2 ranks:
  // LIGGGHTS inserts into each processor's part of an insertion region, and a region that a
  // processor boundary cuts into parts smaller than the grain stays empty (a warning only).
  if (backend.state().atoms.empty())
    throw CaseError("the LIGGGHTS script " + dem.script.string() +
                    " created no grains (its screen output in " + args.out.string() +
                    " says why): a coupled case needs grains. On several ranks, a small insertion "
                    "region cut by a processor boundary stays empty: widen the region, or place "
                    "the processor grid with the script's `processors` command");
  std::vector<std::string> auto_lines;
  const CaseFile c = [&] {
    if (!choose) return given;
    if (args.resume) {  // the first run's choice, made from the grains it started with
      const auto code = saved.integer("coupled_model");
      if (code < 0 || code >= std::int64_t(std::size(kModels)))
        throw CaseError("--resume: the checkpoint's coupling model is unknown");
      const std::string model = kModels[code];
      auto_lines.push_back("coupling.model = \"auto\" -> \"" + model + "\" (as chosen at t = 0)");
      return given.with_override("coupling.model=\"" + model + "\"");
    }
    const AutoChoice a = choose_model(backend.state(), dx, thresholds);
    auto_lines.push_back("coupling.model = \"auto\" -> \"" + a.model + "\"");
    for (const auto& g : a.classes) auto_lines.push_back("  " + describe(g, dx));
    return given.with_override("coupling.model=\"" + a.model + "\"");
  }();
  if (choose) stages = make_coupling_stages<Dim>(c, scene, dt, rank == 0 && !args.resume);
  const GrainModels models = grain_models(coupling_model(c));
  CoupledRun<Dim> run(std::move(scene), settings, backend, dem.substeps, std::move(stages),
                      dem.exchange);
  auto& solver = run.solver();
  const auto& P = solver.particles();
  const UnresolvedCoupling<Dim>* unresolved = nullptr;
  for (const auto& st : run.stages())
    if (!unresolved) unresolved = dynamic_cast<const UnresolvedCoupling<Dim>*>(st.get());
  if (talk) {
    std::printf(
        "isphdem run: %s (%dD, coupled)\n  fluid: %zu fluid, %zu wall particles; dx = %g m\n"
        "  DEM: %s, %zu atoms; fluid dt %g s = %d x DEM dt %g s\n  output: %s every %g s to "
        "t = %g s\n",
        c.path().string().c_str(), Dim, P.count(isph::kFluid), P.count(isph::kWall), P.spacing,
        dem.script.string().c_str(), backend.state().atoms.size(), run.dt(), run.substeps(),
        backend.timestep(), args.out.string().c_str(), settings.output_interval, settings.t_end);
    for (const auto& line : auto_lines) std::printf("  %s\n", line.c_str());
    std::fflush(stdout);
  }
  check_replicas(P, solver.steps());  // the ranks start from the same fluid
  long particles = long(P.size());
  const bool decomposed = run.decompose();
  say_ranks(ranks_notice(ranks, decomposed, solver.config().pressure_solver.preconditioner), rank,
            talk);
  // Grain density for the mass of ejected fines: that of the clumps when there are any (the
  // DEM state has no per-atom mass).
  double grain_density = std::nan("");
  for (const auto& b : backend.state().bodies)
    if (b.volume > 0) grain_density = b.mass / b.volume;
  ErosionDiagnostics<Dim> erosion(
      backend.state(), up, c.has("inflow.velocity") ? std::abs(c.number("inflow.velocity")) : 1.0,
      grain_density);
  if (args.resume) {
    restore_fluid(solver, saved);
    run.restore(with_prefix(saved, "coupled_"));
    erosion.restore(saved.real_array("erosion_layer"));
    // The first run's count (its bodies' PMS particles were made at their first poses).
    const isph::RowShare* d = solver.decomposition();
    particles = long(d ? d->sum(double(P.size())) : double(P.size()));
    if (talk)
      std::printf("isphdem run: resuming from %s (t = %g s, step %ld)\n",
                  checkpoints.resumed_directory().string().c_str(), solver.time(), solver.steps());
  }
  SnapshotWriter writer(args.out, !args.resume, MPI_COMM_WORLD);
  if (args.resume)
    writer.resume_after(checkpoints.resumed_step());
  else
    checkpoints.start_fresh();
  std::unique_ptr<DiagnosticsWriter> diagnostics;
  if (rank == 0) {
    std::ofstream f(args.out / "case_used.toml");
    f << "# " << c.path().string() << " with the overrides of this run\n" << c.table() << "\n";
    diagnostics = std::make_unique<DiagnosticsWriter>(args.out / "diagnostics.csv", columns,
                                                      args.resume, checkpoints.resumed_step());
  }
  auto snapshot = [&]() {
    const DemState& state = backend.state();  // collective
    if (!decomposed) check_replicas(P, solver.steps());
    Snapshot s;
    s.step = solver.steps();
    s.time = solver.time();
    const auto [first, last] = solver.own_block();
    add_fluid_group(P, s, first, last);
    // The grains are written by rank 0 (every rank holds the gathered DEM state).
    if (rank == 0) add_dem_groups(state, hydro_loads(run.loads()), s, &models);
    write_collectively(rank, [&] { writer.write(s); });
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
      const DemState& state = backend.state();  // collective
      // What each rank's own fluid particles give, over all ranks (collective when decomposed).
      double emin = 1.0;
      for (std::size_t i = 0; i < P.size(); ++i)
        if (P.kind[i] != isph::kWall) emin = std::min(emin, P.porosity[i]);
      ErosionMeasures em = erosion.measure(state, P);
      if (const isph::RowShare* ranks = solver.decomposition()) {
        emin = -ranks->max(-emin);
        em.pore_speed_ratios = ranks->concatenate(em.pore_speed_ratios);
        set_pore_speeds(em);
      }
      if (rank == 0) {
        double vmax = 0.0, body_vmax = 0.0;
        for (const auto& a : state.atoms)
          if (a.body == -1) vmax = std::max(vmax, norm(a.v));
        for (const auto& b : state.bodies) body_vmax = std::max(body_vmax, norm(b.v));
        double drag_up = 0.0, res_up = 0.0;
        std::size_t floored = 0;
        if (unresolved) {  // coupling.model = "resolved" has no porosity/drag stage
          const auto& b = unresolved->balance();
          floored = b.floored;
          for (int a = 0; a < Dim; ++a) {
            drag_up += (b.grain_drag[a] + b.grain_pressure[a]) * up[a];
            res_up += b.fluid_resistance[a] * up[a];
          }
        }
        const auto& t = run.timings();
        const Vec3 hydro = total_force(run.loads());
        std::vector<double> row{solver.time(),
                                double(step),
                                omp_get_wtime() - start,
                                double(st.ppe_iterations),
                                st.max_speed,
                                st.dt,
                                double(state.atoms.size()),
                                bed_height(state, up),
                                vmax,
                                body_vmax,
                                emin,
                                double(floored),
                                drag_up,
                                res_up,
                                hydro[0],
                                hydro[1],
                                hydro[2],
                                run.max_overlap(),
                                t.dem,
                                t.coupling,
                                t.fluid};
        for (double v : ErosionDiagnostics<Dim>::row(em)) row.push_back(v);
        write_on_rank_zero(rank, [&] { diagnostics->row(row); });
      }
    }
    if (rank == 0) progress.update(solver.time(), step);
  };
  std::string why, cause;
  const int model = int(std::find(std::begin(kModels), std::end(kModels), coupling_model(c)) -
                        std::begin(kModels));
  auto save = [&](long at) {
    return checkpoints.write(
        solver.steps(), solver.time(), RunPosition{at, 0, ppe_total, omp_get_wtime() - start},
        [&](CheckpointArrays& a, const fs::path& staged) {
          save_fluid(solver, a);
          StageState state;
          run.save(state);
          for (auto& [name, v] : state) a.reals["coupled_" + name] = std::move(v);
          a.reals["erosion_layer"] = erosion.state();
          a.set_integer("coupled_model", model);
          backend.write_restart((staged / kDemRestart).string());  // collective
        });
  };
  long k = args.resume ? position.output_index : 1;
  bool finished = false;
  try {
    InterruptHandlers handlers;
    finished = run_to_end(run, settings, 1e-9, after_step, snapshot, progress, rank == 0, args.out,
                          why, cause, k, checkpoints, save);
  } catch (const Interrupted& e) {
    progress.finish();
    backend.finalize();
    report.cost(solver.time(), solver.steps(), particles, omp_get_wtime() - start, ppe_total);
    report.stages(omp_get_wtime() - process_start,
                  coupled_stage_seconds(run.timings(), solver.timings()),
                  dem_beside(run.timings()));
    report.parallel(solver.row_parts(), solver.rows_shared(), decomposed);
    report.interrupted(announce_interruption(e, args.file.string(), args.out.string(),
                                             args.overrides, ranks_of(MPI_COMM_WORLD), rank == 0));
    return e.exit_status();
  }
  backend.finalize();
  report.cost(solver.time(), solver.steps(), particles, omp_get_wtime() - start, ppe_total);
  report.stages(omp_get_wtime() - process_start,
                coupled_stage_seconds(run.timings(), solver.timings()), dem_beside(run.timings()));
  report.parallel(solver.row_parts(), solver.rows_shared(), decomposed);
  if (!finished) {
    report.stopped(why, cause);
    return 1;
  }
  if (talk) {
    const double wall = omp_get_wtime() - start;
    const auto& t = run.timings();
    std::printf("done: t = %g s in %ld fluid steps, %s wall, %.1f PPE iterations/step\n",
                solver.time(), solver.steps(), format_duration(wall).c_str(),
                solver.steps() ? double(ppe_total) / solver.steps() : 0.0);
    if (t.staggered)
      std::printf(
          "  time per part: coupling (mapping, drag) %.0f%%, ISPH %.0f%%, waiting for the DEM "
          "%.0f%%; DEM substeps beside them %s\n",
          100 * t.coupling / t.total(), 100 * t.fluid / t.total(), 100 * t.dem_wait / t.total(),
          format_duration(t.dem).c_str());
    else
      std::printf(
          "  time per part: DEM substeps %.0f%%, coupling (mapping, drag) %.0f%%, ISPH %.0f%%\n",
          100 * t.dem / t.total(), 100 * t.coupling / t.total(), 100 * t.fluid / t.total());
    print_fluid_stages(solver.timings(), solver.steps() - steps_before);
    print_ppe_cost(solver, solver.steps() - steps_before);
  }
  return 0;
}

}  // namespace

int run_main(int argc, char** argv) {
  Arguments args;
  std::unique_ptr<RunReport> report;  // once the case is loaded: result.json at the end
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // Case and simulation errors arise alike on every rank (each reads the same case and steps the
  // same fluid): rank 0 says it. Others may be one rank's own and are said where they arise.
  auto fail = [&](const std::exception& e, bool every_rank_alike = false) {
    if (!every_rank_alike || rank == 0) std::fprintf(stderr, "isphdem run: %s\n", e.what());
    if (report && rank == 0) {
      report->error(e.what());
      try {
        report->finish(false);
      } catch (const std::exception& w) {
        std::fprintf(stderr, "isphdem run: %s\n", w.what());
      }
    }
    return 2;
  };
  try {
    static_cast<VerbArguments&>(args) = parse_verb_arguments(
        argc, argv, "case file", kUsage, [&](const std::string& arg, const auto&) {
          if (arg != "--resume") return false;
          args.resume = true;
          return true;
        });
    // A result.json never outlives the run it describes, also when this one stops at its input.
    if (rank == 0) remove_run_result(args.out);
    const CaseFile c = CaseFile::load(args.file, args.overrides, case_keys());
    report = std::make_unique<RunReport>(c, args.overrides, args.out);
    const bool has_dem = c.has("dem"), has_fluid = c.has("fluid");
    if (c.has("unresolved") && !(has_dem && has_fluid))
      throw CaseError(
          "[unresolved] couples a fluid with [dem] grains: the case needs both a "
          "[fluid] and a [dem] table, or drop [unresolved]");
    int rc = 0;
    if (has_dem && has_fluid)
      rc = case_dimension(c) == 2 ? run_coupled<2>(c, args, *report)
                                  : run_coupled<3>(c, args, *report);
    else if (has_dem && args.resume)
      throw CaseError("--resume: DEM-only cases write no checkpoints (run them anew)");
    else if (has_dem)
      rc = run_dem_only(c, args.out, args.quiet, *report);
    else
      rc = case_dimension(c) == 2 ? run_fluid_case<2>(c, args, *report)
                                  : run_fluid_case<3>(c, args, *report);
    if (rank == 0) report->finish(!args.quiet);
    return rc;
  } catch (const CaseError& e) {
    return fail(e, true);
  } catch (const isph::SimulationError& e) {
    return fail(e, true);
  } catch (const std::runtime_error& e) {  // DEM backend: missing script, refused loads
    return fail(e);
  } catch (const std::exception& e) {  // a scene the solver refuses (std::invalid_argument)
    std::fprintf(stderr, "isphdem run: error: %s\n", e.what());
    if (report && rank == 0) {
      report->error(e.what());
      try {
        report->finish(false);
      } catch (const std::exception&) {
      }
    }
    return 1;
  }
}

}  // namespace isphdem
