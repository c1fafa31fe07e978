// `isphdem run` with solver.preconditioner = "amg": PETSc options reach the solver from the case
// file and from PETSC_OPTIONS, PETSc's monitors print, a bad option stops the run with PETSc's
// message, a misspelt one is named at the end, and the done: line reports the PPE cost.
#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

// 20 x 20 Taylor-Green particles for 0.02 s, with the AMG pressure solve.
std::string amg_case(const std::filesystem::path& dir) {
  return example("taylor_green_2d") + " --out " + (dir / "out").string() +
         " --set particles.spacing=0.05 --set time.end=0.02 --set 'solver.preconditioner=\"amg\"'";
}

TEST(PetscOptions, CaseFileOptionsReachTheSolverAndDoneLineReportsThePpe) {
  const auto dir = scratch("petsc_case_options");
  const Result r = run(amg_case(dir) + " --set 'solver.petsc.options=\"-ksp_converged_reason\"'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // One line per PPE solve from PETSc's own monitor; the absolute tolerance is ours.
  EXPECT_GT(count(r.output, "Linear solve converged due to CONVERGED_ATOL"), 0) << r.output;
  EXPECT_NE(r.output.find("PPE iterations/step"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pressure solve (amg): setup"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("never used"), std::string::npos) << r.output;
}

// isphdem sets BoomerAMG's coarsening itself (sph_petsc/amg_solver.cpp); a user who swaps the
// preconditioner leaves those options unread, and they are not the user's to be warned about.
TEST(PetscOptions, AnotherPreconditionerLeavesNoWarningAboutIsphdemsBoomerAmgDefaults) {
  const auto dir = scratch("petsc_other_pc");
  const Result r = run(amg_case(dir) + " --set 'solver.petsc.options=\"-pc_type jacobi\"'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("never used"), std::string::npos) << r.output;
}

TEST(PetscOptions, EnvironmentOptionsReachTheSolverAndMisspeltOnesAreNamed) {
  const auto dir = scratch("petsc_env_options");
  const Result r = run_shell("PETSC_OPTIONS='-ksp_monitor -ksp_tyep gmres' " + isphdem() + " run " +
                             amg_case(dir));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(count(r.output, "KSP Residual norm"), 0) << r.output;
  EXPECT_NE(r.output.find("PETSc option -ksp_tyep was set but never used"), std::string::npos)
      << r.output;
}

TEST(PetscOptions, BadOptionStopsTheRunWithPetscsMessage) {
  const auto dir = scratch("petsc_bad_option");
  const Result r = run(amg_case(dir) + " --set 'solver.petsc.options=\"-ksp_type nonsense\"'");
  EXPECT_EQ(r.exit_code, 2) << r.output;  // found while setting up, before any step: bad input
  EXPECT_NE(r.output.find("Unable to find requested KSP type nonsense"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("[solver.petsc] options"), std::string::npos) << r.output;
}

TEST(PetscOptions, PpeThatCannotConvergeStopsWithPetscsReasonStepAndTime) {
  const auto dir = scratch("petsc_no_convergence");
  const Result r =
      run(amg_case(dir) + " --set solver.max_iterations=1 --set solver.pressure_tolerance=1e-14");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("PETSc: DIVERGED_ITS"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pressure solver failed at step 1, t = 0 s"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("output written so far"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace isphdem::cli
