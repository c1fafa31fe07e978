#include "run/run_loop.hpp"

namespace isphdem {

template <int Dim>
void print_ppe_cost(const isph::IsphSolver<Dim>& solver, long steps_taken) {
  const auto& t = solver.timings();
  const double steps = std::max(1L, steps_taken);
  std::printf("  pressure solve (%s): setup %.3g ms/step, iterations %.3g ms/step\n",
              solver.config().pressure_solver.preconditioner.c_str(), 1e3 * t.solve_setup() / steps,
              1e3 * (t.solve() - t.solve_setup()) / steps);
  if (solver.rows_shared())
    std::printf("  rows shared between the ranks: exchanges %.3g ms/step (%.1f%% of the fluid)\n",
                1e3 * t.exchange / steps, 100 * t.exchange / t.total());
}

std::vector<std::pair<std::string, double>> fluid_stage_seconds(const isph::StepTimings& t) {
  std::vector<std::pair<std::string, double>> s;
  for (int k = 0; k < isph::kStageCount; ++k) s.emplace_back(isph::step_stage_name(k), t.stage[k]);
  return s;
}

void print_fluid_stages(const isph::StepTimings& t, long steps) {
  std::string line = "  fluid stages, ms/step:";
  char buf[64];
  for (int k = 0; k < isph::kStageCount; ++k) {
    std::snprintf(buf, sizeof buf, "%s %s %.3g", k ? "," : "", isph::step_stage_name(k),
                  1e3 * t.stage[k] / double(std::max(1L, steps)));
    line += buf;
  }
  std::printf("%s\n", line.c_str());
}

template void print_ppe_cost<2>(const isph::IsphSolver<2>&, long);
template void print_ppe_cost<3>(const isph::IsphSolver<3>&, long);

}  // namespace isphdem
