// The internal-erosion measurements on hand-made states whose answers are known exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "run/erosion_diagnostics.hpp"

namespace isphdem {
namespace {

DemAtom fine(int tag, double x, double y) {
  DemAtom a;
  a.tag = tag;
  a.x = {x, y, 0.0005};
  a.radius = 0.0005;
  return a;
}

// A layer of fines 4 mm high from x = 0 to 10 mm, one clump at (5, 2) mm.
DemState layer() {
  DemState s;
  int tag = 1;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 4; ++j)
      s.atoms.push_back(fine(tag++, 0.0005 + 1e-3 * i, 0.0005 + 1e-3 * j));
  DemBody b;
  b.id = 1;
  b.x = {0.005, 0.002, 0.0005};
  s.bodies.push_back(b);
  return s;
}

const Vec3 kUp{0.0, 1.0, 0.0};

TEST(ErosionDiagnostics, InitialLayerHasNothingAboveAndItsOwnSurface) {
  const DemState s = layer();
  ErosionDiagnostics<2> d(s, kUp, 0.005, 2600.0);
  EXPECT_NEAR(d.initial_surface(), 0.004, 1e-15);
  const auto m = d.measure(s, isph::Particles<2>{});
  EXPECT_EQ(m.fines_above, 0);
  EXPECT_EQ(m.fines_out_of_window, 0);
  EXPECT_NEAR(m.surface_height, 0.004, 1e-15);
  EXPECT_EQ(m.skeleton_displacement, 0.0);
}

TEST(ErosionDiagnostics, EjectedFinesMovedClumpAndPoreJet) {
  const DemState s0 = layer();
  ErosionDiagnostics<2> d(s0, kUp, 0.005, 2600.0);
  DemState s = s0;
  s.atoms[3].x[1] = 0.0046;                // bottom just above the initial surface (0.004): counted
  s.atoms[7].x[1] = 0.0044;                // still overlaps the initial surface: not counted
  s.atoms[0].x[0] = -0.0002;               // centre left of the layer (x >= 0): out of the window
  s.atoms[38].x[0] = 0.0104;               // right of it (x <= 10 mm): out
  s.atoms[39].x[0] = 0.0099;               // moved right but still inside: not counted
  s.atoms[21].x[1] = -0.0001;              // below the layer's bottom (y >= 0): out
  s.bodies[0].x = {0.008, 0.006, 0.0005};  // moved by (3, 4) mm
  isph::Particles<2> fluid;
  fluid.add(isph::Vec<2>(0.002, 0.002), isph::Vec<2>(0.0, 0.01), isph::kFluid);  // in the layer
  fluid.add(isph::Vec<2>(0.002, 0.009), isph::Vec<2>(0.0, 1.0), isph::kFluid);   // above it
  fluid.add(isph::Vec<2>(0.003, 0.001), isph::Vec<2>(0.0, 1.0), isph::kWall);    // not fluid
  fluid.porosity = {0.5, 1.0, 1.0};
  const auto m = d.measure(s, fluid);
  EXPECT_EQ(m.fines_above, 1);
  EXPECT_EQ(m.fines_out_of_window, 3);
  EXPECT_NEAR(m.fines_above_mass, 2600.0 * 4.0 / 3.0 * M_PI * 1.25e-10, 1e-20);
  EXPECT_NEAR(m.skeleton_displacement, 0.005, 1e-15);
  EXPECT_NEAR(m.max_pore_speed_ratio, 0.01 / 0.5 / 0.005, 1e-12);  // interstitial speed / v_in
  EXPECT_NEAR(m.pore_speed_p95_ratio, 4.0, 1e-12);                 // one particle: all three
  EXPECT_NEAR(m.mean_pore_speed_ratio, 4.0, 1e-12);
  // Column 0 (x = 0..2 mm) now reaches 5.1 mm; the median of the 5 columns stays 4 mm.
  EXPECT_NEAR(m.surface_height, 0.004, 1e-15);
}

// Twenty-one particles in the layer at 1..21 v_in (interstitial): the maximum 21, the 95th
// percentile at rank 0.95 x 20 = 19 of the sorted speeds (the 20th: 20 v_in), the mean 11; one
// more particle above the layer and one wall change none of them.
TEST(ErosionDiagnostics, PoreSpeedPercentileAndMeanOverTheLayersFluid) {
  const DemState s0 = layer();
  ErosionDiagnostics<2> d(s0, kUp, 0.005, 2600.0);
  isph::Particles<2> fluid;
  for (int k = 20; k >= 0; --k)  // out of order: the percentile sorts
    fluid.add(isph::Vec<2>(0.0001 + 0.0004 * k, 0.002), isph::Vec<2>(0.0, 0.0025 * (k + 1)),
              isph::kFluid);
  fluid.add(isph::Vec<2>(0.002, 0.009), isph::Vec<2>(0.0, 1.0), isph::kFluid);  // above
  fluid.add(isph::Vec<2>(0.003, 0.001), isph::Vec<2>(0.0, 1.0), isph::kWall);
  fluid.porosity.assign(fluid.size(), 0.5);
  ErosionMeasures m = d.measure(s0, fluid);
  EXPECT_EQ(m.pore_speed_ratios.size(), 21u);
  EXPECT_NEAR(m.max_pore_speed_ratio, 21.0, 1e-12);
  EXPECT_NEAR(m.pore_speed_p95_ratio, 20.0, 1e-12);
  EXPECT_NEAR(m.mean_pore_speed_ratio, 11.0, 1e-12);
  // Decomposed, the ranks' lists are joined and the three set again: two halves, the same.
  ErosionMeasures half = m;
  half.pore_speed_ratios.assign(m.pore_speed_ratios.begin() + 10, m.pore_speed_ratios.end());
  half.pore_speed_ratios.insert(half.pore_speed_ratios.end(), m.pore_speed_ratios.begin(),
                                m.pore_speed_ratios.begin() + 10);
  set_pore_speeds(half);
  EXPECT_EQ(half.pore_speed_p95_ratio, m.pore_speed_p95_ratio);
  EXPECT_EQ(half.mean_pore_speed_ratio, m.mean_pore_speed_ratio);
  // Between ranks the percentile interpolates: 41 values 0..40 give 38 (rank 0.95 x 40 = 38).
  half.pore_speed_ratios.clear();
  for (int k = 0; k <= 40; ++k) half.pore_speed_ratios.push_back(k);
  set_pore_speeds(half);
  EXPECT_NEAR(half.pore_speed_p95_ratio, 38.0, 1e-12);
  half.pore_speed_ratios = {1.0, 3.0};  // rank 0.95: 1 + 0.95 x 2
  set_pore_speeds(half);
  EXPECT_NEAR(half.pore_speed_p95_ratio, 2.9, 1e-12);
}

}  // namespace
}  // namespace isphdem
