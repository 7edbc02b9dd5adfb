#include "vertex_block_map.hpp"

#include "poroseam/layout.hpp"
#include "poroseam/mesh_points.hpp"
#include "poroseam/nullspace.hpp"
#include "poroseam/vertex_blocks.hpp"

#include <algorithm>
#include <petscdmplex.h>
#include <petscsf.h>

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

/// Bit c set when displacement component c of `point` is an unknown (not constrained).
PetscErrorCode freeComponents(PetscSection local, PetscInt point, int dim, unsigned char *bits)
{
  PetscInt ncon;
  const PetscInt *con = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetFieldConstraintDof(local, point, kDisplacementField, &ncon));
  if (ncon)
    PetscCall(PetscSectionGetFieldConstraintIndices(local, point, kDisplacementField, &con));
  *bits = 0;
  for (int c = 0; c < dim; ++c)
    if (std::find(con, con + ncon, c) == con + ncon) *bits |= (unsigned char)(1u << c);
  PetscFunctionReturn(0);
}

/// Per point of the chart: `number` given on the points this rank owns (-1 elsewhere), filled
/// in on the points other ranks own from their owners (the DM's point SF).
PetscErrorCode shareNumbers(DM dm, PetscInt pStart, std::vector<PetscInt> &number)
{
  PetscSF sf;
  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCheck(pStart == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "vertex_blocks: chart not from 0");
  PetscInt roots;
  PetscCall(PetscSFGetGraph(sf, &roots, nullptr, nullptr, nullptr));
  if (roots < 0) PetscFunctionReturn(0); // one rank: no graph, every point is owned
  PetscCall(PetscSFBcastBegin(sf, MPIU_INT, number.data(), number.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPIU_INT, number.data(), number.data(), MPI_REPLACE));
  PetscFunctionReturn(0);
}

/// The order-1 level of an order-2 displacement field (VertexBlockMap::OrderOneLevel): which
/// owned nodes are vertices, the coarse numbering of vertices (owned vertices in point order,
/// ranks in order), and for every other node the vertices of its point's closure. An edge,
/// quadrilateral or hexahedron node sits where the bilinear/trilinear map of its vertices puts
/// the point's centre (reference coordinates), so an order-1 field takes there the mean of its
/// vertex values: the interpolation from order 1 to order 2.
PetscErrorCode buildOrderOneLevel(DM dm, PetscSection local, const std::vector<PetscInt> &owned,
                                  VertexBlockMap &map)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt pStart, pEnd, vStart, vEnd;
  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetChart(local, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscInt higher = 0; // nodes on points that are not vertices (any rank: order 2)
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt udof;
    PetscCall(PetscSectionGetFieldDof(local, p, kDisplacementField, &udof));
    if (udof > 0 && (p < vStart || p >= vEnd)) ++higher;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &higher, 1, MPIU_INT, MPI_MAX, comm));
  if (!higher) PetscFunctionReturn(0); // order 1: nothing to coarsen
  // Node numbers (the extended rows / dim) and vertex numbers (the coarse rows / dim) of the
  // owned nodes, in the order of `owned`; then shared with the ranks that see them as ghosts.
  std::vector<PetscInt> node_number(pEnd - pStart, -1), vertex_number(pEnd - pStart, -1);
  // The coarse level's nodes: the vertices. (Measured and not kept: keeping the steel's
  // order-2 nodes as well, where order-1 hexahedra lock in the skirt's bending: 3D caisson,
  // mesh factor 2, step 1, with an LU on the coarse level 30 outer iterations per Newton
  // iteration instead of 49, but with GAMG there 97, GAMG threshold 0.2 40, slower.)
  auto isVertex = [&](PetscInt p) { return p >= vStart && p < vEnd; };
  PetscInt owned_vertices = 0;
  for (size_t k = 0; k < owned.size(); ++k)
    if (isVertex(owned[k])) ++owned_vertices;
  PetscInt first_vertex = 0;
  PetscCallMPI(MPI_Exscan(&owned_vertices, &first_vertex, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) first_vertex = 0; // MPI_Exscan leaves rank 0's result undefined
  PetscInt next_vertex = first_vertex;
  for (size_t k = 0; k < owned.size(); ++k) {
    node_number[owned[k] - pStart] = map.ext_start / map.dim + (PetscInt)k;
    if (isVertex(owned[k])) vertex_number[owned[k] - pStart] = next_vertex++;
  }
  PetscCall(shareNumbers(dm, pStart, node_number));
  PetscCall(shareNumbers(dm, pStart, vertex_number));
  const int dim = map.dim;
  auto &one = map.order_one;
  one.coarse_of_node.assign(owned.size(), -1);
  one.node_free.assign(owned.size(), 0);
  one.node_vertex_start.assign(owned.size() + 1, 0);
  std::vector<PetscInt> closure;
  for (size_t k = 0; k < owned.size(); ++k) {
    const PetscInt p = owned[k];
    PetscCall(freeComponents(local, p, dim, &one.node_free[k]));
    one.node_vertex_start[k] = (PetscInt)one.vertex_coarse.size();
    if (isVertex(p)) {
      one.coarse_of_node[k] = vertex_number[p - pStart];
    } else {
      PetscCall(closureVertices(dm, p, closure));
      const size_t n = closure.size();
      PetscCheck(n == 2 || n == 4 || n == 8, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "vertex_blocks: a displacement node on a point with %zu vertices (expected an "
                 "edge, a quadrilateral or a hexahedron)",
                 n);
      for (PetscInt v : closure) {
        const PetscInt coarse = vertex_number[v - pStart], ext = node_number[v - pStart];
        PetscCheck(coarse >= 0 && ext >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "vertex_blocks: a closure vertex without a displacement node");
        unsigned char bits;
        PetscCall(freeComponents(local, v, dim, &bits));
        one.vertex_coarse.push_back(coarse);
        one.vertex_ext.push_back(ext);
        one.vertex_free.push_back(bits);
      }
    }
  }
  one.node_vertex_start[owned.size()] = (PetscInt)one.vertex_coarse.size();
  one.coarse_local = dim * owned_vertices;
  one.coarse_start = dim * first_vertex;
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

/// Per owned node: the largest Young's modulus of the cells around it. Each rank sees only its
/// own cells, so the largest over this rank's cells is reduced onto the owner (the DM's
/// point SF) before it is read at the owned points.
PetscErrorCode nodeModuli(DM dm, PetscInt pStart, PetscInt pEnd, const std::vector<PetscInt> &owned,
                          const std::vector<PetscReal> &cell_modulus, std::vector<PetscReal> &out)
{
  PetscInt cStart, cEnd;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCheck((PetscInt)cell_modulus.size() == cEnd - cStart, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "vertex_blocks: %zu cell moduli for %" PetscInt_FMT " cells", cell_modulus.size(),
             cEnd - cStart);
  std::vector<PetscReal> modulus(pEnd - pStart, 0.0);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    const PetscReal e = cell_modulus[c - cStart];
    if (e <= 0.0) continue;
    PetscInt n;
    PetscInt *closure = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
    for (PetscInt i = 0; i < n; ++i)
      modulus[closure[2 * i] - pStart] = std::max(modulus[closure[2 * i] - pStart], e);
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
  }
  PetscSF sf;
  PetscInt roots;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, &roots, nullptr, nullptr, nullptr));
  if (roots >= 0) { // more than one rank
    PetscCall(PetscSFReduceBegin(sf, MPIU_REAL, modulus.data(), modulus.data(), MPI_MAX));
    PetscCall(PetscSFReduceEnd(sf, MPIU_REAL, modulus.data(), modulus.data(), MPI_MAX));
  }
  out.resize(owned.size());
  for (size_t k = 0; k < owned.size(); ++k)
    out[k] = modulus[owned[k] - pStart];
  PetscFunctionReturn(0);
}

} // namespace vertex_blocks_detail

using namespace vertex_blocks_detail;

PetscErrorCode attachVertexBlocks(DM dm, int dim, bool axisymmetric, IS displacement,
                                  MatNullSpace modes, KSP outer, Vec jacobian_diagonal,
                                  const std::vector<PetscReal> &cell_modulus)
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
    PetscInt goff;
    unsigned char free_bits;
    double node[3];
    PetscCall(PetscSectionGetOffset(global, v, &goff));
    PetscCall(displacementNodeLocation(dm, csec, x, v, dim, node));
    for (int d = 0; d < dim; ++d)
      xc[k * dim + d] = node[d];
    // The free components are the point's first global dofs (field 0 comes first), in
    // component order, constrained ones left out.
    PetscCall(freeComponents(local, v, dim, &free_bits));
    PetscInt next = goff;
    for (int c = 0; c < dim; ++c) {
      if (!(free_bits & (1u << c))) continue;
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
  PetscCall(buildOrderOneLevel(dm, local, owned, *map));
  PetscCall(nodeModuli(dm, pStart, pEnd, owned, cell_modulus, map->node_modulus));
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
