// isphdem: command-line front end. Subcommands:
//   isphdem run CASE.toml --out DIR [--set key=value ...]   coupled or fluid-only case
//   isphdem dem SCRIPT [liggghts options]                   plain LIGGGHTS script, fix couple/isph
//   available
//   isphdem study STUDY.toml --out DIR [-j N]               a sweep of case keys, one run each
// MPI is initialised here once for every subcommand (LIGGGHTS needs it; fluid-only runs are a
// singleton job), so subcommands must neither initialise nor finalise it. PETSc likewise
// (solver.preconditioner = "amg"), inside MPI: started after MPI_Init, finalised before
// MPI_Finalize, so that -log_view and the unused-option warnings come at the end of every run.
// `study` alone starts neither: it only forks `isphdem run` processes, which must start MPI as
// fresh singletons, not as children of an MPI process.
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "dem/dem_command.hpp"
#include "petsc_session.hpp"
#include "run/case_keys.hpp"
#include "run/run_command.hpp"
#include "study/study_command.hpp"

namespace {

struct Subcommand {
  const char* name;
  int (*main)(int argc, char** argv);  // argv[0] is the subcommand name
  const char* usage;
  bool mpi;  // runs inside MPI and PETSc
};

int study(int argc, char** argv) { return isphdem::study_main(argc, argv, isphdem::case_keys()); }

const Subcommand kSubcommands[] = {
    {"run", isphdem::run_main, "isphdem run CASE.toml --out DIR [--set key=value ...] [--resume]",
     true},
    {"dem", isphdem::dem_main,
     "isphdem dem SCRIPT [-var NAME VALUE ...] [-log FILE] [-screen FILE]", true},
    {"study", study, "isphdem study STUDY.toml --out DIR [-j N] [--set key=value ...]", false},
};

void print_usage(std::FILE* to) {
  std::fprintf(to, "usage:\n");
  for (const auto& s : kSubcommands) std::fprintf(to, "  %s\n", s.usage);
}

}  // namespace

static const Subcommand* find_subcommand(int argc, char** argv) {
  if (argc < 2) return nullptr;
  for (const auto& s : kSubcommands)
    if (std::string(argv[1]) == s.name) return &s;
  return nullptr;
}

static int run_subcommand(const Subcommand& sub, int argc, char** argv) {
  try {
    if (!sub.mpi) return sub.main(argc - 1, argv + 1);
    isph::PetscSession petsc;
    return sub.main(argc - 1, argv + 1);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isphdem %s: error: %s\n", sub.name, e.what());
    return 1;
  }
}

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help")) {
    print_usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const Subcommand* sub = find_subcommand(argc, argv);
  if (!sub) {
    std::fprintf(stderr, "isphdem: unknown subcommand '%s'\n", argv[1]);
    print_usage(stderr);
    return 2;
  }
  if (!sub->mpi) return run_subcommand(*sub, argc, argv);
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);  // dem.exchange = "staggered"
  const int rc = run_subcommand(*sub, argc, argv);
  MPI_Finalize();
  return rc;
}
