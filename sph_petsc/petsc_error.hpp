#pragma once
// PETSc reports an error by returning a code, after calling the error handler on the way up the
// stack. isphdem keeps PETSc's first message (the one that names the cause) and turns the code
// into an exception that carries it, so a bad option or a failed setup ends the run with
// PETSc's own words instead of its multi-line traceback.
#include <stdexcept>
#include <string>

namespace isph {

class PetscError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Installs the handler that records the message (PetscSession does this once).
void push_petsc_error_handler();
void pop_petsc_error_handler();

// Throws PetscError("<what>: PETSc: <message>. <hint>") when code (a PetscErrorCode) != 0.
void check_petsc(int code, const char* what);

}  // namespace isph
