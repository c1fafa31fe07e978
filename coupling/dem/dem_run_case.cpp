#include "dem/dem_run_case.hpp"

#include <cmath>
#include <stdexcept>

#include "dem/dem_liggghts_backend.hpp"

namespace isphdem {

int run_dem_case(const DemCaseConfig& config, double t_end, const DemRunOptions& options) {
  if (!(t_end >= 0.0)) throw std::runtime_error("run_dem_case: end time must be >= 0");
  LiggghtsBackend dem(config.liggghts_args(options.out_dir), options.comm);
  dem.initialize({config.script, {}});
  const double chunk = config.substeps * dem.timestep();
  if (options.fluid_dt) check_fluid_dt(*options.fluid_dt, config.substeps, dem.timestep());
  // The tolerance keeps t_end = k * chunk from costing an extra chunk through round-off.
  const long n_chunks = static_cast<long>(std::ceil(t_end / chunk - 1e-9));
  for (long c = 1; c <= n_chunks; c++) {
    dem.advance(config.substeps);
    if (options.after_chunk) options.after_chunk(dem, c);
  }
  dem.finalize();
  return 0;
}

}  // namespace isphdem
