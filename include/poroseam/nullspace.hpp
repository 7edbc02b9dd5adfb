// Fieldsplit set-up: named splits from the solution section, with the rigid-body modes of the
// displacement block attached as its near null space (AMG needs them for elasticity).
#pragma once

#include "poroseam/scene.hpp"
#include <petscts.h>
#include <vector>

namespace poroseam {

/// Makes `vectors` orthonormal in place (modified Gram-Schmidt), as MatNullSpaceCreate expects.
PetscErrorCode orthonormalize(std::vector<Vec> &vectors);

/// If the PC of the TS's Newton solver is PCFIELDSPLIT, defines the splits "displacement"
/// (with the rigid-body modes attached as its near null space) and "pressure" (the bulk and
/// the interface pressures together: a Schur complement takes exactly two splits).
/// Call after TSSetFromOptions. With a fieldsplit, *jacobian_diagonal becomes a global vector
/// that the caller must fill with the Jacobian's diagonal at every assembly (the displacement
/// preconditioner vertex_blocks needs it); otherwise it stays null.
PetscErrorCode configureFieldSplit(TS ts, DM dm, const Scene &scene, Vec *jacobian_diagonal);

} // namespace poroseam
