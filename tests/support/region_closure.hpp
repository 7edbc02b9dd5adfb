#pragma once
// Test helper: the mesh points of a region (its cells and their closures), for tests that
// move one body of a mesh (the block of block-on-base meshes) and keep the other.
#include <petscdmplex.h>
#include <vector>

namespace poroseam::test_support {

/// in[p - pStart] = 1 for every point p (cell, face, edge, vertex) in the closure of a cell of
/// `cell_sets` value `tag`, 0 elsewhere; sized to the chart.
inline PetscErrorCode markRegionClosure(DM dm, DMLabel cell_sets, PetscInt tag,
                                        std::vector<char> *in)
{
  PetscInt pStart, pEnd, cStart, cEnd;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  in->assign(pEnd - pStart, 0);
  for (PetscInt cell = cStart; cell < cEnd; ++cell) {
    PetscInt value;
    PetscCall(DMLabelGetValue(cell_sets, cell, &value));
    if (value != tag) continue;
    PetscInt n, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &pts));
    for (PetscInt k = 0; k < n; ++k)
      (*in)[pts[2 * k] - pStart] = 1;
    PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &pts));
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam::test_support
