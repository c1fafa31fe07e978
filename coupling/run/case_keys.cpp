#include "run/case_keys.hpp"

#include "case/coupling_table.hpp"
#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"
#include "dem/dem_case_config.hpp"
#include "study/reference_metrics.hpp"
#include "unresolved/unresolved_case.hpp"

namespace isphdem {

std::vector<std::string> case_keys() {
  auto k = fluid_scene_keys();
  const auto r = run_settings_keys();
  k.insert(k.end(), r.begin(), r.end());
  for (const auto& d : dem_table_keys()) k.push_back("dem." + d + (d == "variables" ? ".*" : ""));
  const auto u = unresolved_keys();
  k.insert(k.end(), u.begin(), u.end());
  const auto cp = coupling_keys();
  k.insert(k.end(), cp.begin(), cp.end());
  const auto ref = reference_keys();
  k.insert(k.end(), ref.begin(), ref.end());
  return k;
}

}  // namespace isphdem
