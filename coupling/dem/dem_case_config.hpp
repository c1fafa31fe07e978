// The `[dem]` table of a case file: which LIGGGHTS script drives the grains and how many DEM
// substeps make one fluid step.
//
//   [dem]
//   script = "in.liggghts"        # relative to the case file's directory
//   substeps = 100                # n_sub >= 1: DEM steps per fluid step
//   exchange = "staggered"        # optional: "sequential" (default) or "staggered"
//   log = "log.liggghts"          # optional, as liggghts -log (relative: to the output dir)
//   screen = "screen.liggghts"    # optional, as liggghts -screen (relative: to the output dir)
//   [dem.variables]               # optional, as liggghts -var NAME VALUE
//   nGrains = 500
#ifndef ISPHDEM_DEM_CASE_CONFIG_HPP
#define ISPHDEM_DEM_CASE_CONFIG_HPP

#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isphdem {

// How the DEM steps against the fluid. Sequential: the fluid steps, then the DEM takes that
// step's loads. Staggered: the DEM's substeps run on a thread of their own beside the fluid step,
// with the loads of the fluid step before (lagged by one fluid step), so that a second core
// carries them.
enum class DemExchange { sequential, staggered };

struct DemCaseConfig {
  std::filesystem::path script;  // resolved against the case directory
  int substeps = 1;
  DemExchange exchange = DemExchange::sequential;
  std::vector<std::pair<std::string, std::string>> variables;  // sorted by name
  std::optional<std::string> log, screen;                      // as written

  // liggghts command-line options for this case: -var ..., -log, -screen. Relative log and
  // screen paths are put under out_dir when one is given ("none" stays "none").
  std::vector<std::string> liggghts_args(const std::filesystem::path& out_dir = {}) const;
};

// Throws std::runtime_error naming the key and how to fix it.
DemCaseConfig parse_dem_table(const toml::table& dem, const std::filesystem::path& case_dir);

std::vector<std::string> dem_table_keys();

// A coupled case's fluid step must be exactly substeps DEM steps (1e-9 relative); throws
// std::runtime_error saying which values disagree and what would match.
void check_fluid_dt(double fluid_dt, int substeps, double dem_dt);

}  // namespace isphdem

#endif
