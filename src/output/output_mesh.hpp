// The mesh the bulk field output is drawn on: its nodes (where the displacement lives), their
// coordinates, and the cells' connectivity in XDMF/VTK order, each in the files' order (by
// serial point number, output_order.hpp). Internal to src/output.
//
// At displacement order 1 the nodes are the vertices and the cells linear (Triangle,
// Quadrilateral, Tetrahedron, Hexahedron). At order 2 (Taylor-Hood, docs/elements.md) every
// mesh point that carries displacement unknowns is a node, the vertices and the points of
// higher dimension (edges, and on tensor cells the faces and the cell), and the cells are
// written as XDMF's quadratic cells (Triangle_6, Quadrilateral_9, Tetrahedron_10,
// Hexahedron_27), which ParaView draws with its quadratic (VTK) cells: the displacement is then
// shown as the quadratic field it is, not only by its vertex values.
#pragma once

#include "output_order.hpp"

#include <petscdm.h>
#include <vector>

namespace poroseam {

struct OutputMesh {
  PetscInt dim = 0;  // topological dimension
  PetscInt cdim = 0; // coordinate dimension
  DMPolytopeType cellType = DM_POLYTOPE_UNKNOWN; // the (single) bulk cell type
  bool quadratic = false;                        // nodes beyond the vertices
  const char *topology = nullptr;                // XDMF topology name
  PetscInt nodesPerCell = 0;
  PetscInt numNodes = 0; // global
  PetscInt numCells = 0; // global
  /// Local points of the nodes this rank writes (owned), in this rank's order.
  std::vector<PetscInt> ownedNodes;
  /// For each owned node, the local vertices whose mean is its position (the node itself for
  /// a vertex; the straight edge's ends, the face's or cell's corners): the pressure, linear
  /// at both orders, is their mean there as well.
  std::vector<std::vector<PetscInt>> nodeVertices;
  /// Local cell points this rank writes (owned bulk cells), in this rank's order.
  std::vector<PetscInt> ownedCells;
  /// Connectivity of ownedCells in the files' order (nodesPerCell global node numbers each).
  std::vector<PetscInt> connectivity;
  /// Coordinates of ownedNodes (cdim each), this rank's order.
  std::vector<PetscScalar> coordinates;
  OutputOrder nodeOrder, cellOrder; // from this rank's order to the files'

  /// Builds everything above from the solution DM and the field `dispField` of its local
  /// section (whose points with unknowns are the nodes). Collective.
  PetscErrorCode build(DM dm, PetscInt dispField);
  PetscErrorCode destroy();
};

/// XDMF name and vertex count of a linear bulk cell type; nullptr for types not written.
const char *xdmfLinearTopology(DMPolytopeType ct, PetscInt *corners);

} // namespace poroseam
