// Grains entering the water (examples/pouring_fines_2d): twenty 1 mm grains fall 10-25 mm through
// air into a quasi-2D tank (dx = 2 mm, unresolved). The run must reach 1 s with no fluid faster
// than twice the grains' entry speed, and the dropped grains must settle at the speed of the same
// grains released under water: entering through the surface changes nothing once they are in.
// Before 2026-12-06 this case threw water out of the tank within 0.2-0.8 s at its step of 1e-4 s
// (0.75 s at 2.5e-4 s): near a disturbed free surface, pressure rows that amplified their own
// divergence and particle pairs closing to 0.5 dx (docs/fluid.md, "A disturbed free surface at
// small dt"; sph/projection_stability.hpp, kMinPairDistance in sph/step_correction.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "coupled_case.hpp"
#include "study/reference_formulas.hpp"

namespace isphdem::coupled_test {
namespace {

struct Fall {
  double max_fluid_speed = 0.0;
  double max_grain_speed = 0.0;
  double settling_speed = 0.0;  // mean -v_y of grains 3-22 mm above the floor over the window
  double end_time = 0.0;
};

// Runs the example to t_end; settling speed averaged over every step in [t0, t1].
Fall run(const std::string& tag, std::vector<std::string> sets, double t_end, double t0,
         double t1) {
  sets.push_back("time.end=" + std::to_string(t_end));
  const CaseFile c = load_coupled_example("pouring_fines_2d", sets);
  auto cc = make_coupled_case<2>(c, std::string(ISPHDEM_BINARY_DIR) + "/tests/pouring_" + tag);
  auto& r = *cc.run;
  Fall f;
  double sum = 0.0, n = 0.0;
  r.run_until(t_end, [&](const isph::StepStats& s) {
    f.max_fluid_speed = std::max(f.max_fluid_speed, s.max_speed);
    const double t = r.solver().time();
    for (const auto& a : cc.backend->state().atoms) {
      f.max_grain_speed = std::max(f.max_grain_speed, std::hypot(a.v[0], a.v[1]));
      if (t >= t0 && t <= t1 && a.x[1] > 0.003 && a.x[1] < 0.022) sum += -a.v[1], n += 1;
    }
  });
  f.settling_speed = n > 0 ? sum / n : 0.0;
  f.end_time = r.solver().time();
  return f;
}

TEST(PouringFines, GrainsEnterTheWaterAndSettleAsIfReleasedInIt) {
  // Dropped from 10-25 mm above the surface: in the water by 0.1 s, settling steadily over
  // 0.14-0.2 s (the first reach the floor at about 0.2 s).
  const Fall dropped = run("dropped", {}, 1.0, 0.14, 0.20);
  // The same grains released at rest 12-27 mm above the floor: steady over 0.08-0.11 s.
  const Fall under =
      run("under_water", {"dem.variables.ins_lo=0.012", "dem.variables.ins_hi=0.027"}, 0.12, 0.08,
          0.11);
  const double v_sn = schiller_naumann_velocity(1e-3, 2600, 1000, 1e-6, 9.81);
  std::printf(
      "dropped: reached t = %.3f s; fastest grain %.3f m/s (entry), fastest fluid %.3f m/s "
      "(%.2f x entry)\n",
      dropped.end_time, dropped.max_grain_speed, dropped.max_fluid_speed,
      dropped.max_fluid_speed / dropped.max_grain_speed);
  std::printf(
      "settling speed: dropped %.4f m/s, released under water %.4f m/s (%+.1f%%); one "
      "grain alone, Schiller-Naumann: %.4f m/s (the cloud %+.1f%%)\n",
      dropped.settling_speed, under.settling_speed,
      100 * (dropped.settling_speed / under.settling_speed - 1), v_sn,
      100 * (dropped.settling_speed / v_sn - 1));
  EXPECT_NEAR(dropped.end_time, 1.0, 1e-9);
  EXPECT_GT(dropped.max_grain_speed, 0.5) << "the grains should enter at about sqrt(2 g h)";
  EXPECT_LT(dropped.max_fluid_speed, 2.0 * dropped.max_grain_speed);
  EXPECT_NEAR(dropped.settling_speed / under.settling_speed, 1.0, 0.05);
}

}  // namespace
}  // namespace isphdem::coupled_test
