// Fieldsplit set-up: named splits from the solution section, with the rigid-body modes of the
// displacement block attached as its near null space (AMG needs them for elasticity).
#pragma once

#include "poroseam/scene.hpp"
#include <petscts.h>

namespace poroseam {

/// If the PC of the TS's Newton solver is PCFIELDSPLIT, defines the splits "displacement"
/// (with the rigid-body modes attached as its near null space) and "pressure" (the bulk and
/// the interface pressures together: a Schur complement takes exactly two splits).
/// Call after TSSetFromOptions.
PetscErrorCode configureFieldSplit(TS ts, DM dm, const Scene &scene);

} // namespace poroseam
