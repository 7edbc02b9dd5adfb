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
/// quadrilateral or hexahedron, where its bilinear / trilinear map puts the Q2 node). With
/// curved cells (-mesh_geometry_order 2, curved_nodes.hpp) an edge, face or cell node is
/// where the second-order mesh puts it.
/// `coords` is the local coordinate array of `csec` (DMGetCoordinatesLocal).
PetscErrorCode displacementNodeLocation(DM dm, PetscSection csec, const PetscScalar *coords,
                                        PetscInt point, int dim, double x[3]);

/// Every displacement node's place (displacementNodeLocation) at its dofs, in the layout of
/// the dm's local vectors (its local section's displacement field; 0 elsewhere): a closure
/// read from it holds the element's nodes' places in node order, first. The geometry of
/// curved cells (-mesh_geometry_order 2).
PetscErrorCode displacementNodePlaces(DM dm, std::vector<double> &places);

} // namespace poroseam
