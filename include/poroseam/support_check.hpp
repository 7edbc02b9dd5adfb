// Bodies that float free: a connected part of the mesh with no displacement condition on any
// of its boundaries and no interface joining it to one that has, can move as a rigid body.
// Its stiffness matrix is singular, and the run fails in Newton with no word about why.
#pragma once

#include "poroseam/scene.hpp"
#include <petscdmplex.h>

namespace poroseam {

/// Refuses, in one line naming the regions of the floating part and a point in it, a mesh
/// part that no displacement condition (-bc_<boundary>_u<x|y|z>) holds, directly or through
/// other parts. Parts are cells connected through shared vertices; interfaces (penalty
/// springs with normal and tangential stiffness) join the parts on their two sides. Call
/// after splitInterfaces, before distribution (the whole mesh on rank 0). Collective.
PetscErrorCode checkBodiesSupported(DM dm, const Scene &scene);

} // namespace poroseam
