#include "poroseam/support_check.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/interfaces.hpp"

#include <numeric>
#include <set>
#include <sstream>
#include <vector>

namespace poroseam {
namespace {

/// Union-find over the mesh's points (cells and vertices).
struct Parts {
  std::vector<PetscInt> parent;
  explicit Parts(PetscInt n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  PetscInt root(PetscInt p)
  {
    while (parent[p] != p)
      p = parent[p] = parent[parent[p]];
    return p;
  }
  void join(PetscInt a, PetscInt b) { parent[root(a)] = root(b); }
};

} // namespace

PetscErrorCode checkBodiesSupported(DM dm, const Scene &scene)
{
  MPI_Comm comm;
  PetscInt pStart, pEnd, cStart, cEnd, vStart, vEnd, dim;
  std::string error;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  if (cEnd > cStart) { // the rank that holds the mesh
    Parts parts(pEnd - pStart);
    // a cell joins its vertices; a cohesive cell's closure holds the vertices of both sides
    for (PetscInt c = cStart; c < cEnd; ++c) {
      PetscInt n, *pts = nullptr;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
      for (PetscInt i = 0; i < n; ++i)
        if (pts[2 * i] >= vStart && pts[2 * i] < vEnd) parts.join(pts[2 * i] - pStart, c - pStart);
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
    }
    // parts held by a displacement condition, per component: a part that nothing holds in
    // one direction translates freely along it. (Axisymmetric: the hoop stiffness holds the
    // radial direction, so only the axial one, y, needs a condition.)
    std::vector<std::set<PetscInt>> held(dim);
    DMLabel faceSets, vertexSets;
    PetscCall(DMGetLabel(dm, "Face Sets", &faceSets));
    PetscCall(DMGetLabel(dm, "Vertex Sets", &vertexSets)); // physical points (supports)
    for (const auto &bc : scene.conditions) {
      DMLabel groups = bc.on_point ? vertexSets : faceSets;
      if (bc.kind != BcKind::displacement || !groups || bc.component >= dim) continue;
      IS is = nullptr;
      PetscCall(DMLabelGetStratumIS(groups, bc.tag, &is));
      if (!is) continue;
      const PetscInt *idx;
      PetscInt m;
      PetscCall(ISGetLocalSize(is, &m));
      PetscCall(ISGetIndices(is, &idx));
      for (PetscInt k = 0; k < m; ++k) {
        PetscInt n, *pts = nullptr;
        PetscCall(DMPlexGetTransitiveClosure(dm, idx[k], PETSC_TRUE, &n, &pts));
        for (PetscInt i = 0; i < n; ++i)
          if (pts[2 * i] >= vStart && pts[2 * i] < vEnd)
            held[bc.component].insert(parts.root(pts[2 * i] - pStart));
        PetscCall(DMPlexRestoreTransitiveClosure(dm, idx[k], PETSC_TRUE, &n, &pts));
      }
      PetscCall(ISRestoreIndices(is, &idx));
      PetscCall(ISDestroy(&is));
    }
    // the first free part: its regions, cells and a point in it
    DMLabel cellSets;
    PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
    PetscInt freeRoot = -1, cells = 0, first = -1;
    std::set<std::string> regions;
    std::string directions;
    auto freeAlong = [&](PetscInt root) {
      std::string along;
      for (PetscInt d = scene.axisymmetric ? 1 : 0; d < dim; ++d)
        if (!held[d].count(root)) along += std::string(along.empty() ? "" : ", ") + "xyz"[d];
      return along;
    };
    for (PetscInt c = cStart; c < cEnd; ++c) {
      DMPolytopeType t;
      PetscCall(DMPlexGetCellType(dm, c, &t));
      if (isCohesive(t)) continue;
      const PetscInt r = parts.root(c - pStart);
      if (freeRoot < 0) {
        directions = freeAlong(r);
        if (directions.empty()) continue;
        freeRoot = r, first = c;
      }
      if (r != freeRoot) continue;
      ++cells;
      PetscInt tag = -1;
      if (cellSets) PetscCall(DMLabelGetValue(cellSets, c, &tag));
      const int region = scene.regionIndexOfTag((int)tag);
      regions.insert(region >= 0 ? "'" + scene.regions[region].name + "'"
                                 : "tag " + std::to_string(tag));
    }
    if (freeRoot >= 0) {
      Vec coords;
      PetscSection csec;
      PetscScalar *x = nullptr;
      PetscInt n = 0;
      PetscCall(DMGetCoordinatesLocal(dm, &coords));
      PetscCall(DMGetCoordinateSection(dm, &csec));
      PetscCall(DMPlexVecGetClosure(dm, csec, coords, first, &n, &x));
      double c[3] = {0, 0, 0};
      for (PetscInt i = 0; i < n; ++i)
        c[i % dim] += PetscRealPart(x[i]) / (n / dim);
      PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, first, &n, &x));
      std::ostringstream msg, names;
      for (const auto &r : regions)
        names << (names.tellp() > 0 ? ", " : "") << r;
      msg << "a part of the mesh (" << cells << " cell" << (cells > 1 ? "s" : "") << " of region"
          << (regions.size() > 1 ? "s " : " ") << names.str() << ", the first near (" << c[0]
          << ", " << c[1] << ", " << c[2] << ")) has no displacement condition along " << directions
          << " on any of its boundaries and no interface joining it to a part that has: it can "
          << "move as a rigid body (a rigid-body mode, a singular stiffness). Fix a displacement "
          << "along " << directions << " on one of its boundaries (-bc_<boundary>_u"
          << directions.substr(0, 1) << " 0), or join it to the rest of the mesh";
      error = msg.str();
    }
  }
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

} // namespace poroseam
