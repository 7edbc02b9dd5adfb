// A run: scene -> mesh -> layout -> TS backward Euler with Newton, per-step outputs.
#pragma once

#include <petscsys.h>
#include <string>
#include <vector>

namespace poroseam {

/// Runs the scene given by the PETSc options database on `comm`. `typed_options`: the names
/// (without '-') of the options the user typed, the same on every rank (unused_options.hpp).
PetscErrorCode runSimulation(MPI_Comm comm, const std::vector<std::string> &typed_options);

} // namespace poroseam
