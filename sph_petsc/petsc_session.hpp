#pragma once
// PETSc's lifetime in one object: PetscInitialize on construction, PetscFinalize on destruction,
// once per process (main(), or a test's main). While it lives, the pressure solver takes
// `solver.preconditioner = "amg"` (BoomerAMG from hypre under a PETSc Krylov solver).
// MPI must already be initialised (main does it for LIGGGHTS) or PETSc initialises it itself.
// The command line is not given to PETSc (isphdem's own arguments are not PETSc options);
// PETSc options come from PETSC_OPTIONS and from the case file ([solver.petsc] options).
namespace isph {

class PetscSession {
 public:
  PetscSession();
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
};

}  // namespace isph
