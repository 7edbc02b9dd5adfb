// A mesh point's vertices and the place of its node (mesh_points.hpp).
#include "poroseam/mesh_points.hpp"

#include "poroseam/curved_nodes.hpp"

#include <petscdmplex.h>

namespace poroseam {

PetscErrorCode closureVertices(DM dm, PetscInt point, std::vector<PetscInt> &vertices)
{
  PetscInt vStart, vEnd, n, *pts = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetTransitiveClosure(dm, point, PETSC_TRUE, &n, &pts));
  vertices.clear();
  for (PetscInt i = 0; i < n; ++i)
    if (pts[2 * i] >= vStart && pts[2 * i] < vEnd) vertices.push_back(pts[2 * i]);
  PetscCall(DMPlexRestoreTransitiveClosure(dm, point, PETSC_TRUE, &n, &pts));
  PetscFunctionReturn(0);
}

PetscErrorCode displacementNodeLocation(DM dm, PetscSection csec, const PetscScalar *coords,
                                        PetscInt point, int dim, double x[3])
{
  std::vector<PetscInt> vertices;
  PetscFunctionBeginUser;
  x[0] = x[1] = x[2] = 0.0;
  PetscCall(closureVertices(dm, point, vertices));
  PetscCheck(!vertices.empty(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "point %" PetscInt_FMT " has no vertex", point);
  for (PetscInt q : vertices) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(csec, q, &off));
    for (int d = 0; d < dim; ++d)
      x[d] += PetscRealPart(coords[off + d]);
  }
  for (int d = 0; d < dim; ++d)
    x[d] /= (double)vertices.size();
  // Curved cells: the node gmsh placed for this edge, face or cell, found by that mean.
  const CurvedNodes *curved = curvedNodes(dm);
  if (!curved || vertices.size() == 1) PetscFunctionReturn(0);
  double node[3] = {0, 0, 0};
  PetscCheck(curved->find((int)vertices.size(), x, node), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "-mesh_geometry_order 2: no second-order node for mesh point %" PetscInt_FMT
             " at (%g, %g, %g)",
             point, x[0], x[1], x[2]);
  for (int d = 0; d < dim; ++d)
    x[d] = node[d];
  PetscFunctionReturn(0);
}

PetscErrorCode displacementNodePlaces(DM dm, std::vector<double> &places)
{
  PetscSection s, csec;
  Vec coords, like;
  const PetscScalar *x;
  PetscInt pStart, pEnd, n, dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetLocalVector(dm, &like));
  PetscCall(VecGetLocalSize(like, &n));
  PetscCall(DMRestoreLocalVector(dm, &like));
  places.assign((size_t)n, 0.0);
  PetscCall(PetscSectionGetChart(s, &pStart, &pEnd));
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetFieldDof(s, p, 0, &dof)); // the displacement
    if (dof != dim) continue;
    PetscCall(PetscSectionGetFieldOffset(s, p, 0, &off));
    double at[3];
    PetscCall(displacementNodeLocation(dm, csec, x, p, (int)dim, at));
    for (PetscInt d = 0; d < dim; ++d)
      places[off + d] = at[d];
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscFunctionReturn(0);
}

} // namespace poroseam
