#include "petsc_session.hpp"

#include <petscsys.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "amg_solver.hpp"
#include "linear_solver.hpp"
#include "petsc_error.hpp"

namespace isph {

PetscSession::PetscSession() {
  // PETSc's own signal handler would catch a crash (or AddressSanitizer's report) and print a
  // PETSc message in its place; the run's own error paths are clearer. Options may be set
  // before PetscInitialize.
  PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
  check_petsc(PetscInitialize(nullptr, nullptr, nullptr, nullptr), "starting PETSc");
  push_petsc_error_handler();
  register_linear_solver("amg", [](const LinearSolverConfig& c) { return make_amg_solver(c); });
}

PetscSession::~PetscSession() {
  register_linear_solver("amg", nullptr);
  if (amg_solvers_created() > 0) {
    // A misspelt option is silently ignored by PETSc; say which ones nothing read.
    PetscInt n = 0;
    char** names = nullptr;
    char** values = nullptr;
    if (!PetscOptionsLeftGet(nullptr, &n, &names, &values)) {
      for (PetscInt k = 0; k < n; ++k)
        if (std::string(names[k]) != "no_signal_handler" && !is_builtin_amg_option(names[k]))
          std::fprintf(stderr,
                       "isphdem: warning: PETSc option -%s was set but never used "
                       "(misspelt, or for a solver this run does not have)\n",
                       names[k]);
      PetscOptionsLeftRestore(nullptr, &n, &names, &values);
    }
  }
  pop_petsc_error_handler();
  PetscFinalize();
}

}  // namespace isph
