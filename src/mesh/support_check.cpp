#include "poroseam/support_check.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/interfaces.hpp"

#include <algorithm>
#include <array>
#include <map>
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

/// The rigid-body displacements of a part (translations, then rotations about its centre c,
/// lengths in units of its size L) that a displacement condition of component `comp` at a
/// vertex x holds: row[k] = mode k's component `comp` at x. 2D: Tx, Ty, Rz; 3D: Tx, Ty, Tz,
/// Rx, Ry, Rz.
int modeRow(int dim, int comp, const double x[3], double row[6])
{
  const double X = x[0], Y = x[1], Z = dim == 3 ? x[2] : 0.0;
  const int n = dim == 2 ? 3 : 6;
  for (int k = 0; k < n; ++k)
    row[k] = 0.0;
  row[comp] = 1.0;
  if (dim == 2) {
    row[2] = comp == 0 ? -Y : X;
  } else {
    const double r[3][3] = {{0, Z, -Y}, {-Z, 0, X}, {Y, -X, 0}}; // [comp][axis]
    for (int a = 0; a < 3; ++a)
      row[3 + a] = r[comp][a];
  }
  return n;
}

/// The number of rigid-body modes a Gram matrix G = sum row row^T leaves free: its rank by
/// Gaussian elimination with full (diagonal) pivoting, pivots below 1e-10 of the largest
/// diagonal entry counting as zero (G is symmetric positive semi-definite).
int freeModes(std::vector<double> G, int n)
{
  double largest = 0.0;
  for (int i = 0; i < n; ++i)
    largest = std::max(largest, G[i * n + i]);
  std::vector<char> used(n, 0);
  int rank = 0;
  for (int step = 0; step < n; ++step) {
    int p = -1;
    for (int i = 0; i < n; ++i)
      if (!used[i] && (p < 0 || G[i * n + i] > G[p * n + p])) p = i;
    if (p < 0 || !(G[p * n + p] > 1e-10 * largest)) break;
    used[p] = 1;
    ++rank;
    for (int i = 0; i < n; ++i)
      if (!used[i]) {
        const double f = G[i * n + p] / G[p * n + p];
        for (int j = 0; j < n; ++j)
          G[i * n + j] -= f * G[p * n + j];
      }
  }
  return n - rank;
}

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
    // Held against rotation too: each part's Gram matrix of the rigid-body modes its
    // conditions hold (modeRow), about the centre of its bounding box in units of its size.
    Vec coords;
    PetscSection csec;
    const PetscScalar *xa;
    PetscCall(DMGetCoordinatesLocal(dm, &coords));
    PetscCall(DMGetCoordinateSection(dm, &csec));
    PetscCall(VecGetArrayRead(coords, &xa));
    auto vertexX = [&](PetscInt v, double x[3]) -> PetscErrorCode {
      PetscInt off;
      PetscFunctionBeginUser;
      PetscCall(PetscSectionGetOffset(csec, v, &off));
      for (PetscInt d = 0; d < 3; ++d)
        x[d] = d < dim ? PetscRealPart(xa[off + d]) : 0.0;
      PetscFunctionReturn(0);
    };
    std::map<PetscInt, std::array<double, 6>> box; // root -> lo, hi
    for (PetscInt v = vStart; v < vEnd; ++v) {
      double x[3] = {0, 0, 0};
      PetscCall(vertexX(v, x));
      auto it = box.find(parts.root(v - pStart));
      if (it == box.end()) {
        box[parts.root(v - pStart)] = {x[0], x[1], x[2], x[0], x[1], x[2]};
        continue;
      }
      for (int d = 0; d < 3; ++d)
        it->second[d] = std::min(it->second[d], x[d]),
        it->second[3 + d] = std::max(it->second[3 + d], x[d]);
    }
    const int nmodes = dim == 2 ? 3 : 6;
    std::map<PetscInt, std::vector<double>> gram; // root -> nmodes x nmodes
    auto holdRotation = [&](PetscInt v, int comp) -> PetscErrorCode {
      PetscFunctionBeginUser;
      const PetscInt root = parts.root(v - pStart);
      const auto &b = box[root];
      double x[3] = {0, 0, 0}, size = 0.0, row[6];
      PetscCall(vertexX(v, x));
      for (int d = 0; d < 3; ++d)
        size = std::max(size, b[3 + d] - b[d]);
      for (int d = 0; d < 3; ++d)
        x[d] = (x[d] - 0.5 * (b[d] + b[3 + d])) / (size > 0.0 ? size : 1.0);
      modeRow((int)dim, comp, x, row);
      auto &G = gram[root];
      G.resize(nmodes * nmodes, 0.0);
      for (int i = 0; i < nmodes; ++i)
        for (int j = 0; j < nmodes; ++j)
          G[i * nmodes + j] += row[i] * row[j];
      PetscFunctionReturn(0);
    };
    for (const auto &bc : scene.conditions) {
      DMLabel groups; // face groups, or physical points and curves (supports)
      PetscCall(DMGetLabel(dm, groupLabel(bc.support_dim), &groups));
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
          if (pts[2 * i] >= vStart && pts[2 * i] < vEnd) {
            held[bc.component].insert(parts.root(pts[2 * i] - pStart));
            PetscCall(holdRotation(pts[2 * i], bc.component));
          }
        PetscCall(DMPlexRestoreTransitiveClosure(dm, idx[k], PETSC_TRUE, &n, &pts));
      }
      PetscCall(ISRestoreIndices(is, &idx));
      PetscCall(ISDestroy(&is));
    }
    PetscCall(VecRestoreArrayRead(coords, &xa));
    // the first free part: its regions, cells and a point in it
    DMLabel cellSets;
    PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
    PetscInt freeRoot = -1, cells = 0, first = -1;
    std::set<std::string> regions;
    std::string directions;
    bool rotation = false; // the first free part is held against translation, not rotation
    auto freeAlong = [&](PetscInt root) {
      std::string along;
      for (PetscInt d = scene.axisymmetric ? 1 : 0; d < dim; ++d)
        if (!held[d].count(root)) along += std::string(along.empty() ? "" : ", ") + "xyz"[d];
      // (axisymmetric: a rotation about the axis is no mode of the (r, z) plane)
      rotation = along.empty() && !scene.axisymmetric && freeModes(gram[root], nmodes) > 0;
      return rotation ? std::string("rotation") : along;
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
      PetscScalar *x = nullptr;
      PetscInt n = 0;
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
          << ", " << c[1] << ", " << c[2] << ")) ";
      if (rotation)
        msg << "is held against translation but its displacement conditions leave a "
            << (dim == 2 ? "rotation about z" : "rotation")
            << " free: it can turn as a rigid body (a rigid-body mode, a singular stiffness). "
            << "Hold a second point in a direction the rotation moves (2D: a point on the x "
            << "axis through a point fixed in x and y, fixed in y; docs/scenes.md, \"Rigid-body "
            << "modes and fixing a point\")";
      else
        msg << "has no displacement condition along " << directions
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
