#pragma once
// `isphdem run` for a case with [dem] and no fluid: the grains advance in chunks of dem.substeps,
// exactly as they will between the fluid steps of a coupled case.
#include <filesystem>

#include "case/case_file.hpp"
#include "run/run_report.hpp"

namespace isphdem {

// Writes snapshots and diagnostics.csv into `out` through rank 0; returns the exit status.
int run_dem_only(const CaseFile& c, const std::filesystem::path& out, bool quiet,
                 RunReport& report);

}  // namespace isphdem
