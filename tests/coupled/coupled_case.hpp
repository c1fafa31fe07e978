#pragma once
// Coupled example cases (fluid + [dem] + [unresolved]) built the way `isphdem run` builds them,
// so that tests and examples cannot drift apart.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/fluid_scene.hpp"
#include "case/run_settings.hpp"
#include "dem/dem_case_config.hpp"
#include "dem/dem_communicator.hpp"
#include "dem/dem_liggghts_backend.hpp"
#include "run/case_keys.hpp"
#include "run/coupled_run.hpp"
#include "run/coupling_stages.hpp"
#include "unresolved/unresolved_coupling.hpp"

namespace isphdem::coupled_test {

inline CaseFile load_coupled_example(const std::string& name,
                                     const std::vector<std::string>& overrides) {
  return CaseFile::load(std::string(ISPHDEM_SOURCE_DIR) + "/examples/" + name + "/case.toml",
                        overrides, case_keys());
}

template <int Dim>
struct CoupledCase {
  std::unique_ptr<DemCommunicator> comm;  // before the backend: freed after it
  std::unique_ptr<LiggghtsBackend> backend;
  std::unique_ptr<CoupledRun<Dim>> run;
  const UnresolvedCoupling<Dim>* unresolved = nullptr;
};

// LIGGGHTS output goes to out_dir.
template <int Dim>
CoupledCase<Dim> make_coupled_case(const CaseFile& c, const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  const RunSettings settings = parse_run_settings(c);
  const DemCaseConfig dem = parse_dem_table(*c.table()["dem"].as_table(), c.directory());
  FluidScene<Dim> scene = build_fluid_scene<Dim>(c);
  auto stages = make_coupling_stages<Dim>(c, scene, settings.fixed_dt.value_or(0.0));
  CoupledCase<Dim> out;
  out.unresolved = dynamic_cast<const UnresolvedCoupling<Dim>*>(stages.front().get());
  out.comm = std::make_unique<DemCommunicator>(dem.exchange == DemExchange::staggered);
  out.backend = std::make_unique<LiggghtsBackend>(dem.liggghts_args(out_dir), out.comm->get());
  out.backend->initialize({dem.script, {}});
  out.run = std::make_unique<CoupledRun<Dim>>(std::move(scene), settings, *out.backend,
                                              dem.substeps, std::move(stages), dem.exchange);
  return out;
}

}  // namespace isphdem::coupled_test
