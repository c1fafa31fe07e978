#include "run/fluid_checkpoint.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace isphdem {

namespace {

// The names of Particles::for_each_array's arrays, in its order. A new array there without a name
// here stops every checkpoint (save and restore count them), so none is ever left out.
const char* const kArrays[] = {
    "x",           "v",           "p",          "porosity", "solid_velocity", "resistance",
    "kind",        "id",          "surface",    "normal",   "wall_distance",  "body",
    "body_offset", "body_normal", "solid_force"};
constexpr std::size_t kArrayCount = sizeof kArrays / sizeof kArrays[0];

template <class T>
void put(CheckpointArrays& a, const std::string& name, const std::vector<T>& v) {
  if constexpr (std::is_floating_point_v<T>) {
    a.reals[name] = v;
  } else if constexpr (std::is_integral_v<T>) {
    a.integers[name].assign(v.begin(), v.end());
  } else {  // Vec<Dim>
    auto& r = a.reals[name];
    r.clear();
    r.reserve(v.size() * T::RowsAtCompileTime);
    for (const auto& x : v)
      for (int c = 0; c < T::RowsAtCompileTime; ++c) r.push_back(x[c]);
  }
}

template <class T>
void get(const CheckpointArrays& a, const std::string& name, std::size_t n, std::vector<T>& v) {
  auto wrong = [&](std::size_t values) {
    throw std::runtime_error("checkpoint: fluid array '" + name + "' holds " +
                             std::to_string(values) + " values for " + std::to_string(n) +
                             " particles");
  };
  if constexpr (std::is_floating_point_v<T>) {
    const auto& r = a.real_array(name);
    if (r.size() != n) wrong(r.size());
    v = r;
  } else if constexpr (std::is_integral_v<T>) {
    const auto& r = a.integer_array(name);
    if (r.size() != n) wrong(r.size());
    v.assign(r.begin(), r.end());
  } else {
    constexpr int cols = T::RowsAtCompileTime;
    const auto& r = a.real_array(name);
    if (r.size() != n * cols) wrong(r.size());
    v.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < cols; ++c) v[i][c] = r[i * cols + c];
  }
}

}  // namespace

template <int Dim>
void save_fluid(const isph::IsphSolver<Dim>& solver, CheckpointArrays& a) {
  isph::Particles<Dim> P = solver.particles();
  std::size_t k = 0;
  P.for_each_array([&](const auto& v) {
    if (k < kArrayCount) put(a, std::string("fluid_") + kArrays[k], v);
    ++k;
  });
  if (k != kArrayCount)
    throw std::logic_error("save_fluid: Particles has " + std::to_string(k) +
                           " arrays, the checkpoint names " + std::to_string(kArrayCount));
  a.set_integer("fluid_dimension", Dim);
  a.set_integer("fluid_particles", std::int64_t(P.size()));
  a.set("fluid_volume", P.volume);
  a.set("fluid_spacing", P.spacing);
  a.set_integer("fluid_next_id", P.next_id);
  a.set_integer("fluid_keep_part", P.keep_part);
  a.set_integer("fluid_keep_parts", P.keep_parts);
  const isph::StepCarry<Dim> c = solver.carry();
  a.set("solver_time", c.time);
  a.set_integer("solver_steps", c.steps);
  a.set("solver_max_eddy_viscosity", c.max_eddy_viscosity);
  a.set("solver_surface_top", c.surface_top);
  a.reals["solver_gravity"] = std::vector<double>(c.gravity.data(), c.gravity.data() + Dim);
  a.reals["solver_unit_response"] = c.unit_response;
  a.set_integer("solver_unit_response_pin", c.unit_response_pin);
  a.set("solver_unit_response_lambda", c.unit_response_lambda);
  a.set_integer("solver_have_q", c.have_q ? 1 : 0);
}

template <int Dim>
void restore_fluid(isph::IsphSolver<Dim>& solver, const CheckpointArrays& a) {
  if (a.integer("fluid_dimension") != Dim)
    throw std::runtime_error("checkpoint: the fluid was " +
                             std::to_string(a.integer("fluid_dimension")) + "-D, the case " +
                             std::to_string(Dim) + "-D");
  const auto n = std::size_t(a.integer("fluid_particles"));
  isph::Particles<Dim> P;
  std::size_t k = 0;
  P.for_each_array([&](auto& v) {
    if (k < kArrayCount) get(a, std::string("fluid_") + kArrays[k], n, v);
    ++k;
  });
  if (k != kArrayCount)
    throw std::logic_error("restore_fluid: Particles has " + std::to_string(k) +
                           " arrays, the checkpoint names " + std::to_string(kArrayCount));
  P.volume = a.real("fluid_volume");
  P.spacing = a.real("fluid_spacing");
  P.next_id = a.integer("fluid_next_id");
  P.keep_part = a.integer("fluid_keep_part");
  P.keep_parts = a.integer("fluid_keep_parts");
  isph::StepCarry<Dim> c;
  c.time = a.real("solver_time");
  c.steps = long(a.integer("solver_steps"));
  c.max_eddy_viscosity = a.real("solver_max_eddy_viscosity");
  c.surface_top = a.real("solver_surface_top");
  const auto& g = a.real_array("solver_gravity");
  if (g.size() != std::size_t(Dim)) throw std::runtime_error("checkpoint: solver_gravity size");
  for (int d = 0; d < Dim; ++d) c.gravity[d] = g[d];
  c.unit_response = a.real_array("solver_unit_response");
  c.unit_response_pin = a.integer("solver_unit_response_pin");
  c.unit_response_lambda = a.real("solver_unit_response_lambda");
  c.have_q = a.integer("solver_have_q") != 0;
  solver.resume(std::move(P), c);
}

template void save_fluid<2>(const isph::IsphSolver<2>&, CheckpointArrays&);
template void save_fluid<3>(const isph::IsphSolver<3>&, CheckpointArrays&);
template void restore_fluid<2>(isph::IsphSolver<2>&, const CheckpointArrays&);
template void restore_fluid<3>(isph::IsphSolver<3>&, const CheckpointArrays&);

}  // namespace isphdem
