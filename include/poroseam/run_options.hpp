// Checks of the run's PETSc options and of its output directory before anything is computed,
// so that a bad value ends in one line that names the option (PETSc's own parser names only
// the value: "Input string abc has no integer value").
#pragma once

#include <petscsys.h>
#include <petscts.h>
#include <string>

namespace poroseam {

/// Collective. Every numeric option poroseam or its PETSc objects read that is set (with or
/// without a solver prefix such as -fieldsplit_pressures_) must parse as PETSc parses it
/// (integer or real), and the time-stepping options must make a run: -ts_max_time > 0,
/// -ts_max_steps > 0, -ts_max_reject >= 0, -ts_dt > 0. Fails with PETSC_ERR_USER_INPUT and
/// "option -ts_max_steps abc: expected an integer" and the like.
PetscErrorCode checkNumericOptions(MPI_Comm comm);

/// For an integer option poroseam or its PETSc objects read (-checkpoint_every,
/// -fieldsplit_displacement_ksp_max_it, -mat_mumps_icntl_14, -output_fields_every ...): ""
/// when `value` fits PetscInt or is no number (checkNumericOptions says so), else "out of
/// range, expected an integer from -2147483648 to 2147483647" (PETSc's parser would cast it
/// silently: 4294967297 became 1). `option` with its '-'. Not collective, no PETSc call.
std::string integerRangeError(const std::string &option, const std::string &value);

/// Collective. Rank 0 creates the output directory (-output_dir, default `output`) with the
/// filesystem library and writes and removes a file in it; every rank learns the outcome.
/// Fails with one line naming the directory and the reason.
PetscErrorCode checkOutputDirectory(MPI_Comm comm);

/// Collective. After TSSetFromOptions: the run's final time and step limits as the TS holds
/// them (whatever set them) allow at least one step: max time > 0, max steps > 0, and
/// -ts_max_reject >= 0 (PETSc takes a negative number as "no limit": endless halving).
PetscErrorCode checkTimeSteppingOptions(TS ts);

/// The options whose value is exactly `value` ("-ts_max_steps", or "-a or -b"); "" if none.
/// Used to name the option in PETSc's parse errors, which give only the value.
std::string optionsWithValue(const std::string &value);

} // namespace poroseam
