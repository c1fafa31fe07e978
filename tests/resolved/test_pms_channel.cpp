// Plane Poiseuille flow in a channel between two PMS walls a few spacings apart (issue 49): the
// throat of a packed bed at the resolution a semi-resolved scene affords. A periodic box, a PMS
// slab of `wall_rows` lattice rows held at rest, and `gap_rows` fluid rows between its two faces
// (one through the periodic boundary); the flow is driven by a body force g along x. The body's
// surface lies half a spacing beyond its outermost rows, so the channel is H = gap_rows dx wide
// and the exact flow rate per unit depth is q = g H^3 / (12 nu).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "resolved_support.hpp"
#include "rigid_solids.hpp"

namespace isphdem::resolved_test {
namespace {

struct ChannelResult {
  double q = 0, exact = 0, force = 0, drive = 0;
  std::vector<double> profile, profile_exact;  // row means of u_x, fluid rows bottom-up
};

ChannelResult measure(const isph::IsphSolver<2>& solver, int gap_rows, double y0,
                      const char* what) {
  const auto& P = solver.particles();
  const double dx = P.spacing, nu = solver.config().viscosity, g = solver.config().gravity[0];
  const double rho = solver.config().density, H = gap_rows * dx;
  const double Lx = solver.domain().length()[0];
  ChannelResult r;
  r.exact = g * H * H * H / (12 * nu);
  r.profile.assign(gap_rows, 0.0);
  r.profile_exact.assign(gap_rows, 0.0);
  std::vector<int> count(gap_rows, 0);
  double m = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == isph::kWall) continue;
    if (P.kind[i] == isph::kSolid) {
      r.force += P.solid_force[i][0];
      continue;
    }
    m += P.volume * P.v[i][0];
    const int row = static_cast<int>(std::floor((P.x[i][1] - y0) / dx));
    if (row < 0 || row >= gap_rows) continue;
    r.profile[row] += P.v[i][0];
    ++count[row];
  }
  for (int k = 0; k < gap_rows; ++k) {
    r.profile[k] /= std::max(count[k], 1);
    const double s = (k + 0.5) * dx;
    r.profile_exact[k] = g / (2 * nu) * s * (H - s);
  }
  r.q = m / Lx;
  r.drive = rho * g * H * Lx;  // the body force on the fluid per unit depth
  std::printf("%s, gap %d dx: q/q_exact %.4f (%+.2f%%), wall force / drive %.4f\n", what, gap_rows,
              r.q / r.exact, 100 * (r.q / r.exact - 1), r.force / r.drive);
  std::printf("  row u/u_exact:");
  for (int k = 0; k < gap_rows; ++k) std::printf(" %.4f", r.profile[k] / r.profile_exact[k]);
  std::printf("\n");
  return r;
}

// Spacing, viscosity and drive of every channel here.
constexpr double kDx = 0.001, kNu = 1e-3, kG = 1e-3;

// Steps of the viscous limit 0.125 dx^2 / nu over ten viscous times H^2 / (pi^2 nu) of the widest
// channel (6 dx): steady to 1e-4.
template <class Step>
void run_to_steady(Step step) {
  const double dt = 0.125 * kDx * kDx / kNu;
  const double t_end = 10.0 * 36e-6 / (M_PI * M_PI * kNu) + 0.02;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int n = 0; n < steps; ++n) step(dt);
}

ChannelResult pms_channel(int gap_rows, const std::vector<std::string>& extra = {}) {
  constexpr int Dim = 2;
  const double dx = kDx, nu = kNu, g = kG;
  // Four rows of slab, or more: the periodic box must be three kernel supports long on each axis.
  const int wall_rows = std::max(4, 8 - gap_rows);
  const int nx = 8, ny = gap_rows + wall_rows;
  const double Lx = nx * dx, Ly = ny * dx;
  std::vector<std::string> o = periodic_box_2d(Lx, Ly, dx, nu, g);
  for (const auto& e : extra) o.push_back(e);
  auto scene = example_scene<Dim>("taylor_green_2d", o);
  isph::IsphSolver<Dim> solver(scene.config, scene.domain, scene.particles);
  auto& P = solver.particles();
  // The slab: the lattice rows with y < wall_rows dx become one held PMS body.
  std::vector<uint8_t> drop(P.size(), 0);
  std::vector<isph::Vec<Dim>> x;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.x[i][1] < wall_rows * dx) {
      drop[i] = 1;
      x.push_back(P.x[i]);
    }
  isph::erase_particles(P, drop);
  isph::RigidPose<Dim> pose;
  pose.x = isph::Vec<Dim>(0.5 * Lx, 0.5 * wall_rows * dx);
  const std::size_t first = P.size();
  isph::add_rigid_body<Dim>(P, 0, x, pose);
  // add_rigid_body finds the surface from free lattice nodes and does not know that the slab
  // is periodic along x: its end columns would see a face there. The faces are the slab's top
  // and bottom only.
  for (std::size_t i = first; i < P.size(); ++i) {
    const double y = P.x[i][1];
    const double up = wall_rows * dx - y, down = y;  // distances to the two faces
    P.wall_distance[i] = std::min(up, down);
    P.normal[i] = isph::Vec<Dim>(0.0, up < down ? 1.0 : -1.0);
    P.body_normal[i] = P.normal[i];
  }
  const std::vector<isph::RigidPose<Dim>> poses{pose};
  run_to_steady([&](double dt) {
    isph::place_rigid_solids(P, solver.domain(), poses);
    solver.step(dt);
  });
  return measure(solver, gap_rows, wall_rows * dx, "PMS");
}

// The same channel between wall particles (walls.boxes), for comparison.
ChannelResult wall_channel(int gap_rows, const std::vector<std::string>& extra = {}) {
  const double dx = kDx, nu = kNu, g = kG;
  const double Lx = 8 * dx, H = gap_rows * dx;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", nu);
  const std::string fluid =
      "{min=[0,0],max=[" + std::to_string(Lx) + "," + std::to_string(H) + "]}";
  std::vector<std::string> o{
      std::string("fluid.viscosity=") + buf,
      "particles.spacing=" + std::to_string(dx),
      "domain.min=[0," + std::to_string(-4 * dx) + "]",
      "domain.max=[" + std::to_string(Lx) + "," + std::to_string(H + 4 * dx) + "]",
      "fluid.blocks=[" + fluid + "]",
      "walls.boxes=[" + fluid + "]",
      "fluid.gravity=[" + std::to_string(g) + ",0]"};
  for (const auto& e : extra) o.push_back(e);
  auto scene = example_scene<2>("poiseuille_2d", o);
  isph::IsphSolver<2> solver(scene.config, scene.domain, scene.particles);
  run_to_steady([&](double dt) { solver.step(dt); });
  return measure(solver, gap_rows, 0.0, "walls");
}

const std::vector<std::string> kQuadratic{"solver.wall_ghosts=\"quadratic\""};

// With the profile fitted along the normal the ghosts continue the parabola through the surface,
// and the SPH(2) Laplacian is exact for it: every row moves at the exact speed. The particles'
// flux is then the midpoint rule of that profile over the rows, which exceeds the exact flow
// rate by dx^2 / (2 H^2) (12.5% at 2 dx, 5.6% at 3, 3.1% at 4, 1.4% at 6): the quadrature of the
// rows, converging at second order, not a slip.
TEST(PmsChannel, QuadraticGhostsCarryThePoiseuilleProfileTwoToSixSpacingsWide) {
  for (int gap : {2, 3, 4, 6}) {
    const ChannelResult r = pms_channel(gap, kQuadratic);
    for (int k = 0; k < gap; ++k) EXPECT_NEAR(r.profile[k] / r.profile_exact[k], 1.0, 0.005);
    const double midpoint = 1.0 + 0.5 / (gap * gap);
    EXPECT_NEAR(r.q / r.exact, midpoint, 0.005) << gap << " spacings";
    EXPECT_NEAR(r.force / r.drive, 1.0, 1e-3);  // the walls take the whole drive
    const ChannelResult w = wall_channel(gap, kQuadratic);
    EXPECT_NEAR(w.q / r.q, 1.0, 1e-3);  // PMS walls are walls
  }
}

// The cause, kept measurable: extrapolated linearly from the fluid's centroid, the ghosts miss
// the profile's curvature across a narrow gap and the fluid slips (the flux +62 / +27 / +15 /
// +6.8% at 2 / 3 / 4 / 6 spacings; the same between wall particles).
TEST(PmsChannel, LinearGhostsLetANarrowGapSlip) {
  const std::vector<std::string> linear{"solver.wall_ghosts=\"linear\""};
  const ChannelResult three = pms_channel(3, linear);
  const ChannelResult six = pms_channel(6, linear);
  EXPECT_GT(three.q / three.exact, 1.2);
  EXPECT_GT(six.q / six.exact, 1.05);
  EXPECT_LT(six.q / six.exact, three.q / three.exact);
}

}  // namespace
}  // namespace isphdem::resolved_test
