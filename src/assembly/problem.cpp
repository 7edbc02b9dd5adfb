#include "poroseam/problem.hpp"

#include "cell_kernel.hpp"

#include "poroseam/biot.hpp"
#include "poroseam/closure_cache.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/elastic.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"

#include <cmath>
#include <petscsf.h>
#include <sstream>

namespace poroseam {
namespace {

/// Cell size h for the stabilisation. Tensor cells: the edge of the square or cube of the same
/// volume, the element length of Aguilar et al.'s 1D analysis, where factor 1/4 is optimal.
/// Simplices: sqrt(2) times the edge of the square or cube they are cut from, i.e. twice the
/// beta of a tensor cell. Measured on the first undrained step of Terzaghi's column
/// (tests/verification/stability.py): with the tensor value, triangles overshoot to 1.08 q and
/// tetrahedra to 1.14 q; with twice it, 1.0002 q and 1.0009 q.
double cellSize(const ReferenceElement &e, double volume)
{
  const double factorial = e.dim == 2 ? 2.0 : e.dim == 3 ? 6.0 : 1.0;
  if (!e.simplex) return std::pow(volume, 1.0 / e.dim);
  return std::sqrt(2.0) * std::pow(factorial * volume, 1.0 / e.dim);
}

} // namespace

PetscErrorCode Problem::elementIndex(DMPolytopeType type, int *index)
{
  PetscFunctionBeginUser;
  auto it = element_of_type_.find((int)type);
  if (it == element_of_type_.end()) {
    ReferenceElement e;
    PetscCall(ReferenceElement::create(type, &e));
    elements_.push_back(e);
    it = element_of_type_.emplace((int)type, (int)elements_.size() - 1).first;
  }
  *index = it->second;
  PetscFunctionReturn(0);
}

double Problem::gravityVector(int d) const
{
  return d == dim_ - 1 ? -scene_->gravity : 0.0;
}

double Problem::initialPressure(const double x[]) const
{
  if (scene_->gravity <= 0.0) return 0.0;
  return scene_->fluid_density * scene_->gravity * (scene_->water_level - x[dim_ - 1]);
}

void Problem::initialStress(const double x[], int region, double stress[3][3]) const
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      stress[i][j] = 0.0;
  const Region &r = scene_->regions[region];
  if (!scene_->geostatic || !r.porous()) return;
  // K0 state: sigma'_v = -gamma' depth below the surface, sigma'_h = K0 sigma'_v.
  const double rho_sat =
      physics::saturatedDensity(r.porosity, r.solid_density, scene_->fluid_density);
  const double buoyant = (rho_sat - scene_->fluid_density) * scene_->gravity;
  const double depth = std::max(0.0, scene_->surface_elevation - x[dim_ - 1]);
  const double vertical = -buoyant * depth;
  for (int i = 0; i < 3; ++i)
    stress[i][i] = r.k0 * vertical;
  stress[dim_ - 1][dim_ - 1] = vertical;
}

double Problem::loadFactor(double t) const
{
  for (const auto &bc : scene_->conditions)
    if (bc.time.kind() != TimeFunction::Kind::step) return bc.time.factor(t);
  return t > 0.0 ? 1.0 : 0.0;
}

PetscErrorCode Problem::setup(DM dm, const Scene &scene)
{
  MPI_Comm comm;
  PetscFunctionBeginUser;
  dm_ = dm;
  scene_ = &scene;
  dim_ = scene.dim;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  cells_.clear();
  faces_.clear();
  constrained_.clear();

  DMLabel cellSets;
  PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
  Vec coords;
  PetscSection csec;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  std::string error;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (isCohesive(ct)) continue; // interfaces: InterfaceAssembly
    PetscInt tag = -1;
    if (cellSets) PetscCall(DMLabelGetValue(cellSets, c, &tag));
    const int region = scene.regionIndexOfTag((int)tag);
    if (region < 0) {
      std::ostringstream msg;
      msg << "cell " << c << " belongs to no region listed in -regions (its Gmsh physical tag is "
          << tag << "); every cell of the mesh needs a region with a material";
      error = msg.str();
      break;
    }
    BulkCell bc{c, region, 0, 0.0};
    PetscCall(elementIndex(ct, &bc.element));
    const ReferenceElement &e = elements_[bc.element];
    PetscScalar *x = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, csec, coords, c, &n, &x));
    double volume = 0.0;
    PointGeometry g;
    for (int q = 0; q < e.num_quadrature; ++q) {
      mapQuadraturePoint(e, x, q, g);
      volume += g.weight;
    }
    PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, c, &n, &x));
    bc.size = cellSize(e, volume);
    cells_.push_back(bc);
  }
  if (scene.axisymmetric && error.empty()) {
    // x is the radius: the mesh must lie on one side of the axis x = 0.
    const PetscScalar *xa;
    PetscInt nx;
    PetscCall(VecGetLocalSize(coords, &nx));
    PetscCall(VecGetArrayRead(coords, &xa));
    for (PetscInt k = 0; k < nx && error.empty(); k += dim_)
      if (xa[k] < -1e-12) {
        std::ostringstream msg;
        msg << "-axisymmetric: the mesh has a vertex at x = " << xa[k]
            << " < 0; x is the radius, the axis is x = 0";
        error = msg.str();
      }
    PetscCall(VecRestoreArrayRead(coords, &xa));
  }
  PetscCall(checkOnAllRanks(comm, error));
  {
    std::vector<PetscInt> points;
    points.reserve(cells_.size());
    for (const auto &cell : cells_)
      points.push_back(cell.cell);
    PetscCall(closures_.setup(dm, points));
  }
  {
    double local[3] = {0.0, 0.0, 0.0}, global[3]; // sum h, count, max modulus (porous cells)
    // Porous regions set the scale; with none (interface flow between solid bodies), all do.
    const bool any_porous = scene.hasPressure();
    for (const auto &cell : cells_) {
      const Region &r = scene.regions[cell.region];
      if (any_porous && !r.porous()) continue;
      local[0] += cell.size;
      local[1] += 1.0;
      local[2] = std::max(local[2], physics::lameFromYoung(r.young, r.poisson).constrained());
    }
    PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&local[2], &global[2], 1, MPI_DOUBLE, MPI_MAX, comm));
    mass_balance_scale_ = global[1] > 0.0 ? global[2] / (global[0] / global[1]) : 1.0;
  }
  PetscCall(interfaces_.setup(
      dm, scene,
      [this](const double x[], int tag, double s0[3][3]) {
        initialStress(x, scene_->regionIndexOfTag(tag), s0);
      },
      [this](const double x[]) { return initialPressure(x); }));

  // Faces carrying tractions or fluxes: integrated once, by the rank that owns the face.
  PetscSF sf;
  PetscInt nleaves;
  const PetscInt *leaves;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  std::vector<char> ghost(pEnd - pStart, 0);
  for (PetscInt i = 0; i < (nleaves > 0 ? nleaves : 0); ++i)
    ghost[(leaves ? leaves[i] : i) - pStart] = 1;
  DMLabel faceSets;
  PetscCall(DMGetLabel(dm, "Face Sets", &faceSets));
  for (size_t i = 0; i < scene.conditions.size(); ++i) {
    const auto &bc = scene.conditions[i];
    if (bc.dirichlet() || !faceSets) continue;
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
      PetscCall(DMPlexGetCellType(dm, idx[k], &ct));
      LoadedFace f{idx[k], (int)i, 0};
      PetscCall(elementIndex(ct, &f.element));
      faces_.push_back(f);
    }
    PetscCall(ISRestoreIndices(faces, &idx));
    PetscCall(ISDestroy(&faces));
  }

  // Local offsets of constrained dofs and the condition that sets each.
  PetscSection s;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscInt numFields;
  PetscCall(PetscSectionGetNumFields(s, &numFields));
  for (size_t i = 0; i < scene.conditions.size(); ++i) {
    const auto &bc = scene.conditions[i];
    if (!bc.dirichlet()) continue;
    DMLabel label;
    PetscCall(DMGetLabel(dm, boundaryLabelName(bc.boundary).c_str(), &label));
    if (bc.kind == BcKind::interface_pressure) {
      std::vector<PetscInt> edges;
      PetscCall(lateralEdgesOnBoundary(dm, bc.boundary, edges));
      for (PetscInt e : edges) {
        PetscInt dof = 0, off = 0;
        PetscCall(PetscSectionGetFieldDof(s, e, kInterfacePressureField, &dof));
        if (!dof) continue;
        PetscCall(PetscSectionGetFieldOffset(s, e, kInterfacePressureField, &off));
        constrained_.push_back({off, (int)i});
      }
      continue;
    }
    IS points = nullptr;
    PetscCall(DMLabelGetStratumIS(label, 1, &points));
    if (!points) continue;
    const PetscInt *idx;
    PetscInt n;
    PetscCall(ISGetLocalSize(points, &n));
    PetscCall(ISGetIndices(points, &idx));
    const int field = bc.kind == BcKind::pressure ? kPressureField : kDisplacementField;
    for (PetscInt k = 0; k < n; ++k) {
      PetscInt dof = 0, off = 0;
      if (field >= numFields) continue;
      PetscCall(PetscSectionGetFieldDof(s, idx[k], field, &dof));
      if (!dof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, idx[k], field, &off));
      constrained_.push_back({off + (field == kDisplacementField ? bc.component : 0), (int)i});
    }
    PetscCall(ISRestoreIndices(points, &idx));
    PetscCall(ISDestroy(&points));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::initialState(Vec local) const
{
  PetscSection s, csec;
  Vec coords;
  const PetscScalar *x;
  PetscScalar *u;
  PetscInt vStart, vEnd, numFields;
  PetscFunctionBeginUser;
  PetscCall(VecSet(local, 0.0));
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(PetscSectionGetNumFields(s, &numFields));
  if (numFields <= kPressureField) PetscFunctionReturn(0);
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &vStart, &vEnd));
  PetscCall(VecGetArrayRead(coords, &x));
  PetscCall(VecGetArray(local, &u));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt dof, off, coff;
    PetscCall(PetscSectionGetFieldDof(s, v, kPressureField, &dof));
    if (!dof) continue;
    PetscCall(PetscSectionGetFieldOffset(s, v, kPressureField, &off));
    PetscCall(PetscSectionGetOffset(csec, v, &coff));
    u[off] = initialPressure(&x[coff]);
  }
  if (numFields > kInterfacePressureField) {
    // p3 starts hydrostatic too, at the position of its lateral edge's vertices.
    PetscInt eStart, eEnd;
    PetscCall(DMPlexGetDepthStratum(dm_, 1, &eStart, &eEnd));
    for (PetscInt e = eStart; e < eEnd; ++e) {
      PetscInt dof, off, coff;
      PetscCall(PetscSectionGetFieldDof(s, e, kInterfacePressureField, &dof));
      if (!dof) continue;
      const PetscInt *cone;
      PetscCall(DMPlexGetCone(dm_, e, &cone));
      PetscCall(PetscSectionGetFieldOffset(s, e, kInterfacePressureField, &off));
      PetscCall(PetscSectionGetOffset(csec, cone[0], &coff));
      u[off] = initialPressure(&x[coff]);
    }
  }
  PetscCall(VecRestoreArray(local, &u));
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::insertBoundaryValues(double t, Vec local) const
{
  PetscScalar *u;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(local, &u));
  for (const auto &c : constrained_) {
    const auto &bc = scene_->conditions[c.condition];
    u[c.offset] = bc.value[0] * bc.time.factor(t);
  }
  PetscCall(VecRestoreArray(local, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::insertBoundaryRates(double t, const RateStencil &stencil,
                                            Vec local_rate) const
{
  PetscScalar *rate;
  const PetscScalar *state[2] = {nullptr, nullptr};
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(local_rate, &rate));
  for (int k = 0; k < stencil.count; ++k)
    PetscCall(VecGetArrayRead(stencil.state[k], &state[k]));
  for (const auto &c : constrained_) {
    const auto &bc = scene_->conditions[c.condition];
    double r = stencil.now * bc.value[0] * bc.time.factor(t);
    for (int k = 0; k < stencil.count; ++k)
      r += stencil.weight[k] * state[k][c.offset];
    rate[c.offset] = r;
  }
  for (int k = 0; k < stencil.count; ++k)
    PetscCall(VecRestoreArrayRead(stencil.state[k], &state[k]));
  PetscCall(VecRestoreArray(local_rate, &rate));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::residual(double t, Vec local, Vec local_rate, const ResidualMode &mode,
                                 Vec f) const
{
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(events_.residual));
  PetscCall(assembleResidual(t, local, local_rate, mode, f));
  PetscCall(endLogEvent(events_.residual));
  PetscFunctionReturn(0);
}

void Problem::cellTerms(size_t i, const PetscScalar *u, const PetscScalar *u_t,
                        const PetscScalar *coords, double mass_scale, double shift,
                        bool with_jacobian, CellWork &w) const
{
  const BulkCell &cell = cells_[i];
  const CellMaterial m = materialOf(*scene_, scene_->regions[cell.region], cell.size);
  const int n = closures_.closureSize(i), nc = closures_.coordinateSize(i);
  w.x.resize(n), w.xdot.resize(n), w.xc.resize(nc);
  gatherClosure(u, closures_.local(i), n, w.x.data());
  gatherClosure(u_t, closures_.local(i), n, w.xdot.data());
  gatherClosure(coords, closures_.coordinates(i), nc, w.xc.data());
  w.F.assign(n, 0.0);
  if (with_jacobian) w.K.assign((size_t)n * n, 0.0);
  CellKernel kernel{
      elements_[cell.element], dim_, m, scene_->hasPressure() && m.porous, mass_scale, {0, 0, 0},
      scene_->axisymmetric};
  for (int d = 0; d < dim_; ++d)
    kernel.gravity[d] = gravityVector(d);
  kernel(
      w.xc.data(), w.x.data(), w.xdot.data(), n,
      [&](const double *p, double s0[3][3]) { initialStress(p, cell.region, s0); },
      [&](const double *p) { return initialPressure(p); }, w.F.data(), shift,
      with_jacobian ? w.K.data() : nullptr);
}

PetscErrorCode Problem::assembleResidual(double t, Vec local, Vec local_rate,
                                         const ResidualMode &mode, Vec f) const
{
  PetscSection s, csec;
  Vec coords;
  PetscFunctionBeginUser;
  PetscCall(VecSet(f, 0.0));
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  CellWork work;
  {
    // Closures through the cache (closure_cache.hpp), read from and added to the local arrays:
    // the same values and additions, in the same order, as DMPlexVec{Get,Set}Closure.
    const PetscScalar *ua, *ra, *ca;
    PetscScalar *fa;
    PetscCall(VecGetArrayRead(local, &ua));
    PetscCall(VecGetArrayRead(local_rate, &ra));
    PetscCall(VecGetArrayRead(coords, &ca));
    PetscCall(VecGetArray(f, &fa));
    for (size_t i = 0; i < cells_.size(); ++i) {
      cellTerms(i, ua, ra, ca, mode.mass_scale, 0.0, false, work);
      // All entries, constrained dofs included: they are the reactions (ADD_ALL_VALUES).
      addClosure(work.F.data(), closures_.local(i), closures_.closureSize(i), fa);
    }
    PetscCall(VecRestoreArray(f, &fa));
    PetscCall(VecRestoreArrayRead(coords, &ca));
    PetscCall(VecRestoreArrayRead(local_rate, &ra));
    PetscCall(VecRestoreArrayRead(local, &ua));
  }
  PetscCall(beginLogEvent(events_.interface_residual));
  PetscCall(interfaces_.residual(local, InterfaceRates{local_rate, mode.dt}, mode.mass_scale, f));
  PetscCall(endLogEvent(events_.interface_residual));
  if (!mode.include_loads) PetscFunctionReturn(0);
  // Natural conditions: R_u -= int t . v, R_p += s int psi q_n.
  std::vector<double> F;
  for (const auto &face : faces_) {
    const auto &bc = scene_->conditions[face.condition];
    const ReferenceElement &e = elements_[face.element];
    const double factor = bc.time.factor(t);
    PetscScalar *xc = nullptr;
    PetscInt nc = 0, n = 0;
    PetscCall(DMPlexVecGetClosure(dm_, csec, coords, face.face, &nc, &xc));
    PetscScalar *x = nullptr;
    PetscCall(DMPlexVecGetClosure(dm_, s, local, face.face, &n, &x));
    F.assign(n, 0.0);
    const int nv = e.num_vertices, nu = nv * dim_;
    const int np = (int)n - nu;
    for (int q = 0; q < e.num_quadrature; ++q) {
      const double *phi = &e.basis[q * nv];
      double w = surfaceWeight(e, xc, dim_, q);
      if (scene_->axisymmetric) {
        double r = 0.0;
        for (int a = 0; a < nv; ++a)
          r += phi[a] * xc[a * dim_];
        w *= 2.0 * M_PI * r;
      }
      for (int a = 0; a < nv; ++a) {
        if (bc.kind == BcKind::traction)
          for (int i = 0; i < dim_; ++i)
            F[a * dim_ + i] -= w * phi[a] * bc.value[i] * factor;
        else if (bc.kind == BcKind::flux && np == nv)
          F[nu + a] += mode.mass_scale * w * phi[a] * bc.value[0] * factor;
      }
    }
    PetscCall(DMPlexVecRestoreClosure(dm_, s, local, face.face, &n, &x));
    PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, face.face, &nc, &xc));
    PetscCall(DMPlexVecSetClosure(dm_, s, f, face.face, F.data(), ADD_ALL_VALUES));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::jacobian(double t, double shift, Vec local, Vec local_rate,
                                 const ResidualMode &mode, Mat J) const
{
  const double mass_scale = mode.mass_scale;
  Vec coords;
  const PetscScalar *ua, *ra, *ca;
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(events_.jacobian));
  PetscCall(MatZeroEntries(J));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  CellWork work;
  std::vector<PetscInt> rows;
  // Closures and matrix indices through the cache (closure_cache.hpp); one MatSetValues per
  // cell with the indices DMPlexMatSetClosure would compute (constrained dofs negative).
  PetscCall(VecGetArrayRead(local, &ua));
  PetscCall(VecGetArrayRead(local_rate, &ra));
  PetscCall(VecGetArrayRead(coords, &ca));
  for (size_t i = 0; i < cells_.size(); ++i) {
    cellTerms(i, ua, ra, ca, mass_scale, shift, true, work);
    const int n = closures_.closureSize(i);
    rows.resize(n);
    closures_.globalIndices(i, rows.data());
    PetscCall(MatSetValues(J, n, rows.data(), n, rows.data(), work.K.data(), ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(VecRestoreArrayRead(local_rate, &ra));
  PetscCall(VecRestoreArrayRead(local, &ua));
  PetscCall(beginLogEvent(events_.interface_jacobian));
  PetscCall(interfaces_.jacobian(local, InterfaceRates{local_rate, mode.dt}, shift, mass_scale, J));
  PetscCall(endLogEvent(events_.interface_jacobian));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscCall(endLogEvent(events_.jacobian));
  PetscFunctionReturn(0);
}

} // namespace poroseam
