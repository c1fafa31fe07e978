// fix couple/isph must reach Debian's prebuilt libliggghts through run-time registration.
#include <gtest/gtest.h>

#include "dem/dem_liggghts_session.hpp"
#include "fix_couple_isph.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "register_couple_isph.h"

namespace {

std::vector<std::string> quiet() {
  return {"-log",    "none",
          "-echo",   "none",
          "-screen", std::string(ISPHDEM_BINARY_DIR) + "/tests/dem_screen_registration.txt"};
}

TEST(FixRegistration, StockLibraryLacksTheStyleUntilRegistered) {
  std::vector<std::string> args = {"test"};
  for (auto& a : quiet()) args.push_back(a);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  auto* lmp = new LAMMPS_NS::LAMMPS(static_cast<int>(argv.size()), argv.data(), MPI_COMM_WORLD);
  EXPECT_TRUE(isphdem::fix_style_registered(lmp, "nve/sphere"));  // the lookup itself works
  EXPECT_FALSE(isphdem::fix_style_registered(lmp, "couple/isph"));
  isphdem::register_couple_isph(lmp);
  EXPECT_TRUE(isphdem::fix_style_registered(lmp, "couple/isph"));
  delete lmp;
}

TEST(FixRegistration, DriverSessionCreatesTheFixFromAnInputLine) {
  auto lmp = isphdem::open_liggghts(quiet(), MPI_COMM_WORLD);
  ASSERT_TRUE(isphdem::fix_style_registered(lmp.get(), "couple/isph"));
  for (const char* line : {"atom_style sphere", "atom_modify map array", "units si",
                           "region box block 0 1 0 1 0 1 units box", "create_box 1 box",
                           "fix cpl all couple/isph planar z 0.5"})
    lmp->input->one(line);
  const int i = lmp->modify->find_fix("cpl");
  ASSERT_GE(i, 0);
  EXPECT_STREQ(lmp->modify->fix[i]->style, "couple/isph");
  EXPECT_NE(dynamic_cast<LAMMPS_NS::FixCoupleIsph*>(lmp->modify->fix[i]), nullptr);
}

}  // namespace
