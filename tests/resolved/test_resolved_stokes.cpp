// Stokes drag on a held PMS body in a periodic array, against the exact results for dilute
// arrays: a simple cubic array of spheres (Hasimoto 1959; Sangani & Acrivos 1982) and a square
// array of cylinders (Sangani & Acrivos 1982). The fluid is driven by a body force g along x in
// a box periodic in every direction; the drag F on the body and the mean velocity U (volume flux
// over the box section) are compared, and the fluid's momentum balance rho g V_f - dM/dt = F
// checks that what the fluid loses is what the body receives. The exact relations, with c the
// solid volume (area) fraction:
//   sphere   F = 6 pi mu a U K,
//            1/K = 1 - 1.7601 c^(1/3) + c - 1.5593 c^2 + 3.9799 c^(8/3) - 3.0734 c^(10/3)
//   cylinder F = 4 pi mu U / (-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.039 c^3)   (per unit length)
// At Reynolds numbers of 1e-2 inertia is negligible. This checks the viscous exchange between
// fluid and PMS particles (two thirds of a sphere's Stokes drag is viscous stress), which the
// Archimedes tests (pressure only) do not see.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "resolved_support.hpp"

namespace isphdem::resolved_test {
namespace {

struct StokesResult {
  double ratio = 0, exact = 0, added = 0, reynolds = 0, balance = 0;
};

// Runs six viscous time constants and compares drag and U over the last steps (quasi-steadily,
// see below); returns drag / (mu U) (3D: per 6 pi a) measured and exact.
template <int Dim>
StokesResult periodic_array(double L, double dx, double a, double g) {
  const double nu = 1e-3, rho = 1000.0, mu = rho * nu;
  std::vector<std::string> o{"case.dimension=" + std::to_string(Dim), "fluid.viscosity=1e-3",
                             "initial.velocity=\"rest\"",
                             "particles.spacing=" + std::to_string(dx)};
  const std::string zero = Dim == 2 ? "0" : "0,0";
  const std::string box =
      Dim == 2 ? "[" + std::to_string(L) + "," + std::to_string(L) + "]"
               : "[" + std::to_string(L) + "," + std::to_string(L) + "," + std::to_string(L) + "]";
  const std::string origin = Dim == 2 ? "[0,0]" : "[0,0,0]";
  o.push_back("domain.min=" + origin);
  o.push_back("domain.max=" + box);
  o.push_back(std::string("domain.periodic=") + (Dim == 2 ? "[true,true]" : "[true,true,true]"));
  o.push_back("fluid.blocks=[{min=" + origin + ",max=" + box + "}]");
  o.push_back("fluid.gravity=[" + std::to_string(g) + "," + zero + "]");
  // The Taylor-Green example is the periodic, wall-free box.
  auto scene = example_scene<Dim>("taylor_green_2d", o);
  isph::IsphSolver<Dim> solver(scene.config, scene.domain, scene.particles);
  // The body: a sphere (3D) or, in 2D, a sphere in a slab T = 4a/3 (its section is the disc of
  // radius a), centred on a lattice node in the middle of the box.
  const double c0 = dx * std::floor(0.5 * L / dx) + 0.5 * dx;
  DemState dem = clump({Vec3{c0, c0, Dim == 3 ? c0 : 0.0}}, a, 1e9);
  const ResolvedSettings set = held_body_settings(dx, rho, a);
  ResolvedCoupling<Dim> stage(set);
  stage.initialize(dem, solver);
  const double dt = 0.125 * dx * dx / nu;
  // The slowest periodic mode decays as exp(-nu (2 pi / L)^2 t): run 6 of its time constants.
  const int steps = static_cast<int>(6.0 / (nu * std::pow(2 * M_PI / L, 2)) / dt);
  const double scale = Dim == 2 ? set.slab_thickness : 1.0;
  const auto& P = solver.particles();
  const auto fluid_sum = [&](auto&& value) {
    double sum = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == isph::kFluid) sum += P.volume * value(i);
    return sum;
  };
  const double fluid_volume = fluid_sum([](std::size_t) { return 1.0; });
  // The flow approaches the steady state with the time constant U/g of the array (0.3 s in 3D
  // here), far slower than the viscous one; rather than waiting, the last `window` steps are
  // used quasi-steadily (the drag follows U; Re ~ 1e-2), and the fluid's momentum balance
  // rho g V_f - dM/dt = F checks that what the fluid loses is what the body gets.
  const int window = 50;
  double f_window = 0, u_window = 0, momentum0 = 0;
  for (int n = 0; n < steps; ++n) {
    if (n == steps - window) momentum0 = rho * fluid_sum([&](std::size_t i) { return P.v[i][0]; });
    stage.move_particles(dem, solver);
    solver.step(dt);
    DemLoads loads;
    stage.after_fluid_step(dem, solver, dt, loads);
    if (n < steps - window) continue;
    f_window += loads.body_force[0][0] / scale / window;  // per unit depth in 2D
    u_window += fluid_sum([&](std::size_t i) { return P.v[i][0]; }) / std::pow(L, Dim) / window;
  }
  const double momentum1 = rho * fluid_sum([&](std::size_t i) { return P.v[i][0]; });
  const double dmdt = (momentum1 - momentum0) / (window * dt);
  const double U = u_window;
  const double c = stage.bodies()[0].fluid_volume / scale / std::pow(L, Dim);
  const double balance = (rho * g * fluid_volume - dmdt) / f_window;
  std::printf(
      "  over the last %d steps: body force %.4e, driving rho g V_f %.4e, fluid dM/dt %.4e: "
      "(rho g V_f - dM/dt) / F = %.6f\n",
      window, f_window, rho * g * fluid_volume, dmdt, balance);
  // The fluid still accelerates: the held body also feels the accelerating fluid's pressure
  // (rho V_s a, as buoyancy in an accelerating frame) and its added mass (C_m rho V_s a; C_m = 1/2
  // for a sphere, 1 for a cylinder). Taken off, what is left is the drag (1.5-2% of F here).
  const double solid_volume = stage.bodies()[0].fluid_volume / scale;
  const double added = (Dim == 3 ? 1.5 : 2.0) * rho * solid_volume * dmdt / (rho * fluid_volume);
  const double f = f_window - added;
  StokesResult r;
  r.balance = balance;
  r.added = added / f_window;
  r.reynolds = U * 2 * a / nu;
  if (Dim == 3) {
    const double ac =
        std::cbrt(3.0 * c * std::pow(L, 3) / (4.0 * M_PI));  // radius of the PMS volume
    r.ratio = f / (6 * M_PI * mu * ac * U);
    r.exact = 1.0 / (1 - 1.7601 * std::cbrt(c) + c - 1.5593 * c * c +
                     3.9799 * std::pow(c, 8.0 / 3.0) - 3.0734 * std::pow(c, 10.0 / 3.0));
  } else {
    r.ratio = f / (mu * U);
    r.exact = 4 * M_PI / (-0.5 * std::log(c) - 0.738 + c - 0.887 * c * c + 2.039 * c * c * c);
  }
  std::printf(
      "%dD: L = %g, dx = %g, a = %g (%zu PMS particles, solid fraction %.4f), %d steps: U = %.4e "
      "m/s (Re %.1e); drag/(mu U%s) = %.4f, exact %.4f, error %+.2f%% (acceleration terms %.2f%% "
      "of F)\n",
      Dim, L, dx, a, stage.bodies()[0].particles, c, steps, U, r.reynolds,
      Dim == 3 ? " 6 pi a" : "", r.ratio, r.exact, 100 * (r.ratio / r.exact - 1), 100 * r.added);
  return r;
}

// d/dx = 5: +5.5% with the pressure-increment PMS rows (issue 46). Projected as fluid, the body
// leaked by dt g a step at this step (the viscous limit), which passed more flow and offset part
// of the resolution's excess drag (the 2D array's share of it: tests/resolved/
// test_pms_time_step.cpp).
TEST(ResolvedStokes, HeldSphereInCubicArrayMatchesHasimoto) {
  const StokesResult r = periodic_array<3>(0.04, 0.002, 0.005, 2e-3);
  EXPECT_LT(r.reynolds, 0.05);
  EXPECT_NEAR(r.balance, 1.0, 1e-3);
  EXPECT_NEAR(r.ratio, r.exact, 0.07 * r.exact);
}

TEST(ResolvedStokes, HeldCylinderInSquareArrayMatchesSanganiAcrivos) {
  const StokesResult r = periodic_array<2>(0.04, 0.001, 0.005, 2e-3);
  EXPECT_LT(r.reynolds, 0.05);
  EXPECT_NEAR(r.balance, 1.0, 1e-3);
  EXPECT_NEAR(r.ratio, r.exact, 0.05 * r.exact);
}

}  // namespace
}  // namespace isphdem::resolved_test
