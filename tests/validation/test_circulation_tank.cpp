// The seed's circulation tank without soil (examples/circulation_tank_2d): water is forced upward
// at v_in in a zone between the two inner walls and circulates back down outside them. At steady
// state the upward flux through the window above the forcing zone (where the soil layer will sit)
// must equal the forced flux v_in * 28 mm (within 1% over 10 s, 3% over the default 0.3 s), no
// particle may leave the tank and no value may become NaN (the solver throws on both, which fails
// the test with its message). The flux read +4.2% while the forcing zone's predictor left out
// gravity (the column above the zone was projected to v_in + dt g); +0.96% since.
//
// CIRCULATION_TANK_END is the simulated time: 0.3 s in the default suite (steady flux is reached
// within a few hundredths of a second: the fluid is incompressible), the 10 s in the slow
// variant. Both at the case's dx = 1 mm and dt = 1e-4 s. The free surface survives the upwelling
// through the case's surface remesh (sph/surface_remesh.hpp); without it the 10 s run broke up
// at 1.26 s, and FastUpwellingKeepsItsSurface, the default suite's reproducer, at 0.45 s. With
// the remesh but surface marks allowed anywhere, the 10 s run burst at 6.7 s: a void in the
// separating flow behind an inner wall's top corner read as surface 10 mm under the water.
//
// The same tank closed at the water line (closed.toml: a rigid lid, no free surface) has no
// Dirichlet row, so one pinned particle fixes the pressure level; it ran away from that corner at
// t = 0.41 s (4.5 m/s) until the pressure equation's net source was removed for every such
// system, not only porous ones. Its run must stay as quiet as the open tank's and carry the same
// flux.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case_path.hpp"
#include "run/fluid_run.hpp"

#ifndef CIRCULATION_TANK_END
#define CIRCULATION_TANK_END 0.3
#endif

namespace isphdem::validation {
namespace {

// Window between the inner walls (their inner faces at x = 16 and 44 mm), centred 25 mm above
// the floor: above the forcing zone (12-18 mm) and below the top of the inner walls (40 mm).
constexpr double kWindowLo = 0.016, kWindowHi = 0.044, kWindowY = 0.025;

// Volume flux per unit depth through the window: the mean upward velocity of the particles in a
// slab 2 dx thick across the window, times the window width. (Summing V_i v_y over the slab and
// dividing by its thickness instead counts each particle as dx^2 of water; the particle count
// in the slab fluctuates by a few percent with the disorder, and that read 4% high on average.)
struct WindowSample {
  double flux = 0.0;    // mean v_y times width
  double volume = 0.0;  // sum V_i v_y / slab thickness, for comparison
};

WindowSample window_flux(const isph::IsphSolver<2>& s) {
  const auto& P = s.particles();
  const double slab = 2.0 * P.spacing;
  double sum_v = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == isph::kWall) continue;
    const auto& x = P.x[i];
    if (x[0] > kWindowLo && x[0] < kWindowHi && std::abs(x[1] - kWindowY) < 0.5 * slab) {
      sum_v += P.v[i][1];
      ++count;
    }
  }
  WindowSample w;
  if (count > 0) w.flux = sum_v / count * (kWindowHi - kWindowLo);
  w.volume = P.volume * sum_v / slab;
  return w;
}

struct TankResult {
  double t = 0.0, flux = 0.0, forced = 0.0, v_max = 0.0, v_in = 0.0;
  double volume_start = 0.0, volume_end = 0.0;  // fluid volume from the number densities
  int outside = 0;
  std::string failure;
};

TankResult run_tank(const std::string& file, double t_end,
                    const std::vector<std::string>& extra = {}) {
  // The short run starts the pump at once (no ramp) so that its second half is at full v_in.
  std::vector<std::string> set = {"time.end=" + std::to_string(t_end)};
  if (t_end < 1.0) set.push_back("inflow.ramp=0");
  set.insert(set.end(), extra.begin(), extra.end());
  const CaseFile c =
      CaseFile::load(std::string(ISPHDEM_SOURCE_DIR) + "/examples/circulation_tank_2d/" + file, set,
                     all_fluid_keys());
  TankResult out;
  out.v_in = c.number("inflow.velocity");
  out.forced = out.v_in * (kWindowHi - kWindowLo);
  FluidRun<2> run(build_fluid_scene<2>(c), parse_run_settings(c));
  auto& s = run.solver();
  // Flux averaged over the second half of the run (sampled every step).
  double sum = 0.0, sum_volume = 0.0, lo = 1e9, hi = -1e9;
  long samples = 0;
  try {
    run.run_until(t_end, [&](const isph::StepStats& st) {
      out.v_max = std::max(out.v_max, st.max_speed);
      if (out.volume_start == 0.0) out.volume_start = st.fluid_volume;
      out.volume_end = st.fluid_volume;
      if (s.time() < 0.5 * t_end) return;
      const WindowSample w = window_flux(s);
      sum += w.flux;
      sum_volume += w.volume;
      lo = std::min(lo, w.flux);
      hi = std::max(hi, w.flux);
      ++samples;
    });
  } catch (const isph::SimulationError& e) {
    out.failure = e.what();
  }
  out.t = s.time();
  out.flux = samples > 0 ? sum / samples : 0.0;
  // Every fluid particle still inside the tank (walls at x = 0 and 60 mm, floor at 0, the
  // closed tank's lid at 50 mm).
  const double top = c.boolean("solver.free_surface", true) ? 1e9 : 0.05;
  const auto& P = s.particles();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] != isph::kWall && (P.x[i][0] < 0.0 || P.x[i][0] > 0.06 || P.x[i][1] < 0.0 ||
                                     P.x[i][1] > top || !P.x[i].allFinite()))
      ++out.outside;
  std::printf(
      "  %s: t = %.2f s in %ld steps; window flux %.4e m^2/s (min %.4e, max %.4e over t >= %.2f "
      "s), forced %.4e: error %+.2f%% (slab-volume estimate %+.2f%%); max speed %.4f m/s "
      "(%.1f v_in); particles outside %d; fluid volume %+.3f%%\n",
      file.c_str(), out.t, s.steps(), out.flux, lo, hi, 0.5 * t_end, out.forced,
      100.0 * (out.flux - out.forced) / out.forced,
      samples > 0 ? 100.0 * (sum_volume / samples - out.forced) / out.forced : 0.0, out.v_max,
      out.v_max / out.v_in, out.outside,
      100.0 * (out.volume_end - out.volume_start) / std::max(out.volume_start, 1e-300));
  if (!out.failure.empty()) std::printf("  stopped: %s\n", out.failure.c_str());
  return out;
}

// One run of each tank shared by the tests below.
const TankResult& tank() {
  static const TankResult r = run_tank("case.toml", CIRCULATION_TANK_END);
  return r;
}

// The closed tank runs twice as long as the open one's default-suite run: the pinned corner ran
// away at 0.41 s.
const TankResult& closed_tank() {
  static const TankResult r = run_tank("closed.toml", std::max(0.6, CIRCULATION_TANK_END));
  return r;
}

// The criteria for the free surface: it reaches the end, nothing leaves the tank, no jet,
// and the fluid volume stays within 0.5% of its start.
void expect_surface_survives(const TankResult& r, double t_end) {
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_GE(r.t, t_end - 1e-9);
  EXPECT_EQ(r.outside, 0);
  // The forcing drives a slow circulation; a spurious jet would show as a speed far above v_in.
  EXPECT_LT(r.v_max, 10.0 * r.v_in);
  EXPECT_LT(std::abs(r.volume_end - r.volume_start), 0.005 * r.volume_start);
}

TEST(CirculationTank, StaysStableAndNothingEscapes) {
  expect_surface_survives(tank(), CIRCULATION_TANK_END);
}

// The seed's faster upwelling, 2 cm/s, for 1 s (the pump ramped in over 0.5 s): the quickest
// reproducer of the free surface's break-up over the upwelling (docs/fluid.md). Without the
// surface remesh the top layer broke at 0.45 s (0.5 m/s at 0.49 s) and a particle left the domain
// at 0.59 s; with the remesh but alpha_s at its default 0.001, at 0.27 s.
TEST(CirculationTank, FastUpwellingKeepsItsSurface) {
  const TankResult r = run_tank("case.toml", 1.0, {"inflow.velocity=0.02"});
  expect_surface_survives(r, 1.0);
}

// The 1% over the 10 s run's second half; 3% over the short run's, which starts the pump at
// once and whose second half (0.15-0.3 s) still carries some of the start.
TEST(CirculationTank, WindowFluxEqualsForcedFlux) {
  const auto& r = tank();
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_LT(std::abs(r.flux - r.forced) / r.forced, CIRCULATION_TANK_END >= 1.0 ? 0.01 : 0.03);
}

TEST(CirculationTank, ClosedTankStaysQuietAndCarriesTheForcedFlux) {
  const auto& r = closed_tank();
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_EQ(r.outside, 0);
  EXPECT_LT(r.v_max, 10.0 * r.v_in);
  EXPECT_LT(std::abs(r.flux - r.forced) / r.forced, 0.03);
}

}  // namespace
}  // namespace isphdem::validation
