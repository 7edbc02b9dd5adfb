// Errors found on one rank (a bad cell, a point outside the mesh) must stop every rank with
// the same message, or the others would wait forever in the next collective call.
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

/// Collective: if any rank passes a non-empty message, every rank fails with the message of
/// the lowest such rank (PETSC_ERR_USER_INPUT).
PetscErrorCode checkOnAllRanks(MPI_Comm comm, const std::string &local_error);

} // namespace poroseam
