// A mesh point's vertices and the place of its node (mesh_points.hpp).
#include "poroseam/mesh_points.hpp"

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
  PetscFunctionReturn(0);
}

} // namespace poroseam
