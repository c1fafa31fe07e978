// A DEM-only case (a `[dem]` table, no fluid) run through the same backend as coupled cases.
#ifndef ISPHDEM_DEM_RUN_CASE_HPP
#define ISPHDEM_DEM_RUN_CASE_HPP

#include <mpi.h>

#include <filesystem>
#include <functional>
#include <optional>

#include "dem/dem_backend.hpp"
#include "dem/dem_case_config.hpp"

namespace isphdem {

struct DemRunOptions {
  MPI_Comm comm = MPI_COMM_WORLD;
  std::filesystem::path out_dir;   // relative [dem] log/screen go here (see liggghts_args)
  std::optional<double> fluid_dt;  // if the case sets one: checked against substeps x DEM dt
  // Called on every rank after each chunk of `substeps` DEM steps (e.g. to write output);
  // chunk counts from 1.
  std::function<void(DemBackend&, long chunk)> after_chunk;
};

// Runs the script (its own `run` commands included), then advances in chunks of
// config.substeps DEM steps until t_end seconds have passed after the script (time 0 is the end
// of the script; the last chunk is not cut short). Returns 0.
int run_dem_case(const DemCaseConfig& config, double t_end, const DemRunOptions& options = {});

}  // namespace isphdem

#endif
