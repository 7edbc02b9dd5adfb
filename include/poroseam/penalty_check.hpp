// Set-up warning for interface penalties far from what the mesh calls for
// (docs/interface_parameters.md; the verdict itself is advisePenalty in penalty_advice.hpp).
#pragma once

#include "poroseam/scene.hpp"
#include <petscdm.h>

namespace poroseam {

/// Collective on dm (interfaces split; before distribution, so both sides of a face are on one
/// rank: a face whose sides this rank does not both hold is skipped): for each interface and each of K_N, K_T,
/// prints one warning line when some face's K h / E leaves [1, 1e4] (h the height of the
/// adjacent bulk cells over the face, E the softer or stiffer side's Young's modulus).
PetscErrorCode warnAboutPenalties(DM dm, const Scene &scene);

} // namespace poroseam
