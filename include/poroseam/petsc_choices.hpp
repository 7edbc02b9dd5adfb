// Values of PETSc's choice options (-ksp_type, -pc_type, -pc_hypre_type, -ts_type ...) checked
// against PETSc's own lists before PETSc reads them: PETSc stops on an unknown one with a
// 30-line traceback (from every rank) that names neither the option nor what it accepts.
#pragma once

#include <petscsys.h>
#include <string>
#include <vector>

namespace poroseam {

/// What a choice option accepts.
struct PetscChoices {
  std::vector<std::string> values; ///< every value accepted
  std::string what;                ///< "Krylov method of PETSc (KSPType)"
  bool ignore_case = false;        ///< enum tables ignore case; registries do not (KSPSetType)
};

/// The values the choice option `name` (without '-', with or without a solver prefix such as
/// fieldsplit_displacement_) accepts; false when `name` is no choice option this check knows. Lists
/// come from PETSc's registries (KSPList, PCList, SNESList, SNESLineSearchList, TSList,
/// MatOrderingList, the solver packages PETSc was built with) and its enum tables; -pc_hypre_type's
/// from PETSc 3.18's hypre.c (not exported). Call after the registries are filled
/// (checkPetscChoices does) and after poroseam's own preconditioners are registered.
bool petscChoices(const std::string &name, PetscChoices *choices);

/// Collective (the options are the same on every rank). Every choice option set, with any
/// prefix, holds a value PETSc accepts; else fails with PETSC_ERR_USER_INPUT and one line:
/// "option -ksp_type gmress: not a Krylov method of PETSc; expected one of cg, ..., gmres, ...
/// (did you mean gmres?)". Call after poroseam's preconditioners are registered and before
/// TSSetFromOptions.
PetscErrorCode checkPetscChoices(MPI_Comm comm);

} // namespace poroseam
