#include "run/run_loop.hpp"

namespace isphdem {

template <int Dim>
void print_ppe_cost(const isph::IsphSolver<Dim>& solver) {
  const auto& t = solver.timings();
  const double steps = std::max(1L, solver.steps());
  std::printf("  pressure solve (%s): setup %.3g ms/step, iterations %.3g ms/step\n",
              solver.config().pressure_solver.preconditioner.c_str(), 1e3 * t.solve_setup / steps,
              1e3 * (t.solve - t.solve_setup) / steps);
  if (solver.rows_shared())
    std::printf("  rows shared between the ranks: exchanges %.3g ms/step (%.1f%% of the fluid)\n",
                1e3 * t.exchange / steps, 100 * t.exchange / t.total());
}

template void print_ppe_cost<2>(const isph::IsphSolver<2>&);
template void print_ppe_cost<3>(const isph::IsphSolver<3>&);

}  // namespace isphdem
