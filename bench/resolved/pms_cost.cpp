// Cost of the resolved (PMS) coupling per clump and fluid step, and its growth with the number
// of PMS particles (issue 6). The stream of examples/cylinder_re20_2d (periodic, U = 20 mm/s,
// here at dx = 2 mm: 15 000 particles) with N square clumps of s x s lattice particles each,
// held fixed on a grid downstream of the forcing zone; every run has the same total particle
// count, because PMS particles take the places of the fluid they replace. A stream rather than
// still water: in still water the warm-started pressure solve needs almost no iterations and
// the step is not representative. Per configuration it times, over the same steps:
//   coupling - the stage's own work (placing PMS particles before the step, summing forces and
//              torques after it);
//   step     - IsphSolver::step, whose extra cost with bodies (solid rows in the pressure
//              equation, waterline marking) is step minus the no-body step;
// and prints a markdown table. Usage: bench_resolved [STEPS] [REPEATS] (default 100, 3).
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/fluid_scene.hpp"
#include "resolved/resolved_coupling.hpp"
#include "run/case_keys.hpp"

namespace {

using namespace isphdem;

FluidScene<2> stream() {
  return build_fluid_scene<2>(
      CaseFile::load(std::string(ISPHDEM_SOURCE_DIR) + "/examples/cylinder_re20_2d/case.toml",
                     {"particles.spacing=0.002"}, case_keys()));
}

// n clumps (n = k^2) of s x s dx-wide spheres on the lattice (one PMS particle per sphere, as in
// the seed), on a k x k grid over x in [50, 250] mm, y in [0, 200] mm.
DemState clumps(int n, int s, double dx) {
  DemState st;
  const int k = static_cast<int>(std::lround(std::sqrt(n)));
  int tag = 1;
  for (int b = 0; b < n; ++b) {
    DemBody body;
    body.id = b + 1;
    const double cx = 0.05 + 0.2 * (b % k + 0.5) / k, cy = 0.2 * (b / k + 0.5) / k;
    const double x0 = dx * (std::floor(cx / dx - 0.5 * s) + 0.5);
    const double y0 = dx * (std::floor(cy / dx - 0.5 * s) + 0.5);
    const double r = 0.5 * dx, vs = 4.0 / 3.0 * M_PI * r * r * r;
    body.x = {x0 + 0.5 * (s - 1) * dx, y0 + 0.5 * (s - 1) * dx, 0.0};
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        DemAtom a;
        a.tag = tag++;
        a.x = {x0 + i * dx, y0 + j * dx, 0.0};
        a.radius = r;
        a.body = body.id;
        st.atoms.push_back(a);
        body.members.push_back(a.tag);
      }
    body.volume = vs * s * s;
    body.mass = 2600.0 * body.volume;
    const double side = s * dx;
    body.inertia = {body.mass * side * side / 6, body.mass * side * side / 6,
                    body.mass * side * side / 6};
    body.axes = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    st.bodies.push_back(body);
  }
  return st;
}

struct Timing {
  std::size_t particles = 0, pms = 0;
  double step = 0, solve = 0, coupling = 0, ppe = 0, rest = 0;
};

Timing run(int n, int s, int steps) {
  auto scene = stream();
  isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
  const double dx = solver.particles().spacing, dt = 0.01;  // 0.1 dx / U
  DemState dem = clumps(n, s, dx);
  ResolvedSettings set;
  set.spacing = dx;
  set.fluid_density = scene.config.density;
  set.slab_thickness = dx;
  set.shape = PmsShape::PerSphere;
  ResolvedCoupling<2> stage(set);
  if (n > 0) stage.initialize(dem, solver);
  Timing t;
  t.particles = solver.particles().size();
  for (const auto& b : stage.bodies()) t.pms += b.particles;
  const auto one_step = [&](bool timed) {
    const double t0 = omp_get_wtime();
    if (n > 0) {
      stage.move_particles(dem, solver);
      stage.before_fluid_step(dem, solver);
    }
    const double t1 = omp_get_wtime(), solve0 = solver.timings().solve();
    const auto st = solver.step(dt);
    const double t2 = omp_get_wtime(), solve1 = solver.timings().solve();
    DemLoads loads;
    if (n > 0) stage.after_fluid_step(dem, solver, dt, loads);
    const double t3 = omp_get_wtime();
    if (!timed) return;
    t.coupling += (t1 - t0) + (t3 - t2);
    t.step += t2 - t1;
    t.solve += solve1 - solve0;
    t.ppe += st.ppe_iterations;
  };
  for (int k = 0; k < 20; ++k) one_step(false);  // the start-up transient
  for (int k = 0; k < steps; ++k) one_step(true);
  t.step /= steps;
  t.solve /= steps;
  t.coupling /= steps;
  t.ppe /= steps;
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 100;
  struct Config {
    int n, s;
  };
  // The no-body stream is run first and last: their difference is the timing drift.
  const std::vector<Config> configs{{0, 0}, {1, 4},  {1, 8},  {1, 16}, {1, 32},
                                    {4, 8}, {16, 4}, {16, 8}, {4, 16}, {0, 0}};
  std::printf(
      "Resolved coupling cost: the stream of examples/cylinder_re20_2d at dx = 2 mm (15 000 "
      "particles), %d timed steps of 0.01 s after 20 untimed, %d thread(s); medians of %d runs.\n"
      "rest = step - pressure solve; extra = (rest - rest without bodies) + coupling.\n\n",
      steps, omp_get_max_threads(), argc > 2 ? std::atoi(argv[2]) : 3);
  std::printf(
      "| clumps | PMS per clump | PPE it/step | step [ms] | solve [ms] | rest [ms] | "
      "coupling [ms] | extra per clump [ms] | extra per PMS particle [us] |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  // Each configuration is run `repeats` times in turn and the median of each time is kept: the
  // difference being measured is a few percent of a step.
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  std::vector<std::vector<Timing>> runs(configs.size());
  for (int r = 0; r < repeats; ++r)
    for (std::size_t k = 0; k < configs.size(); ++k)
      runs[k].push_back(run(configs[k].n, configs[k].s, steps));
  const auto median = [](std::vector<Timing> v, double Timing::*m) {
    std::sort(v.begin(), v.end(), [&](const Timing& a, const Timing& b) { return a.*m < b.*m; });
    return v[v.size() / 2].*m;
  };
  double base = -1;
  for (std::size_t k = 0; k < configs.size(); ++k) {
    const Config& c = configs[k];
    Timing t = runs[k].front();
    t.step = median(runs[k], &Timing::step);
    t.solve = median(runs[k], &Timing::solve);
    t.coupling = median(runs[k], &Timing::coupling);
    t.ppe = median(runs[k], &Timing::ppe);
    std::vector<Timing> rests = runs[k];
    for (auto& x : rests) x.rest = x.step - x.solve;
    const double rest = median(rests, &Timing::rest);
    if (c.n == 0 && base < 0) base = rest;
    std::printf("| %d | %d | %.1f | %.2f | %.2f | %.2f | %.3f |", c.n, c.s * c.s, t.ppe,
                1e3 * t.step, 1e3 * t.solve, 1e3 * rest, 1e3 * t.coupling);
    const double extra = rest - base + t.coupling;
    if (c.n > 0)
      std::printf(" %.3f | %.2f |\n", 1e3 * extra / c.n, 1e6 * extra / t.pms);
    else
      std::printf(" | |\n");
    std::fflush(stdout);
  }
  return 0;
}
