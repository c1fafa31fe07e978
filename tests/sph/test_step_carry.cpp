// IsphSolver::carry / resume (sph/step_carry.hpp): a solver built from the same scene, given
// another's particles and carry between two steps, takes the same next steps, bit for bit. In a
// periodic box (the pinned pressure's unit response q and its lambda, reused between q's solves
// every 10 steps: without lambda the resumed run differs) and in a sloshing tank whose free
// surface is remeshed every 5 steps (the remesh falls on the same steps; the remeshed rows'
// height, also carried, stays on its lattice row here, so this scene would not tell it missing).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "isph_solver.hpp"
#include "lattice.hpp"

namespace isph {
namespace {

struct Scene {
  IsphConfig<2> config;
  Domain<2> domain;
  Particles<2> particles;
};

Scene periodic_vortex() {
  Scene s;
  s.domain.periodic = {true, true};
  s.config.viscosity = 0.01;
  s.config.free_surface = false;
  s.particles.spacing = 0.05;
  s.particles.volume = 0.05 * 0.05;
  fill_box<2>(s.particles, Vec<2>(0, 0), Vec<2>(1, 1), 0.05, kFluid);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const auto& x = s.particles.x[i];
    s.particles.v[i] = Vec<2>(-std::cos(2 * M_PI * x[0]) * std::sin(2 * M_PI * x[1]),
                              std::sin(2 * M_PI * x[0]) * std::cos(2 * M_PI * x[1]));
  }
  return s;
}

Scene remeshed_tank() {
  Scene s;
  s.domain.lo = Vec<2>(-0.1, -0.1);
  s.domain.hi = Vec<2>(0.5, 0.5);
  s.config.gravity = Vec<2>(0, -9.81);
  s.config.surface_remesh_rows = 2;
  s.config.surface_remesh_every = 5;
  s.particles.spacing = 0.02;
  s.particles.volume = 0.02 * 0.02;
  fill_box<2>(s.particles, Vec<2>(0, 0), Vec<2>(0.4, 0.2), 0.02, kFluid);
  add_wall_shell<2>(s.particles, Vec<2>(0, 0), Vec<2>(0.4, 0.4), 0.02, 3,
                    {true, true, true, false});
  s.config.surface_remesh_alpha_s = 0.02;  // reads the remeshed rows' height every step
  for (std::size_t i = 0; i < s.particles.size(); ++i)  // a slosh: the surface rises on the right
    if (s.particles.kind[i] == kFluid) s.particles.v[i] = Vec<2>(0.2, 0.0);
  return s;
}

void expect_resumed_run_takes_the_same_steps(const std::function<Scene()>& make, double dt) {
  Scene a = make(), b = make();
  IsphSolver<2> whole(a.config, a.domain, a.particles);
  IsphSolver<2> resumed(b.config, b.domain, b.particles);
  for (int k = 0; k < 13; ++k) whole.step(dt);
  resumed.resume(whole.particles(), whole.carry());
  EXPECT_EQ(resumed.steps(), 13);
  EXPECT_EQ(resumed.time(), whole.time());
  for (int k = 0; k < 14; ++k) {
    const StepStats s = whole.step(dt), t = resumed.step(dt);
    EXPECT_EQ(s.ppe_iterations, t.ppe_iterations) << "step " << whole.steps();
  }
  const auto &P = whole.particles(), &Q = resumed.particles();
  ASSERT_EQ(P.size(), Q.size());
  EXPECT_TRUE(P.id == Q.id);
  EXPECT_TRUE(P.x == Q.x);
  EXPECT_TRUE(P.v == Q.v);
  EXPECT_TRUE(P.p == Q.p);
  EXPECT_TRUE(P.surface == Q.surface);
}

TEST(StepCarry, PeriodicBoxResumesBitForBit) {
  expect_resumed_run_takes_the_same_steps(periodic_vortex, 0.005);
}

TEST(StepCarry, RemeshedFreeSurfaceResumesBitForBit) {
  expect_resumed_run_takes_the_same_steps(remeshed_tank, 5e-4);
}

}  // namespace
}  // namespace isph
