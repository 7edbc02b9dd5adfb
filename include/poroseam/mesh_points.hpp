// What a mesh point's closure says about it: its vertices, and where the displacement node it
// carries lies. Shared by the interfaces' set-up, the solver's rigid-body modes and node
// blocks, and the outputs (one definition of "the node of an edge is its midpoint").
#pragma once

#include <petscdm.h>
#include <vector>

namespace poroseam {

/// The vertices in the closure of `point`, in closure order (a vertex: itself).
PetscErrorCode closureVertices(DM dm, PetscInt point, std::vector<PetscInt> &vertices);

/// Where the displacement node of a point lies: the mean of the vertices of its closure (the
/// vertex itself; at order 2 the midpoint of a straight edge, and the centre of a
/// quadrilateral or hexahedron, where its bilinear / trilinear map puts the Q2 node).
/// `coords` is the local coordinate array of `csec` (DMGetCoordinatesLocal).
PetscErrorCode displacementNodeLocation(DM dm, PetscSection csec, const PetscScalar *coords,
                                        PetscInt point, int dim, double x[3]);

} // namespace poroseam
