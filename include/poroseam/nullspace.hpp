// Fieldsplit set-up: named splits from the solution section, with the rigid-body modes of the
// displacement block attached as its near null space (AMG needs them for elasticity).
#pragma once

#include "poroseam/scene.hpp"
#include <petscts.h>

namespace poroseam {

/// If the PC of the TS's Newton solver is PCFIELDSPLIT, defines one split per non-empty field
/// ("displacement", "pressure", "interface_pressure") and attaches the rigid-body modes to the
/// displacement split.
/// Call after TSSetFromOptions.
PetscErrorCode configureFieldSplit(TS ts, DM dm, const Scene &scene);

} // namespace poroseam
