// The output mesh of the bulk fields: nodes, coordinates and connectivity (output_mesh.hpp).
#include "output_mesh.hpp"

#include "poroseam/mesh.hpp"
#include "poroseam/mesh_points.hpp"

#include <petscdmplex.h>
#include <petscsf.h>

#include <algorithm>
#include <array>
#include <map>

namespace poroseam {

const char *xdmfLinearTopology(DMPolytopeType ct, PetscInt *corners)
{
  switch (ct) {
  case DM_POLYTOPE_TRIANGLE:
    *corners = 3;
    return "Triangle";
  case DM_POLYTOPE_QUADRILATERAL:
    *corners = 4;
    return "Quadrilateral";
  case DM_POLYTOPE_TETRAHEDRON:
    *corners = 4;
    return "Tetrahedron";
  case DM_POLYTOPE_HEXAHEDRON:
    *corners = 8;
    return "Hexahedron";
  default:
    *corners = 0;
    return nullptr;
  }
}

namespace {

// Converts the vertices of a cell from DMPlex closure order to XDMF/VTK order (in place).
// DMPlex reference cells (DMPlexCreateReferenceCell): triangle and quadrilateral are
// counterclockwise (same as VTK); the tetrahedron (-1,-1,-1),(-1,1,-1),(1,-1,-1),(-1,-1,1) has
// negative VTK orientation (swap 0 and 1); the hexahedron lists the bottom face clockwise seen
// from above, (-1,-1,-1),(-1,1,-1),(1,1,-1),(1,-1,-1), then the top face counterclockwise
// (-1,-1,1),(1,-1,1),(1,1,1),(-1,1,1) (swap 1 and 3). This is DMPlexInvertCell().
void closureToXdmfOrder(DMPolytopeType ct, std::vector<PetscInt> &v)
{
  switch (ct) {
  case DM_POLYTOPE_TETRAHEDRON:
    std::swap(v[0], v[1]);
    break;
  case DM_POLYTOPE_HEXAHEDRON:
    std::swap(v[1], v[3]);
    break;
  default:
    break;
  }
}

// The nodes of XDMF's quadratic cells after the corners, each named by the corners (in XDMF
// corner order) it is the mean of: VTK's node order of the quadratic triangle, biquadratic
// quadrilateral, quadratic tetrahedron and triquadratic hexahedron (vtkCellType.h and the
// class documentation of each), which ParaView's XDMF 3 reader takes unchanged. The last entry
// of the quadrilateral and the hexahedron (all corners) is the cell's centre.
using NodeCorners = std::vector<std::vector<int>>;
const NodeCorners &quadraticNodes(DMPolytopeType ct)
{
  static const NodeCorners none;
  static const NodeCorners triangle = {{0, 1}, {1, 2}, {2, 0}};
  static const NodeCorners quadrilateral = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 1, 2, 3}};
  static const NodeCorners tetrahedron = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  static const NodeCorners hexahedron = {
      {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6},
      {3, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7},
      {0, 1, 2, 3, 4, 5, 6, 7}};
  switch (ct) {
  case DM_POLYTOPE_TRIANGLE:
    return triangle;
  case DM_POLYTOPE_QUADRILATERAL:
    return quadrilateral;
  case DM_POLYTOPE_TETRAHEDRON:
    return tetrahedron;
  case DM_POLYTOPE_HEXAHEDRON:
    return hexahedron;
  default:
    return none;
  }
}

const char *xdmfQuadraticTopology(DMPolytopeType ct)
{
  switch (ct) {
  case DM_POLYTOPE_TRIANGLE:
    return "Triangle_6";
  case DM_POLYTOPE_QUADRILATERAL:
    return "Quadrilateral_9";
  case DM_POLYTOPE_TETRAHEDRON:
    return "Tetrahedron_10";
  case DM_POLYTOPE_HEXAHEDRON:
    return "Hexahedron_27";
  default:
    return nullptr;
  }
}

} // namespace

PetscErrorCode OutputMesh::build(DM dm, PetscInt dispField)
{
  MPI_Comm comm;
  PetscSection section;
  PetscInt pStart, pEnd, vStart, vEnd, cStart, cEnd, cellHeight;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCheck(pStart == 0, comm, PETSC_ERR_SUP, "FieldWriter: chart must start at 0");
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));

  // Ownership of points from the point SF: a point is owned unless it is a leaf.
  std::vector<char> owned(pEnd, 1);
  PetscSF sf;
  {
    PetscInt nroots, nleaves;
    const PetscInt *ilocal;
    PetscCall(DMGetPointSF(dm, &sf));
    PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &ilocal, nullptr));
    if (nroots >= 0)
      for (PetscInt l = 0; l < nleaves; ++l)
        owned[ilocal ? ilocal[l] : l] = 0;
  }

  // The bulk cell type: one over the whole mesh (cohesive prisms are not written).
  PetscCall(DMPlexGetVTKCellHeight(dm, &cellHeight));
  PetscCall(DMPlexGetHeightStratum(dm, cellHeight, &cStart, &cEnd));
  PetscInt typeMin = PETSC_MAX_INT, typeMax = -1, corners = 0;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscInt nc;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (!owned[c] || !xdmfLinearTopology(ct, &nc)) continue;
    typeMin = PetscMin(typeMin, (PetscInt)ct);
    typeMax = PetscMax(typeMax, (PetscInt)ct);
  }
  {
    PetscInt in[2] = {-typeMin, typeMax}, out[2];
    PetscCall(MPIU_Allreduce(in, out, 2, MPIU_INT, MPI_MAX, comm));
    typeMin = -out[0];
    typeMax = out[1];
  }
  PetscCheck(typeMax >= 0, comm, PETSC_ERR_ARG_WRONG,
             "FieldWriter: the mesh has no bulk cells (triangle, quadrilateral, tetrahedron, "
             "hexahedron)");
  PetscCheck(typeMin == typeMax, comm, PETSC_ERR_SUP,
             "FieldWriter: mixed bulk cell types (%s and %s) are not supported; one bulk cell "
             "type per mesh",
             DMPolytopeTypes[typeMin], DMPolytopeTypes[typeMax]);
  cellType = (DMPolytopeType)typeMax;
  topology = xdmfLinearTopology(cellType, &corners);

  // Quadratic when some non-vertex point of a bulk cell carries displacement unknowns.
  auto dispDof = [&](PetscInt p, PetscInt *dof) -> PetscErrorCode {
    return PetscSectionGetFieldDof(section, p, dispField, dof);
  };
  std::vector<char> bulkNode(pEnd, 0); // a point in a bulk cell's closure with displacement
  {
    PetscInt any = 0;
    for (PetscInt c = cStart; c < cEnd; ++c) {
      DMPolytopeType ct;
      PetscInt *closure = nullptr, n;
      PetscCall(DMPlexGetCellType(dm, c, &ct));
      if (ct != cellType) continue;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
      for (PetscInt i = 0; i < 2 * n; i += 2) {
        const PetscInt q = closure[i];
        if (q >= vStart && q < vEnd) continue;
        PetscInt dof;
        PetscCall(dispDof(q, &dof));
        if (dof > 0) bulkNode[q] = 1, any = 1;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
    }
    PetscInt anyGlobal;
    PetscCall(MPIU_Allreduce(&any, &anyGlobal, 1, MPIU_INT, MPI_MAX, comm));
    quadratic = anyGlobal > 0;
    // The owner of a point need not hold a bulk cell around it (a face of an interface whose
    // cohesive cell went to another rank than the bulk cell): tell the owners.
    std::vector<PetscInt> mark(bulkNode.begin(), bulkNode.end()), ownerMark(mark);
    PetscCall(PetscSFReduceBegin(sf, MPIU_INT, mark.data(), ownerMark.data(), MPI_MAX));
    PetscCall(PetscSFReduceEnd(sf, MPIU_INT, mark.data(), ownerMark.data(), MPI_MAX));
    for (PetscInt p = pStart; p < pEnd; ++p)
      bulkNode[p] = (char)(ownerMark[p] > 0);
  }
  nodesPerCell = corners;
  if (quadratic) {
    topology = xdmfQuadraticTopology(cellType);
    nodesPerCell = corners + (PetscInt)quadraticNodes(cellType).size();
  }

  // Nodes: every owned vertex (as at order 1), then the owned higher-order points; all in the
  // files by serial point number, a vertex or an edge alike.
  std::vector<PetscInt> serial;
  PetscCall(serialPointNumbers(dm, serial));
  std::vector<PetscInt> keys;
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (owned[v]) {
      ownedNodes.push_back(v);
      nodeVertices.push_back({v});
    }
  for (PetscInt p = pStart; p < pEnd; ++p)
    if (owned[p] && bulkNode[p]) {
      ownedNodes.push_back(p);
      nodeVertices.emplace_back();
      PetscCall(closureVertices(dm, p, nodeVertices.back()));
    }
  for (PetscInt p : ownedNodes)
    keys.push_back(serial[p]);
  PetscInt nOwned = (PetscInt)ownedNodes.size();
  PetscCall(MPIU_Allreduce(&nOwned, &numNodes, 1, MPIU_INT, MPI_SUM, comm));
  std::vector<PetscInt> gnum(pEnd, -1);
  {
    std::vector<PetscInt> position;
    PetscCall(positionsByKey(comm, keys, std::vector<PetscInt>(keys.size(), 1), position));
    for (size_t i = 0; i < ownedNodes.size(); ++i)
      gnum[ownedNodes[i]] = position[i];
    PetscCall(nodeOrder.setup(comm, position));
    std::vector<PetscInt> leafNum(gnum);
    PetscCall(PetscSFBcastBegin(sf, MPIU_INT, gnum.data(), leafNum.data(), MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(sf, MPIU_INT, gnum.data(), leafNum.data(), MPI_REPLACE));
    gnum.swap(leafNum);
  }

  // Cells: corners in XDMF order, then (quadratic) the node of the closure point spanned by
  // each entry of quadraticNodes.
  const NodeCorners &extra = quadraticNodes(cellType);
  std::vector<PetscInt> verts, pointVerts;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (!owned[c] || ct != cellType) continue;
    PetscCall(closureVertices(dm, c, verts));
    PetscCheck((PetscInt)verts.size() == corners, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "FieldWriter: cell %" PetscInt_FMT " has %zu vertices in its closure, expected "
               "%" PetscInt_FMT,
               c, verts.size(), corners);
    closureToXdmfOrder(cellType, verts);
    std::vector<PetscInt> row(verts);
    if (quadratic) {
      // The cell's non-vertex points by their sorted corner sets.
      std::map<std::vector<PetscInt>, PetscInt> bySpan;
      PetscInt *closure = nullptr, n;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
      for (PetscInt i = 0; i < 2 * n; i += 2) {
        const PetscInt q = closure[i];
        if (q >= vStart && q < vEnd) continue;
        PetscCall(closureVertices(dm, q, pointVerts));
        std::sort(pointVerts.begin(), pointVerts.end());
        bySpan[pointVerts] = q;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
      for (const std::vector<int> &span : extra) {
        std::vector<PetscInt> key;
        for (int k : span)
          key.push_back(verts[k]);
        std::sort(key.begin(), key.end());
        const auto it = bySpan.find(key);
        PetscCheck(it != bySpan.end(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "FieldWriter: cell %" PetscInt_FMT " has no edge or face through %zu of its "
                   "corners",
                   c, key.size());
        row.push_back(it->second);
      }
    }
    for (PetscInt p : row) {
      PetscCheck(gnum[p] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "FieldWriter: point %" PetscInt_FMT " of cell %" PetscInt_FMT
                 " is not an output node",
                 p, c);
      connectivity.push_back(gnum[p]);
    }
    ownedCells.push_back(c);
  }
  PetscInt nCellsLocal = (PetscInt)ownedCells.size();
  PetscCall(MPIU_Allreduce(&nCellsLocal, &numCells, 1, MPIU_INT, MPI_SUM, comm));
  {
    std::vector<PetscInt> cellKeys, position;
    for (PetscInt c : ownedCells)
      cellKeys.push_back(serial[c]);
    PetscCall(positionsByKey(comm, cellKeys, std::vector<PetscInt>(cellKeys.size(), 1), position));
    PetscCall(cellOrder.setup(comm, position));
  }
  PetscCall(cellOrder.permute(connectivity, nodesPerCell));

  // Node coordinates: the mean of the node's corners (straight-sided cells: an edge's
  // midpoint, a face's or cell's centre under the bilinear / trilinear map).
  coordinates.assign(ownedNodes.size() * cdim, 0.0);
  {
    Vec coords;
    PetscSection csec;
    const PetscScalar *ca;
    PetscCall(DMGetCoordinatesLocal(dm, &coords));
    PetscCall(DMGetCoordinateSection(dm, &csec));
    PetscCall(VecGetArrayRead(coords, &ca));
    for (size_t i = 0; i < ownedNodes.size(); ++i) {
      double x[3];
      PetscCall(displacementNodeLocation(dm, csec, ca, ownedNodes[i], (int)cdim, x));
      for (PetscInt d = 0; d < cdim; ++d)
        coordinates[i * cdim + d] = x[d];
    }
    PetscCall(VecRestoreArrayRead(coords, &ca));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutputMesh::destroy()
{
  PetscFunctionBeginUser;
  PetscCall(nodeOrder.destroy());
  PetscCall(cellOrder.destroy());
  PetscFunctionReturn(0);
}

} // namespace poroseam
