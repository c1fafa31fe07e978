// coupling.model = "auto": each grain class resolved or not by d/dx, the fixed model the
// classes add up to, and what /dem/model then says of each atom.
#include <gtest/gtest.h>

#include "run/auto_model.hpp"

namespace isphdem {
namespace {

// A clump of `n` spheres of radius r in a row along x, centred at x0, and its body.
void add_clump(DemState& s, int id, double x0, int n, double r) {
  DemBody b;
  b.id = id;
  b.x = {x0, 0, 0};
  b.volume = n * 4.0 / 3.0 * M_PI * r * r * r;
  for (int k = 0; k < n; ++k) {
    DemAtom a;
    a.tag = int(s.atoms.size()) + 1;
    a.x = {x0 + (k - 0.5 * (n - 1)) * 2 * r, 0, 0};
    a.radius = r;
    a.body = id;
    b.members.push_back(a.tag);
    s.atoms.push_back(a);
  }
  s.bodies.push_back(b);
}

void add_spheres(DemState& s, int n, double r) {
  for (int k = 0; k < n; ++k) {
    DemAtom a;
    a.tag = int(s.atoms.size()) + 1;
    a.radius = r;
    s.atoms.push_back(a);
  }
}

TEST(AutoModel, SeedLayerIsSemiResolved) {
  // The seed's layer at dx = 1 mm: 5 mm clumps (five 1 mm spheres) and 1 mm fines.
  DemState s;
  add_clump(s, 1, 0.0, 5, 0.5e-3);
  add_clump(s, 2, 0.01, 5, 0.5e-3);
  add_spheres(s, 40, 0.5e-3);
  const AutoChoice c = choose_model(s, 1e-3, AutoThresholds{});
  EXPECT_EQ(c.model, "semi-resolved");
  ASSERT_EQ(c.classes.size(), 2u);
  EXPECT_TRUE(c.classes[0].clump);
  EXPECT_NEAR(c.classes[0].diameter, 5e-3, 1e-12);  // the extent, not the volume's 2.9 mm
  EXPECT_EQ(c.classes[0].count, 2u);
  EXPECT_TRUE(c.classes[0].resolved);
  EXPECT_FALSE(c.classes[1].resolved);
  EXPECT_EQ(c.classes[1].count, 40u);
  EXPECT_EQ(describe(c.classes[0], 1e-3), "clumps d = 5 mm, d/dx 5 -> resolved (PMS), 2 bodies");
  EXPECT_EQ(describe(c.classes[1], 1e-3),
            "free spheres d = 1 mm, d/dx 1 -> unresolved (porosity and drag), 40 spheres; between "
            "the validated ranges (unresolved up to d/dx 0.50, resolved from 3.00)");
}

TEST(AutoModel, CoarseFluidLeavesEverythingUnresolved) {
  DemState s;
  add_clump(s, 1, 0.0, 5, 0.5e-3);
  add_spheres(s, 3, 0.5e-3);
  EXPECT_EQ(choose_model(s, 4e-3, AutoThresholds{}).model, "unresolved");  // d/dx 1.25
  // Raising the threshold or refining moves the clumps across it.
  EXPECT_EQ(choose_model(s, 1e-3, AutoThresholds{6.0, 1.0}).model, "unresolved");
  EXPECT_EQ(choose_model(s, 0.8e-3, AutoThresholds{6.0, 1.0}).model, "semi-resolved");
}

TEST(AutoModel, ClumpsWithoutFinesAreResolvedAndMixedSizesSaySo) {
  DemState s;
  add_clump(s, 1, 0.0, 5, 0.5e-3);  // 5 mm
  add_clump(s, 2, 0.1, 2, 0.5e-3);  // 2 mm: below the threshold, resolved with the others
  const AutoChoice c = choose_model(s, 1e-3, AutoThresholds{});
  EXPECT_EQ(c.model, "resolved");
  ASSERT_EQ(c.classes.size(), 2u);
  for (const auto& g : c.classes) EXPECT_TRUE(g.resolved);
  const int noted = !c.classes[0].note.empty() + !c.classes[1].note.empty();
  EXPECT_EQ(noted, 1);
}

TEST(AutoModel, FreeSpheresAreResolvedWhenLargeEnough) {
  DemState s;
  add_spheres(s, 2, 1e-3);  // d = 2 mm
  AutoChoice c = choose_model(s, 1e-3, AutoThresholds{});
  EXPECT_EQ(c.model, "unresolved");
  EXPECT_NE(c.classes[0].note.find("between the validated ranges"), std::string::npos);
  c = choose_model(s, 0.5e-3, AutoThresholds{});  // d/dx 4
  EXPECT_EQ(c.model, "resolved");
  EXPECT_TRUE(c.classes[0].resolved);
  // With a second, small class of fines both stay unresolved (one model for all free spheres).
  add_spheres(s, 5, 0.1e-3);
  c = choose_model(s, 0.5e-3, AutoThresholds{});
  EXPECT_EQ(c.model, "unresolved");
  ASSERT_EQ(c.classes.size(), 2u);
  EXPECT_NE(c.classes[1].note.find("one model for all free spheres"), std::string::npos)
      << c.classes[1].note;
}

TEST(AutoModel, DemModelDatasetPerModel) {
  EXPECT_EQ(grain_models("semi-resolved").clumps, 1);
  EXPECT_EQ(grain_models("semi-resolved").free_spheres, 0);
  EXPECT_EQ(grain_models("unresolved").clumps, 0);
  EXPECT_EQ(grain_models("resolved").free_spheres, 1);
}

}  // namespace
}  // namespace isphdem
