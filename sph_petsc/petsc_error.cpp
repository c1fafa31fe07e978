#include "petsc_error.hpp"

#include <petscsys.h>

#include <type_traits>

namespace isph {

namespace {

// The first (innermost) message of the error now travelling up; cleared once thrown.
std::string& pending_message() {
  static std::string m;
  return m;
}

PetscErrorCode record(MPI_Comm, int, const char* func, const char*, PetscErrorCode code,
                      PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL || pending_message().empty()) {
    const char* general = nullptr;
    PetscErrorMessage(code, &general, nullptr);
    std::string m = general ? general : "error";
    if (message && *message) m += ": " + std::string(message);
    if (func && *func) m += " (in " + std::string(func) + ")";
    pending_message() = m;
  }
  return code;
}

}  // namespace

void push_petsc_error_handler() { PetscPushErrorHandler(record, nullptr); }
void pop_petsc_error_handler() { PetscPopErrorHandler(); }

static_assert(std::is_same_v<PetscErrorCode, int>, "check_petsc takes PETSc's error code as int");

void check_petsc(int code, const char* what) {
  if (!code) return;
  std::string m = std::move(pending_message());
  pending_message().clear();
  if (m.empty()) m = "error code " + std::to_string(code);
  throw PetscError(std::string(what) + ": PETSc: " + m +
                   ". Check [solver.petsc] options in the case file and PETSC_OPTIONS in the "
                   "environment");
}

}  // namespace isph
