#include "vertex_block_map.hpp"

#include "poroseam/layout.hpp"
#include "poroseam/nullspace.hpp"
#include "poroseam/vertex_blocks.hpp"

#include <algorithm>
#include <petscdmplex.h>

namespace poroseam {
namespace vertex_blocks_detail {
namespace {

constexpr const char *kMapName = "poroseam vertex blocks";

PetscErrorCode destroyMap(void *ctx)
{
  auto *map = static_cast<VertexBlockMap *>(ctx);
  PetscFunctionBeginUser;
  for (auto &v : map->ext_modes)
    PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&map->ext_of_free_global));
  PetscCall(VecDestroy(&map->jacobian_diagonal));
  PetscCall(VecDestroy(&map->coordinates));
  PetscCall(ISDestroy(&map->displacement));
  delete map;
  PetscFunctionReturn(0);
}

/// Axisymmetric: the two translations only (a radial displacement strains the hoop; the
/// translations are still the smooth low-energy modes AMG needs). Otherwise PETSc's rigid-body
/// modes from the coordinates.
PetscErrorCode extendedModes(int dim, bool axisymmetric, Vec coords, std::vector<Vec> &modes)
{
  PetscFunctionBeginUser;
  if (!axisymmetric) {
    MatNullSpace rigid;
    PetscInt n;
    const Vec *vecs;
    PetscCall(MatNullSpaceCreateRigidBody(coords, &rigid));
    PetscCall(MatNullSpaceGetVecs(rigid, nullptr, &n, &vecs));
    modes.resize(n);
    for (PetscInt m = 0; m < n; ++m) {
      PetscCall(VecDuplicate(vecs[m], &modes[m]));
      PetscCall(VecCopy(vecs[m], modes[m]));
    }
    PetscCall(MatNullSpaceDestroy(&rigid));
    PetscFunctionReturn(0);
  }
  Vec t[2];
  for (int m = 0; m < 2; ++m) {
    PetscInt n;
    PetscScalar *a;
    PetscCall(VecDuplicate(coords, &t[m]));
    PetscCall(VecGetLocalSize(t[m], &n));
    PetscCall(VecGetArray(t[m], &a));
    for (PetscInt i = 0; i < n; ++i)
      a[i] = (i % dim == m) ? 1.0 : 0.0;
    PetscCall(VecRestoreArray(t[m], &a));
    PetscCall(VecNormalize(t[m], nullptr));
  }
  modes.assign(t, t + 2);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode findMap(Mat P, const VertexBlockMap **map)
{
  MatNullSpace modes;
  PetscContainer container = nullptr;
  PetscFunctionBeginUser;
  PetscCall(MatGetNearNullSpace(P, &modes));
  if (modes) PetscCall(PetscObjectQuery((PetscObject)modes, kMapName, (PetscObject *)&container));
  PetscCheck(container, PetscObjectComm((PetscObject)P), PETSC_ERR_USER_INPUT,
             "-pc_type vertex_blocks works only on poroseam's displacement split "
             "(-fieldsplit_displacement_pc_type vertex_blocks with -pc_type fieldsplit)");
  void *ptr;
  PetscCall(PetscContainerGetPointer(container, &ptr));
  *map = static_cast<const VertexBlockMap *>(ptr);
  PetscFunctionReturn(0);
}

} // namespace vertex_blocks_detail

using namespace vertex_blocks_detail;

PetscErrorCode attachVertexBlocks(DM dm, int dim, bool axisymmetric, IS displacement,
                                  MatNullSpace modes, KSP outer, Vec jacobian_diagonal)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscSection local, global, csec;
  Vec coords;
  PetscInt pStart, pEnd;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(PetscSectionGetChart(local, &pStart, &pEnd));
  auto *map = new VertexBlockMap;
  map->dim = dim;
  map->outer = outer;
  PetscCall(PetscObjectReference((PetscObject)jacobian_diagonal));
  map->jacobian_diagonal = jacobian_diagonal;
  PetscCall(PetscObjectReference((PetscObject)displacement));
  map->displacement = displacement;
  PetscInt nfree;
  const PetscInt *free_global;
  PetscCall(ISGetLocalSize(displacement, &nfree));
  PetscCall(ISGetIndices(displacement, &free_global));

  map->ext_of_free.assign(nfree, -1);
  // Owned displacement nodes, in point order: dim extended rows each. A node is a point with
  // displacement unknowns: every vertex, and at order 2 edges, quadrilaterals and hexahedra
  // (layout.hpp).
  std::vector<PetscInt> owned;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt gdof, udof;
    PetscCall(PetscSectionGetDof(global, p, &gdof));
    PetscCall(PetscSectionGetFieldDof(local, p, kDisplacementField, &udof));
    if (gdof >= 0 && udof > 0) owned.push_back(p);
  }
  map->ext_local = dim * (PetscInt)owned.size();
  PetscCallMPI(MPI_Exscan(&map->ext_local, &map->ext_start, 1, MPIU_INT, MPI_SUM, comm));
  const PetscInt ext_start = map->ext_start;
  Vec ext_coords;
  PetscCall(VecCreateMPI(comm, map->ext_local, PETSC_DETERMINE, &ext_coords));
  PetscCall(VecSetBlockSize(ext_coords, dim));
  PetscScalar *xc;
  const PetscScalar *x;
  PetscCall(VecGetArray(ext_coords, &xc));
  PetscCall(VecGetArrayRead(coords, &x));
  for (size_t k = 0; k < owned.size(); ++k) {
    const PetscInt v = owned[k];
    PetscInt goff, ncon;
    const PetscInt *con = nullptr;
    double node[3];
    PetscCall(PetscSectionGetOffset(global, v, &goff));
    PetscCall(displacementNodeLocation(dm, csec, x, v, dim, node));
    for (int d = 0; d < dim; ++d)
      xc[k * dim + d] = node[d];
    // The free components are the point's first global dofs (field 0 comes first), in
    // component order, constrained ones left out.
    PetscCall(PetscSectionGetFieldConstraintDof(local, v, kDisplacementField, &ncon));
    if (ncon) PetscCall(PetscSectionGetFieldConstraintIndices(local, v, kDisplacementField, &con));
    PetscInt next = goff;
    for (int c = 0; c < dim; ++c) {
      if (std::find(con, con + ncon, c) != con + ncon) continue;
      const PetscInt *at = std::lower_bound(free_global, free_global + nfree, next);
      PetscCheck(at != free_global + nfree && *at == next, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "vertex_blocks: displacement dof %" PetscInt_FMT " not in the split", next);
      map->ext_of_free[at - free_global] = ext_start + (PetscInt)k * dim + c;
      ++next;
    }
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(VecRestoreArray(ext_coords, &xc));
  PetscCall(ISRestoreIndices(displacement, &free_global));
  for (PetscInt e : map->ext_of_free)
    PetscCheck(e >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "vertex_blocks: a displacement dof that belongs to no owned node");
  PetscCall(extendedModes(dim, axisymmetric, ext_coords, map->ext_modes));
  map->coordinates = ext_coords;
  // The same map as a vector of the displacement block, to look up off-rank columns.
  PetscCall(VecCreateMPI(comm, nfree, PETSC_DETERMINE, &map->ext_of_free_global));
  PetscScalar *e;
  PetscCall(VecGetArray(map->ext_of_free_global, &e));
  for (PetscInt i = 0; i < nfree; ++i)
    e[i] = (PetscScalar)map->ext_of_free[i];
  PetscCall(VecRestoreArray(map->ext_of_free_global, &e));
  PetscContainer container;
  PetscCall(PetscContainerCreate(comm, &container));
  PetscCall(PetscContainerSetPointer(container, map));
  PetscCall(PetscContainerSetUserDestroy(container, destroyMap));
  PetscCall(PetscObjectCompose((PetscObject)modes, kMapName, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscFunctionReturn(0);
}

} // namespace poroseam
