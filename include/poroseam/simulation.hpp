// A run: scene -> mesh -> layout -> TS backward Euler with Newton, per-step outputs.
#pragma once

#include <petscsys.h>

namespace poroseam {

/// Runs the scene given by the PETSc options database on `comm`.
PetscErrorCode runSimulation(MPI_Comm comm);

} // namespace poroseam
