#pragma once
// Validation tests run the shipped example cases (with --set-style overrides), so examples and
// tests cannot drift apart.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"

namespace isphdem::validation {

inline std::string example(const std::string& name) {
  return std::string(ISPHDEM_SOURCE_DIR) + "/examples/" + name + "/case.toml";
}

inline std::vector<std::string> all_fluid_keys() {
  auto k = fluid_scene_keys();
  const auto r = run_settings_keys();
  k.insert(k.end(), r.begin(), r.end());
  k.push_back("reference.*");  // error metrics of `isphdem run` (docs/study.md): not read here
  return k;
}

// ctest runs some validations a second time with ISPHDEM_TEST_PRECONDITIONER=amg (the *.amg
// tests): the same case, the same tolerances, another pressure solver.
inline std::vector<std::string> with_test_preconditioner(std::vector<std::string> overrides) {
  if (const char* pc = std::getenv("ISPHDEM_TEST_PRECONDITIONER")) {
    std::printf("pressure solver: solver.preconditioner = \"%s\" (ISPHDEM_TEST_PRECONDITIONER)\n",
                pc);
    overrides.push_back("solver.preconditioner=\"" + std::string(pc) + "\"");
  }
  return overrides;
}

inline CaseFile load_example(const std::string& name, const std::vector<std::string>& overrides) {
  return CaseFile::load(example(name), with_test_preconditioner(overrides), all_fluid_keys());
}

}  // namespace isphdem::validation
