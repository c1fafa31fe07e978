#pragma once
// What IsphSolver keeps from one step to the next besides the particles: the clock, the limits'
// eddy viscosity, the remeshed surface's height, the body force a drive may have changed, and
// spread_pinned_source's unit response q (reused for up to 10 steps). A checkpoint saves this with
// every particle array; IsphSolver::resume puts both back, so that the next step is the one the
// uninterrupted run would have taken, bit for bit.
#include <cstdint>
#include <vector>

#include "vec.hpp"

namespace isph {

template <int Dim>
struct StepCarry {
  double time = 0.0;
  long steps = 0;
  double max_eddy_viscosity = 0.0;
  double surface_top = 0.0;
  Vec<Dim> gravity = Vec<Dim>::Zero();
  // q in this process's storage order (empty when none is kept), the particle it was solved for,
  // the last step's lambda, and (decomposed) whether q is valid on every process.
  std::vector<double> unit_response;
  int64_t unit_response_pin = -1;
  double unit_response_lambda = 0.0;
  bool have_q = false;
};

}  // namespace isph
