// The overlap check of the coupled run (run/grain_overlap.hpp): the deepest overlap of two
// grains relative to the smaller radius, spheres of one clump left out.
#include <gtest/gtest.h>

#include "run/grain_overlap.hpp"

namespace isphdem {
namespace {

DemAtom atom(int tag, Vec3 x, double r, int body = -1) {
  DemAtom a;
  a.tag = tag;
  a.x = x;
  a.radius = r;
  a.body = body;
  return a;
}

TEST(GrainOverlap, DeepestPairRelativeToTheSmallerRadius) {
  DemState s;
  // 1 and 2 touch (gap 0), 3 and 4 overlap by 0.1 mm with radii 1 and 0.5 mm: 20% of 0.5 mm;
  // 5 sits far from everything. Tags out of cell order on purpose.
  s.atoms = {atom(4, {0.0104, 0, 0}, 0.5e-3), atom(1, {0, 0, 0}, 1e-3),
             atom(2, {0.002, 0, 0}, 1e-3), atom(3, {0.009, 0, 0}, 1e-3),
             atom(5, {0.5, 0.5, 0.5}, 1e-3)};
  const GrainOverlap o = deepest_overlap(s);
  EXPECT_NEAR(o.relative, 0.2, 1e-9);
  EXPECT_EQ(std::min(o.tag_a, o.tag_b), 3);
  EXPECT_EQ(std::max(o.tag_a, o.tag_b), 4);
}

TEST(GrainOverlap, SpheresOfOneClumpDoNotCountButClumpsAgainstEachOtherDo) {
  DemState s;
  // Two clumps of two spheres each overlapping by design (centres 1 mm apart, radius 1 mm).
  s.atoms = {atom(1, {0, 0, 0}, 1e-3, 7), atom(2, {0.001, 0, 0}, 1e-3, 7),
             atom(3, {0.01, 0, 0}, 1e-3, 8), atom(4, {0.011, 0, 0}, 1e-3, 8)};
  EXPECT_EQ(deepest_overlap(s).relative, 0.0);
  // The second clump pressed into the first by 0.5 mm: sphere 3 against sphere 2.
  s.atoms[2].x[0] = 0.0025;
  s.atoms[3].x[0] = 0.0035;
  const GrainOverlap o = deepest_overlap(s);
  EXPECT_NEAR(o.relative, 0.5, 1e-9);
  EXPECT_EQ(o.tag_a, 2);
  EXPECT_EQ(o.tag_b, 3);
}

TEST(GrainOverlap, NothingToCompare) {
  DemState s;
  EXPECT_EQ(deepest_overlap(s).relative, 0.0);
  s.atoms = {atom(1, {0, 0, 0}, 1e-3)};
  EXPECT_EQ(deepest_overlap(s).relative, 0.0);
}

}  // namespace
}  // namespace isphdem
