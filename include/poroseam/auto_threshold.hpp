// -solver_auto_threshold, read in one place for its two users: the memory estimate made before
// the mesh is read (mesh_limits.cpp, which predicts the preset) and the solver preset itself
// (solver_preset.cpp). Its default depends on the displacement order (defaultAutoThreshold).
#pragma once

#include <petscsys.h>

namespace poroseam {

/// Reads -solver_auto_threshold into *threshold (the default by `displacement_order` when not
/// given). Inside a PetscOptionsBegin section (PetscOptionsObject not null) -help lists it;
/// with null it is read without a -help line, so that -help lists it once. A negative value is
/// refused with one line. Collective on `comm`.
PetscErrorCode readAutoThreshold(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                                 int displacement_order, PetscInt *threshold);

} // namespace poroseam
