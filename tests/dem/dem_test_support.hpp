// Shared bits of the DEM tests: input paths and a quiet LiggghtsBackend.
#ifndef ISPHDEM_TESTS_DEM_TEST_SUPPORT_HPP
#define ISPHDEM_TESTS_DEM_TEST_SUPPORT_HPP

#include <cmath>
#include <string>

#include "dem/dem_liggghts_backend.hpp"

namespace isphdem::test {

inline std::string dem_input(const std::string& name) {
  return std::string(ISPHDEM_SOURCE_DIR) + "/tests/dem/inputs/" + name;
}

// LIGGGHTS's screen output goes to a file (not `-screen none`: see DESIGN.md pitfalls).
inline LiggghtsBackend quiet_backend(const std::string& tag) {
  return LiggghtsBackend({"-log", "none", "-echo", "none", "-screen",
                          std::string(ISPHDEM_BINARY_DIR) + "/tests/dem_screen_" + tag + ".txt"});
}

inline double rel_err(double got, double want) { return std::fabs(got - want) / std::fabs(want); }

}  // namespace isphdem::test

#endif
