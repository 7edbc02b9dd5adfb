#include "poroseam/closure_cache.hpp"

namespace poroseam {
namespace {

/// Offsets DMPlexVecGetClosure reads for each point: the closures of a vector whose entries
/// are their own offsets. Whatever ordering or permutation PETSc applies comes out the same.
PetscErrorCode closureOffsets(DM dm, PetscSection section, Vec like,
                              const std::vector<PetscInt> &points, std::vector<PetscInt> &start,
                              std::vector<PetscInt> &offsets)
{
  Vec v;
  PetscScalar *a;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(like, &v));
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt i = 0; i < n; ++i)
    a[i] = (PetscScalar)i;
  PetscCall(VecRestoreArray(v, &a));
  start.assign(1, 0);
  offsets.clear();
  for (PetscInt p : points) {
    PetscScalar *x = nullptr;
    PetscInt nx = 0;
    PetscCall(DMPlexVecGetClosure(dm, section, v, p, &nx, &x));
    for (PetscInt k = 0; k < nx; ++k)
      offsets.push_back((PetscInt)x[k]);
    PetscCall(DMPlexVecRestoreClosure(dm, section, v, p, &nx, &x));
    start.push_back((PetscInt)offsets.size());
  }
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ClosureCache::setup(DM dm, const std::vector<PetscInt> &points)
{
  PetscSection s, gs, csec;
  Vec work, coords;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetLocalVector(dm, &work));
  PetscCall(closureOffsets(dm, s, work, points, start_, local_));
  PetscCall(closureOffsets(dm, csec, coords, points, coordinate_start_, coordinates_));
  PetscInt nlocal;
  PetscCall(VecGetLocalSize(work, &nlocal));
  PetscCall(DMRestoreLocalVector(dm, &work));

  // Global indices exactly as DMPlexMatSetClosure computes them (closure permutation on,
  // constrained dofs negative). With one dof per point per field there is no orientation
  // permutation, so each local dof has one global index: checked here.
  const PetscInt unset = PETSC_MIN_INT;
  global_of_local_.assign(nlocal, unset);
  for (size_t i = 0; i < points.size(); ++i) {
    PetscInt n = 0, *idx = nullptr;
    PetscCall(
        DMPlexGetClosureIndices(dm, s, gs, points[i], PETSC_TRUE, &n, &idx, nullptr, nullptr));
    PetscCheck(n == closureSize(i), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "closure of point %" PetscInt_FMT ": %" PetscInt_FMT " indices, %d values",
               points[i], n, closureSize(i));
    const PetscInt *l = local(i);
    for (PetscInt k = 0; k < n; ++k) {
      PetscInt &g = global_of_local_[l[k]];
      PetscCheck(g == unset || g == idx[k], PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "local dof %" PetscInt_FMT " has global indices %" PetscInt_FMT
                 " and %" PetscInt_FMT " in different closures",
                 l[k], g, idx[k]);
      g = idx[k];
    }
    PetscCall(
        DMPlexRestoreClosureIndices(dm, s, gs, points[i], PETSC_TRUE, &n, &idx, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
