// Loads on the boundary (split from problem.cpp): the faces that carry applied tractions,
// normal pressures, fluxes and the free water's pressure, and their terms of the residual, also
// summed per boundary for the force and flow columns of the time series (run_resultants.cpp).

#include "poroseam/problem.hpp"

#include "cell_kernel.hpp"

#include "poroseam/collective_check.hpp"

#include <algorithm>
#include <cmath>
#include <petscsf.h>
#include <sstream>

namespace poroseam {
namespace {

/// Index of the boundary `name` in scene.boundaries, -1 when it is not one of them.
int boundaryIndex(const Scene &scene, const std::string &name)
{
  for (size_t b = 0; b < scene.boundaries.size(); ++b)
    if (scene.boundaries[b].name == name) return (int)b;
  return -1;
}

} // namespace

double Problem::loadFactor(double t) const
{
  for (const auto &bc : scene_->conditions)
    if (bc.time.kind() != TimeFunction::Kind::step) return bc.time.factor(t);
  return t > 0.0 ? 1.0 : 0.0;
}

PetscErrorCode Problem::setupLoadedFaces()
{
  PetscFunctionBeginUser;
  // Faces carrying tractions or fluxes: integrated once, by the rank that owns the face.
  PetscSF sf;
  PetscInt nleaves;
  const PetscInt *leaves;
  PetscCall(DMGetPointSF(dm_, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(dm_, &pStart, &pEnd));
  std::vector<char> ghost(pEnd - pStart, 0);
  for (PetscInt i = 0; i < (nleaves > 0 ? nleaves : 0); ++i)
    ghost[(leaves ? leaves[i] : i) - pStart] = 1;
  DMLabel faceSets;
  std::string error;
  PetscCall(DMGetLabel(dm_, "Face Sets", &faceSets));
  for (size_t i = 0; i < scene_->conditions.size(); ++i) {
    const auto &bc = scene_->conditions[i];
    if (bc.dirichlet() || !faceSets || bc.support_dim >= 0) continue;
    IS faces = nullptr;
    PetscCall(DMLabelGetStratumIS(faceSets, bc.tag, &faces));
    if (!faces) continue;
    const PetscInt *idx;
    PetscInt n;
    PetscCall(ISGetLocalSize(faces, &n));
    PetscCall(ISGetIndices(faces, &idx));
    for (PetscInt k = 0; k < n; ++k) {
      if (ghost[idx[k] - pStart]) continue;
      DMPolytopeType ct;
      PetscCall(DMPlexGetCellType(dm_, idx[k], &ct));
      LoadedFace f{idx[k], (int)i, 0, {0, 0, 0}, boundaryIndex(*scene_, bc.boundary)};
      PetscCall(elementIndex(ct, &f.element));
      if (bc.kind == BcKind::normal_pressure) {
        PetscCall(pressureNormal(bc, idx[k], &f, &error));
        if (!error.empty()) break;
      }
      faces_.push_back(f);
    }
    PetscCall(ISRestoreIndices(faces, &idx));
    PetscCall(ISDestroy(&faces));
  }
  PetscCall(checkOnAllRanks(PetscObjectComm((PetscObject)dm_), error));
  PetscCall(setupWaterLoad(ghost, pStart));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::pressureNormal(const BoundaryCondition &bc, PetscInt face, LoadedFace *f,
                                       std::string *error) const
{
  const PetscInt *support;
  PetscInt ns;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetSupportSize(dm_, face, &ns));
  PetscCall(DMPlexGetSupport(dm_, face, &support));
  if (ns != 1) {
    // Inside the mesh a face has two sides and no outward normal: which side is pushed?
    *error = bc.option + ": boundary '" + bc.boundary +
             "' has faces inside the mesh (cells on both sides); a normal pressure acts on the "
             "outer boundary only (inside, give a -bc_<b>_traction vector)";
    PetscFunctionReturn(0);
  }
  PetscCall(outwardNormal(face, support[0], f->normal));
  // A prescribed displacement component along the normal replaces the equilibrium row the
  // pressure loads (the traction rule of readBoundary); a tangential one is a rough support
  // and is kept (docs/scenes.md).
  for (const auto &c : scene_->conditions)
    if (c.boundary == bc.boundary && c.kind == BcKind::displacement &&
        std::abs(f->normal[c.component]) > 1e-8) {
      std::ostringstream n;
      n << "(";
      for (int d = 0; d < dim_; ++d)
        n << (d ? ", " : "") << f->normal[d];
      n << ")";
      *error = c.option + " and " + bc.option + " on the same boundary '" + bc.boundary +
               "': the pressure acts along the faces' normal, here " + n.str() +
               ", and the prescribed component leaves none of it to apply; give one of them "
               "(or split the boundary in the mesh)";
      break;
    }
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::setupWaterLoad(const std::vector<char> &ghost, PetscInt pStart)
{
  DMLabel faceSets;
  std::string error;
  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm_, "Face Sets", &faceSets));
  for (const auto &b : scene_->water_load_boundaries) {
    IS faces = nullptr;
    if (faceSets) PetscCall(DMLabelGetStratumIS(faceSets, b.tag, &faces));
    if (!faces) continue;
    const PetscInt *idx;
    PetscInt n;
    PetscCall(ISGetLocalSize(faces, &n));
    PetscCall(ISGetIndices(faces, &idx));
    for (PetscInt k = 0; k < n; ++k) {
      if (ghost[idx[k] - pStart]) continue;
      const PetscInt *support;
      PetscInt ns;
      PetscCall(DMPlexGetSupportSize(dm_, idx[k], &ns));
      PetscCall(DMPlexGetSupport(dm_, idx[k], &support));
      if (ns != 1) {
        // Inside the mesh the water would push both sides: it is not a free surface.
        error = "-water_load_boundaries: boundary '" + b.name +
                "' has faces inside the mesh; the water can only stand on the outer boundary";
        break;
      }
      DMPolytopeType ct;
      PetscCall(DMPlexGetCellType(dm_, idx[k], &ct));
      LoadedFace f{idx[k], kWaterLoad, 0, {0, 0, 0}, boundaryIndex(*scene_, b.name)};
      PetscCall(elementIndex(ct, &f.element));
      PetscCall(outwardNormal(idx[k], support[0], f.normal));
      // A prescribed displacement component of the same boundary would drop the water's
      // load along it (the traction rule of readBoundary, docs/scenes.md).
      for (const auto &bc : scene_->conditions)
        if (error.empty() && bc.boundary == b.name && bc.kind == BcKind::displacement &&
            std::abs(f.normal[bc.component]) > 1e-8)
          error = "-water_load_boundaries names '" + b.name + "', where " + bc.option +
                  " is prescribed: the free water's pressure acts along the faces' normal, "
                  "and the prescribed component leaves none of it to apply; give one of them";
      faces_.push_back(f);
    }
    PetscCall(ISRestoreIndices(faces, &idx));
    PetscCall(ISDestroy(&faces));
  }
  PetscCall(checkOnAllRanks(PetscObjectComm((PetscObject)dm_), error));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::addLoads(double t, double mass_scale, Vec f,
                                 std::vector<double> *totals) const
{
  PetscSection s, csec;
  Vec coords;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  if (totals) totals->assign(scene_->boundaries.size() * (dim_ + 1), 0.0);
  // Curved faces (-mesh_geometry_order 2): their nodes' places, read like a closure.
  Vec places = nullptr;
  if (!node_places_.empty())
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, (PetscInt)node_places_.size(),
                                    node_places_.data(), &places));
  // Natural conditions: R_u -= int t . v, R_p += s int psi q_n.
  std::vector<double> F, xg;
  for (const auto &face : faces_) {
    const bool water = face.condition == kWaterLoad;
    const BoundaryCondition *bc = water ? nullptr : &scene_->conditions[face.condition];
    const ReferenceElement &e = elements_[face.element];
    const double factor = water ? 1.0 : bc->time.factor(t);
    PetscScalar *xc = nullptr;
    PetscInt nc = 0, n = 0;
    PetscCall(DMPlexVecGetClosure(dm_, csec, coords, face.face, &nc, &xc));
    PetscScalar *x = nullptr; // only its size n: the face's dofs
    PetscCall(DMPlexVecGetClosure(dm_, s, f, face.face, &n, &x));
    PetscCall(DMPlexVecRestoreClosure(dm_, s, f, face.face, &n, &x));
    F.assign(n, 0.0);
    // Face closure: nn * dim displacements (node basis), then nv pressures (vertex basis).
    const int nv = e.num_vertices, nn = e.num_nodes, nu = nn * dim_;
    const int np = (int)n - nu;
    // The geometry: the vertices (straight face) or the nodes (curved, isoparametric).
    const bool curved = places != nullptr;
    if (curved) {
      PetscScalar *xp = nullptr;
      PetscInt npl = 0;
      PetscCall(DMPlexVecGetClosure(dm_, s, places, face.face, &npl, &xp));
      xg.assign(xp, xp + nu);
      PetscCall(DMPlexVecRestoreClosure(dm_, s, places, face.face, &npl, &xp));
    } else
      xg.assign(xc, xc + nc);
    const int ng = curved ? nn : nv;
    for (int q = 0; q < e.num_quadrature; ++q) {
      const double *phi = &e.basis[q * nv], *N = &e.node_basis[q * nn];
      const double *gphi = curved ? N : phi;
      double w = surfaceWeight(e, xg.data(), dim_, q, curved);
      double xq[3] = {0, 0, 0};
      for (int a = 0; a < ng; ++a)
        for (int d = 0; d < dim_; ++d)
          xq[d] += gphi[a] * xg[a * dim_ + d];
      // The normal at the point: the face's own (straight), or the curved face's there.
      double normal[3] = {face.normal[0], face.normal[1], face.normal[2]};
      if (curved) surfaceNormal(e, xg.data(), dim_, q, true, face.normal, normal);
      if (scene_->axisymmetric) w *= 2.0 * M_PI * xq[0];
      if (water) {
        // The free water's pressure, t = -p_w n where the face is below the water level: a
        // permanent load like gravity (no time function), balanced by the geostatic state.
        const double pw = std::max(0.0, initialPressure(xq));
        for (int a = 0; a < nn; ++a)
          for (int i = 0; i < dim_; ++i)
            F[a * dim_ + i] += w * N[a] * pw * normal[i];
        continue;
      }
      if (bc->kind == BcKind::traction)
        for (int a = 0; a < nn; ++a)
          for (int i = 0; i < dim_; ++i)
            F[a * dim_ + i] -= w * N[a] * bc->value[i] * factor;
      else if (bc->kind == BcKind::normal_pressure) // t = -P n on the face's own normal
        for (int a = 0; a < nn; ++a)
          for (int i = 0; i < dim_; ++i)
            F[a * dim_ + i] += w * N[a] * bc->value[0] * factor * normal[i];
      else if (bc->kind == BcKind::flux && np == nv)
        for (int a = 0; a < nv; ++a)
          F[nu + a] += mass_scale * w * phi[a] * bc->value[0] * factor;
    }
    PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, face.face, &nc, &xc));
    PetscCall(DMPlexVecSetClosure(dm_, s, f, face.face, F.data(), ADD_ALL_VALUES));
    if (totals && face.boundary >= 0) {
      // What the residual holds is minus the force on the body, plus the outflow.
      double *total = &(*totals)[face.boundary * (dim_ + 1)];
      for (int a = 0; a < nn; ++a)
        for (int i = 0; i < dim_; ++i)
          total[i] -= F[a * dim_ + i];
      if (np == nv)
        for (int a = 0; a < nv; ++a)
          total[dim_] += F[nu + a];
    }
  }
  PetscCall(VecDestroy(&places));
  PetscFunctionReturn(0);
}
} // namespace poroseam
