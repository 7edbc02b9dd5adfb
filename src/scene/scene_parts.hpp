// The parts of readSceneOptions that live in their own files (one concept per file).
#pragma once

#include "poroseam/scene.hpp"

#include <petscsys.h>

namespace poroseam {

/// A region's options, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readRegion(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, Region &r,
                          bool drained);

} // namespace poroseam
