// The hints for LIGGGHTS errors match the messages as Debian's LIGGGHTS 3.8 prints them (taken
// from its screen output), and an unknown message gets none.
#include "dem/liggghts_error_hints.hpp"

#include <gtest/gtest.h>

namespace isphdem {
namespace {

TEST(LiggghtsErrorHints, KnownMessagesGetTheirHint) {
  const std::pair<const char*, const char*> cases[] = {
      {"ERROR: Incorrect args for pair coefficients (./src/pair_gran.cpp:208)", "pair_coeff * *"},
      {"ERROR: Invalid fix style: \"bogus/style\" (./src/modify.cpp:850)", "spelling of the fix"},
      {"ERROR: Fix particletemplate/multisphere (id clp): illegal number of spheres "
       "(./src/fix_template_multiplespheres.cpp:92)",
       "a single sphere is not a multisphere body"},
      {"ERROR: Set command with no atoms existing (./src/set.cpp:108)",
       "outside the simulation box"},
      {"ERROR: Fix insert/pack (id ins): Insertion region extends outside simulation box and a "
       "fixed boundary is used.Please use non-fixed boundaries in this case only "
       "(./src/fix_insert_pack.cpp:271)",
       "insertion region"},
      {"ERROR on proc 1: Lost atoms: original 5 current 4 (./src/thermo.cpp:445)",
       "left the DEM box"},
  };
  for (const auto& [line, expected] : cases)
    EXPECT_NE(liggghts_error_hint(line).find(expected), std::string::npos) << line;
}

TEST(LiggghtsErrorHints, UnknownMessageGetsNone) {
  EXPECT_EQ(liggghts_error_hint("ERROR: Something nobody has seen (./src/x.cpp:1)"), "");
}

}  // namespace
}  // namespace isphdem
