// isphdem: command-line front end. Subcommands:
//   isphdem run CASE.toml --out DIR [--set key=value ...]   coupled or fluid-only case
//   isphdem dem SCRIPT [liggghts options]                   plain LIGGGHTS script, fix couple/isph
//   available
// MPI is initialised here once for every subcommand (LIGGGHTS needs it; fluid-only runs are a
// singleton job), so subcommands must neither initialise nor finalise it. PETSc likewise
// (solver.preconditioner = "amg"), inside MPI: started after MPI_Init, finalised before
// MPI_Finalize, so that -log_view and the unused-option warnings come at the end of every run.
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "dem/dem_command.hpp"
#include "petsc_session.hpp"
#include "run/run_command.hpp"

namespace {

struct Subcommand {
  const char* name;
  int (*main)(int argc, char** argv);  // argv[0] is the subcommand name
  const char* usage;
};

const Subcommand kSubcommands[] = {
    {"run", isphdem::run_main, "isphdem run CASE.toml --out DIR [--set key=value ...]"},
    {"dem", isphdem::dem_main,
     "isphdem dem SCRIPT [-var NAME VALUE ...] [-log FILE] [-screen FILE]"},
};

void print_usage(std::FILE* to) {
  std::fprintf(to, "usage:\n");
  for (const auto& s : kSubcommands) std::fprintf(to, "  %s\n", s.usage);
}

}  // namespace

static int run_subcommand(int argc, char** argv) {
  int rc = 2;
  if (argc < 2 || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help")) {
    print_usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const Subcommand* found = nullptr;
  for (const auto& s : kSubcommands)
    if (std::string(argv[1]) == s.name) found = &s;
  if (!found) {
    std::fprintf(stderr, "isphdem: unknown subcommand '%s'\n", argv[1]);
    print_usage(stderr);
    return rc;
  }
  try {
    isph::PetscSession petsc;
    rc = found->main(argc - 1, argv + 1);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isphdem %s: error: %s\n", found->name, e.what());
    rc = 1;
  }
  return rc;
}

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  const int rc = run_subcommand(argc, argv);
  MPI_Finalize();
  return rc;
}
