// The high-order nodes of a second-order Gmsh mesh (curved_nodes.hpp).
#include "poroseam/curved_nodes.hpp"

#include <petscdmplex.h>

#include <petscfe.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

namespace poroseam {
namespace {

/// Name of the PetscContainer composed with a DM: its CurvedNodes.
constexpr const char *kCurvedNodes = "poroseam_curved_nodes";

PetscErrorCode destroyTable(void *table)
{
  delete static_cast<CurvedNodes *>(table);
  return 0;
}

/// PETSc 3.18 keeps the second-order coordinates of a simplex on the cell itself (a
/// discontinuous field: the cell's dofs hold all its nodes, vertices included, in the order of
/// the coordinate element's functionals, dim values each; measured on triangles and
/// tetrahedra), not on its edges as for quadrilaterals and hexahedra. A node's reference point
/// gives its barycentric coordinates, hence the reference vertices it lies between (two: the
/// node of an edge at order 2), whose mean is its key. The reference vertices are found among
/// the cell's vertices by their nodes, which must be the vertices exactly (the same file
/// through the same reader; the reference tetrahedron lists the first two in the other order
/// from the closure). Each edge's node is added once (`seen`).
PetscErrorCode addSimplexNodes(DM linear, PetscDualSpace space, PetscInt cell, const double *node,
                               PetscInt count, PetscSection lsec, const PetscScalar *l,
                               PetscInt vStart, PetscInt vEnd, PetscInt cdim,
                               std::set<std::vector<PetscInt>> &seen, CurvedNodes &table,
                               char *error, size_t error_size)
{
  PetscInt n, *pts = nullptr, dim;
  std::vector<PetscInt> vertices;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(linear, &dim));
  PetscCall(DMPlexGetTransitiveClosure(linear, cell, PETSC_TRUE, &n, &pts));
  for (PetscInt i = 0; i < n; ++i)
    if (pts[2 * i] >= vStart && pts[2 * i] < vEnd) vertices.push_back(pts[2 * i]);
  PetscCall(DMPlexRestoreTransitiveClosure(linear, cell, PETSC_TRUE, &n, &pts));
  // Barycentric coordinates of every node: the reference simplex has vertex 0 at
  // (-1, ..., -1) and vertex i at -1 + 2 e_(i-1).
  std::vector<std::vector<double>> lambda(count, std::vector<double>(dim + 1));
  for (PetscInt a = 0; a < count; ++a) {
    PetscQuadrature functional;
    const PetscReal *xi;
    PetscCall(PetscDualSpaceGetFunctional(space, a * cdim, &functional));
    PetscCall(PetscQuadratureGetData(functional, nullptr, nullptr, nullptr, &xi, nullptr));
    lambda[a][0] = 1.0;
    for (PetscInt i = 1; i <= dim; ++i) {
      lambda[a][i] = 0.5 * (xi[i - 1] + 1.0);
      lambda[a][0] -= lambda[a][i];
    }
  }
  std::vector<PetscInt> vertexOf(dim + 1, -1); // reference vertex -> mesh vertex
  for (PetscInt a = 0; a < count; ++a) {
    PetscInt only = -1, nonzero = 0;
    for (PetscInt i = 0; i <= dim; ++i)
      if (std::fabs(lambda[a][i]) > 1e-10) only = i, ++nonzero;
    if (nonzero != 1) continue;
    for (PetscInt v : vertices) {
      PetscInt qo;
      bool same = true;
      PetscCall(PetscSectionGetOffset(lsec, v, &qo));
      for (PetscInt d = 0; d < cdim; ++d)
        same = same && node[a * cdim + d] == PetscRealPart(l[qo + d]);
      if (same) vertexOf[only] = v;
    }
  }
  for (PetscInt i = 0; i <= dim; ++i)
    if (vertexOf[i] < 0) {
      PetscCall(PetscSNPrintf(error, error_size,
                              "the high-order read moved a vertex of simplex %d (no vertex of "
                              "the cell at its node %d)",
                              (int)cell, (int)i));
      PetscFunctionReturn(0);
    }
  for (PetscInt a = 0; a < count; ++a) {
    std::vector<PetscInt> between;
    double straight[3] = {0, 0, 0}, curved[3] = {0, 0, 0};
    for (PetscInt i = 0; i <= dim; ++i) {
      if (std::fabs(lambda[a][i]) < 1e-10) continue;
      between.push_back(vertexOf[i]);
      PetscInt qo;
      PetscCall(PetscSectionGetOffset(lsec, vertexOf[i], &qo));
      for (PetscInt d = 0; d < cdim; ++d)
        straight[d] += PetscRealPart(l[qo + d]);
    }
    if (between.size() < 2) continue; // a vertex (checked above)
    std::sort(between.begin(), between.end());
    if (!seen.insert(between).second) continue;
    for (PetscInt d = 0; d < cdim; ++d) {
      straight[d] /= between.size();
      curved[d] = node[a * cdim + d];
    }
    table.add((int)between.size(), straight, curved);
  }
  PetscFunctionReturn(0);
}

} // namespace

void CurvedNodes::add(int corners, const double straight[3], const double curved[3])
{
  entries_.push_back(corners);
  entries_.insert(entries_.end(), straight, straight + 3);
  entries_.insert(entries_.end(), curved, curved + 3);
}

void CurvedNodes::bucketOf(const double x[3], long long cell[3]) const
{
  for (int d = 0; d < 3; ++d)
    cell[d] = (long long)std::floor(x[d] / bucket_);
}

long long CurvedNodes::bucketKey(int corners, const long long cell[3]) const
{
  // A hash, not a unique number: find() compares the places.
  unsigned long long h = (unsigned long long)corners * 0x9E3779B97F4A7C15ull;
  for (int d = 0; d < 3; ++d)
    h = (h ^ (unsigned long long)cell[d]) * 0x100000001B3ull;
  return (long long)h;
}

void CurvedNodes::finish(double tolerance)
{
  tolerance_ = tolerance;
  // Buckets larger than the tolerance: a place within it lies in a neighbouring bucket.
  bucket_ = 4.0 * tolerance;
  index_.clear();
  for (size_t i = 0; i < size(); ++i) {
    const double *e = &entries_[i * kStride];
    long long cell[3];
    bucketOf(e + 1, cell);
    index_.emplace(bucketKey((int)e[0], cell), i);
  }
}

bool CurvedNodes::find(int corners, const double straight[3], double curved[3]) const
{
  long long cell[3], c[3];
  bucketOf(straight, cell);
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        c[0] = cell[0] + i, c[1] = cell[1] + j, c[2] = cell[2] + k;
        const auto range = index_.equal_range(bucketKey(corners, c));
        for (auto it = range.first; it != range.second; ++it) {
          const double *e = &entries_[it->second * kStride];
          if ((int)e[0] != corners) continue;
          const double dx = e[1] - straight[0], dy = e[2] - straight[1], dz = e[3] - straight[2];
          if (std::sqrt(dx * dx + dy * dy + dz * dz) > tolerance_) continue;
          std::copy(e + 4, e + 7, curved);
          return true;
        }
      }
  return false;
}

PetscErrorCode readGmshFile(MPI_Comm comm, const char *msh, bool high_order, DM *dm)
{
  // PETSc 3.18's reader takes the choice from the options database only; it is set for this
  // one read and the previous value (if any) put back.
  const char *name = "-dm_plex_gmsh_highorder";
  char previous[64] = "";
  PetscBool had = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, name, previous, sizeof previous, &had));
  PetscCall(PetscOptionsSetValue(nullptr, name, high_order ? "1" : "0"));
  PetscCall(DMPlexCreateGmshFromFile(comm, msh, PETSC_TRUE, dm));
  if (had)
    PetscCall(PetscOptionsSetValue(nullptr, name, previous[0] ? previous : nullptr));
  else
    PetscCall(PetscOptionsClearValue(nullptr, name));
  PetscFunctionReturn(0);
}

PetscErrorCode attachCurvedNodes(MPI_Comm comm, const char *msh, DM linear)
{
  PetscMPIInt rank;
  auto table = std::make_unique<CurvedNodes>();
  std::vector<double> packed;
  double tolerance = 0.0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  DM curved;
  PetscCall(readGmshFile(comm, msh, true, &curved));
  char error[256] = "";
  if (rank == 0) {
    PetscInt pStart, pEnd, qStart, qEnd, vStart, vEnd, cdim;
    PetscSection hsec, lsec;
    Vec hx, lx;
    const PetscScalar *h, *l;
    PetscCall(DMPlexGetChart(curved, &pStart, &pEnd));
    PetscCall(DMPlexGetChart(linear, &qStart, &qEnd));
    PetscCall(DMPlexGetDepthStratum(linear, 0, &vStart, &vEnd));
    PetscCall(DMGetCoordinateDim(linear, &cdim));
    PetscCall(DMGetCoordinateSection(curved, &hsec));
    PetscCall(DMGetCoordinateSection(linear, &lsec));
    PetscCall(DMGetCoordinatesLocal(curved, &hx));
    PetscCall(DMGetCoordinatesLocal(linear, &lx));
    PetscCall(VecGetArrayRead(hx, &h));
    PetscCall(VecGetArrayRead(lx, &l));
    // The same file through the same reader: the same points. Checked on the vertices.
    if (pStart != qStart || pEnd != qEnd)
      PetscCall(
          PetscSNPrintf(error, sizeof error, "the high-order read of %s has other points", msh));
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (PetscInt v = vStart; v < vEnd && !error[0]; ++v) {
      PetscInt ho, lo_off, hd;
      PetscCall(PetscSectionGetOffset(hsec, v, &ho));
      PetscCall(PetscSectionGetDof(hsec, v, &hd));
      PetscCall(PetscSectionGetOffset(lsec, v, &lo_off));
      for (PetscInt d = 0; d < cdim; ++d) {
        const double a = PetscRealPart(h[ho + d]), b = PetscRealPart(l[lo_off + d]);
        // hd == 0: a simplex's vertex, whose node the cell holds (addSimplexNodes checks it).
        if ((hd != cdim && hd != 0) || (hd == cdim && a != b))
          PetscCall(PetscSNPrintf(error, sizeof error, "the high-order read of %s moved vertex %d",
                                  msh, (int)v));
        lo[d] = v == vStart ? b : std::min(lo[d], b);
        hi[d] = v == vStart ? b : std::max(hi[d], b);
      }
    }
    double diameter = 0.0;
    for (int d = 0; d < 3; ++d)
      diameter += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    tolerance = 1e-9 * std::sqrt(diameter);
    std::set<std::vector<PetscInt>> seen; // simplices' edges whose node is in the table
    PetscDualSpace space = nullptr;       // of the coordinate element (simplices)
    for (PetscInt p = pStart; p < pEnd && !error[0]; ++p) {
      if (p >= vStart && p < vEnd) continue;
      PetscInt dof, off, n, *pts = nullptr;
      PetscCall(PetscSectionGetDof(hsec, p, &dof));
      if (dof == 0) continue;
      DMPolytopeType type;
      PetscCall(DMPlexGetCellType(linear, p, &type));
      if (dof > cdim && DMPolytopeTypeGetNumVertices(type) == DMPolytopeTypeGetDim(type) + 1) {
        if (!space) {
          DM cdm;
          PetscObject field;
          PetscCall(DMGetCoordinateDM(curved, &cdm));
          PetscCall(DMGetField(cdm, 0, nullptr, &field));
          PetscCall(PetscFEGetDualSpace((PetscFE)field, &space));
        }
        PetscInt functionals;
        PetscCall(PetscDualSpaceGetDimension(space, &functionals));
        PetscCall(PetscSectionGetOffset(hsec, p, &off));
        if (functionals != dof) {
          PetscCall(PetscSNPrintf(error, sizeof error,
                                  "%s: simplex %d holds %d coordinates, its element %d", msh,
                                  (int)p, (int)dof, (int)functionals));
          break;
        }
        std::vector<double> nodes(dof);
        for (PetscInt k = 0; k < dof; ++k)
          nodes[k] = PetscRealPart(h[off + k]);
        PetscCall(addSimplexNodes(linear, space, p, nodes.data(), dof / cdim, lsec, l, vStart, vEnd,
                                  cdim, seen, *table, error, sizeof error));
        continue;
      }
      if (dof != cdim) {
        PetscCall(PetscSNPrintf(error, sizeof error,
                                "%s: point %d holds %d coordinates; poroseam reads second-order "
                                "meshes with one node per point",
                                msh, (int)p, (int)dof));
        break;
      }
      PetscCall(PetscSectionGetOffset(hsec, p, &off));
      double straight[3] = {0, 0, 0}, node[3] = {0, 0, 0};
      int corners = 0;
      PetscCall(DMPlexGetTransitiveClosure(linear, p, PETSC_TRUE, &n, &pts));
      for (PetscInt i = 0; i < n; ++i) {
        const PetscInt q = pts[2 * i];
        if (q < vStart || q >= vEnd) continue;
        PetscInt qo;
        PetscCall(PetscSectionGetOffset(lsec, q, &qo));
        for (PetscInt d = 0; d < cdim; ++d)
          straight[d] += PetscRealPart(l[qo + d]);
        ++corners;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(linear, p, PETSC_TRUE, &n, &pts));
      for (PetscInt d = 0; d < cdim; ++d) {
        straight[d] /= corners;
        node[d] = PetscRealPart(h[off + d]);
      }
      table->add(corners, straight, node);
    }
    PetscCall(VecRestoreArrayRead(lx, &l));
    PetscCall(VecRestoreArrayRead(hx, &h));
    packed = table->packed();
  }
  PetscCall(DMDestroy(&curved));
  PetscCallMPI(MPI_Bcast(error, sizeof error, MPI_CHAR, 0, comm));
  PetscCheck(!error[0], comm, PETSC_ERR_LIB, "%s", error);
  long long count = (long long)packed.size();
  PetscCallMPI(MPI_Bcast(&count, 1, MPI_LONG_LONG, 0, comm));
  PetscCallMPI(MPI_Bcast(&tolerance, 1, MPI_DOUBLE, 0, comm));
  packed.resize((size_t)count);
  if (count) PetscCallMPI(MPI_Bcast(packed.data(), (int)count, MPI_DOUBLE, 0, comm));
  table->setPacked(std::move(packed));
  table->finish(tolerance);
  PetscContainer container;
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
  PetscCall(PetscContainerSetPointer(container, table.release()));
  PetscCall(PetscContainerSetUserDestroy(container, destroyTable));
  PetscCall(PetscObjectCompose((PetscObject)linear, kCurvedNodes, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscFunctionReturn(0);
}

const CurvedNodes *curvedNodes(DM dm)
{
  PetscContainer container = nullptr;
  if (PetscObjectQuery((PetscObject)dm, kCurvedNodes, (PetscObject *)&container) || !container)
    return nullptr;
  void *table = nullptr;
  if (PetscContainerGetPointer(container, &table)) return nullptr;
  return static_cast<const CurvedNodes *>(table);
}

PetscErrorCode keepCurvedNodes(DM from, DM to)
{
  PetscContainer container = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)from, kCurvedNodes, (PetscObject *)&container));
  if (container)
    PetscCall(PetscObjectCompose((PetscObject)to, kCurvedNodes, (PetscObject)container));
  PetscFunctionReturn(0);
}

} // namespace poroseam
