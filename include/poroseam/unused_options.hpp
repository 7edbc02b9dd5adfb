// Options the user typed that nothing reads stop the run early, with "did you mean".
//
// PETSc warns about an option nothing read only as it finishes: -ts_dtt, -snes_montor or
// -ksp_typ ran a long 3D job to the end with the default in place of what was meant. Here the
// options the user typed (scene files, command line, PETSC_OPTIONS; not the options of
// poroseam's solver presets, which serve many scenes) are looked at twice:
//   - after set-up (TSSetFromOptions, TSSetUp, SNESSetUp), before the first step: the options
//     of the top-level time stepper, Newton, Krylov method and preconditioner (-ts_*, -snes_*,
//     -ksp_*, -pc_*), which PETSc has read by then;
//   - after the first linear solve: every other option, since solver splits
//     (-fieldsplit_*), sub-preconditioners and factorisation packages (-mat_mumps_*) read
//     theirs only when the first matrix is factored or the first split is set up.
// An option read by neither stops the run on every rank, one line each:
//   "option -ts_dtt: no such option in this run (did you mean -ts_dt?)"
// -options_unused_ok turns these errors into warnings (an option kept in a scene file for
// another solver configuration). Left to the warning at the end of the run: options read only
// at the end of a solve or of the run (names with "view", -*_converged_reason), PETSc's
// runtime options (-log_*, -malloc_*, -options_*, ...) and poroseam's own scene options,
// which checkOptionNames checks by name (option_check.hpp).
#pragma once

#include <petscts.h>
#include <set>
#include <string>
#include <vector>

namespace poroseam {

/// The options to watch and what was found so far.
struct UnusedOptionCheck {
  std::vector<std::string> typed; ///< names without '-', as typed (same order on every rank)
  bool warn_only = false;         ///< -options_unused_ok
  TS ts = nullptr;                ///< the run's time stepper (its solvers list their options)
  bool first_solve_checked = false;
  std::set<std::string> warned; ///< warned about already (with -options_unused_ok)
};

/// Reads -options_unused_ok (inside its own options section, so -help lists it).
PetscErrorCode readUnusedOptionsOk(MPI_Comm comm, UnusedOptionCheck *check);

/// Collective. After set-up: fails with PETSC_ERR_USER_INPUT (or warns, -options_unused_ok)
/// for the top-level solver options nothing read; then watches the first linear solve of
/// `check->ts` (a KSP post-solve hook) and checks every option there. `check` must outlive
/// the time stepper.
PetscErrorCode checkUnusedOptionsAfterSetUp(MPI_Comm comm, UnusedOptionCheck *check);

/// At the end of a run: every option nothing read, one warning line each (the solver preset's
/// options for a split the scene does not have; the options left to the end above; scene
/// options that do not apply in this configuration, such as -interface_<i>_D0 without _flow;
/// with -options_unused_ok, those warned about at set-up or the first solve, again).
/// -options_left, which PETSc reads only as it finishes, is not one of them.
PetscErrorCode reportUnusedOptions(MPI_Comm comm);

} // namespace poroseam
