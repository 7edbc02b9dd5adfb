// The problem's set-up: the bulk cells and their reference elements, the closure cache, the
// geostatic column and its checks, the loaded faces (tractions, fluxes, water load) and the
// constrained dofs. Part of Problem (problem.hpp); the states are in problem_state.cpp, the
// assembly in problem_assembly.cpp.
#include "poroseam/problem.hpp"

#include "cell_kernel.hpp"

#include "poroseam/biot.hpp"
#include "poroseam/closure_cache.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/curved_nodes.hpp"
#include "poroseam/elastic.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/mesh_points.hpp"

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
    // Bulk cells and their boundary faces carry the scene's displacement order.
    ReferenceElement e;
    PetscCall(ReferenceElement::create(type, &e, scene_->displacement_order));
    elements_.push_back(e);
    it = element_of_type_.emplace((int)type, (int)elements_.size() - 1).first;
  }
  *index = it->second;
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::setupGeostatic(MPI_Comm comm, const std::vector<double> &bottom,
                                       const std::vector<double> &top)
{
  const Scene &scene = *scene_;
  PetscFunctionBeginUser;
  std::vector<double> lo(bottom.size()), hi(top.size());
  PetscCallMPI(MPI_Allreduce(bottom.data(), lo.data(), (int)lo.size(), MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(top.data(), hi.data(), (int)hi.size(), MPI_DOUBLE, MPI_MAX, comm));
  std::vector<physics::GroundRegion> ground;
  double lowest = scene.surface_elevation;
  for (size_t i = 0; i < scene.regions.size(); ++i) {
    const Region &r = scene.regions[i];
    if (!r.inGround() || lo[i] > hi[i]) continue; // a structure, or a region with no cells
    physics::GroundRegion g;
    g.name = r.name;
    g.bottom = lo[i];
    g.top = hi[i];
    // The density the cell kernel weighs the region with.
    g.density = r.porous()
                    ? physics::saturatedDensity(r.porosity, r.solid_density, scene.fluid_density)
                    : r.solid_density;
    g.k0 = r.k0;
    g.k0_origin = r.k0_origin;
    g.alpha = r.porous() ? r.biot_coefficient : 0.0;
    ground.push_back(g);
    lowest = std::min(lowest, g.bottom);
  }
  // Elevations of one mesh closer than this are the same (Gmsh writes ~16 digits).
  const double tolerance = 1e-9 * std::max(1.0, scene.surface_elevation - lowest);
  std::string error =
      physics::buildGeostaticLayers(ground, scene.surface_elevation, tolerance, column_.layers);

  // A ground face on the outer boundary that faces upwards is part of the ground surface: it
  // must lie on the plane z = z_s, or the column above its points is not what the layers say
  // (a slope, a step, an excavation).
  // Outer boundary faces: one bulk cell in their support on this rank and on no other (the
  // point SF: not a leaf, and no other rank's leaf points to it).
  PetscSF sf;
  PetscInt nroots, nleaves, pStart, pEnd, fStart, fEnd;
  const PetscInt *leaves, *degree = nullptr;
  PetscCall(DMGetPointSF(dm_, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &leaves, nullptr));
  PetscCall(DMPlexGetChart(dm_, &pStart, &pEnd));
  std::vector<char> shared(pEnd - pStart, 0);
  for (PetscInt i = 0; i < (nleaves > 0 ? nleaves : 0); ++i)
    shared[(leaves ? leaves[i] : i) - pStart] = 1;
  if (nroots >= 0) {
    PetscCall(PetscSFComputeDegreeBegin(sf, &degree));
    PetscCall(PetscSFComputeDegreeEnd(sf, &degree));
    for (PetscInt p = 0; p < nroots; ++p)
      if (degree[p] > 0) shared[p] = 1;
  }
  DMLabel cellSets;
  PetscCall(DMGetLabel(dm_, "Cell Sets", &cellSets));
  Vec coords;
  PetscSection csec;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  PetscCall(DMPlexGetHeightStratum(dm_, 1, &fStart, &fEnd));
  for (PetscInt f = fStart; f < fEnd && error.empty(); ++f) {
    const PetscInt *support;
    PetscInt ns, tag = -1;
    DMPolytopeType ct;
    PetscCall(DMPlexGetSupportSize(dm_, f, &ns));
    if (ns != 1 || shared[f - pStart]) continue;
    PetscCall(DMPlexGetSupport(dm_, f, &support));
    PetscCall(DMPlexGetCellType(dm_, support[0], &ct));
    if (isCohesive(ct)) continue; // a lateral face of an interface
    if (cellSets) PetscCall(DMLabelGetValue(cellSets, support[0], &tag));
    const int region = scene.regionIndexOfTag((int)tag);
    if (region < 0 || !scene.regions[region].inGround()) continue;
    double normal[3];
    PetscCall(outwardNormal(f, support[0], normal));
    if (normal[dim_ - 1] < 1e-6) continue; // vertical or downward: not the surface
    PetscScalar *x = nullptr;
    PetscInt nx = 0;
    PetscCall(DMPlexVecGetClosure(dm_, csec, coords, f, &nx, &x));
    for (PetscInt a = dim_ - 1; a < nx; a += dim_)
      if (std::abs(x[a] - scene.surface_elevation) > tolerance && error.empty()) {
        std::ostringstream msg;
        msg << "region '" << scene.regions[region].name
            << "' has an upward-facing outer boundary face at z = " << x[a]
            << ", not on the soil surface " << scene.surface_elevation
            << " (-surface_elevation): the geostatic state is exact only for a horizontal "
               "ground surface";
        error = msg.str();
      }
    PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, f, &nx, &x));
  }
  PetscCall(checkOnAllRanks(comm, error.empty() ? error : "-initial_state geostatic: " + error));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::outwardNormal(PetscInt face, PetscInt cell, double normal[3]) const
{
  Vec coords;
  PetscSection csec;
  PetscScalar *xf = nullptr, *xc = nullptr;
  PetscInt nf = 0, nc = 0;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  PetscCall(DMPlexVecGetClosure(dm_, csec, coords, face, &nf, &xf));
  PetscCall(DMPlexVecGetClosure(dm_, csec, coords, cell, &nc, &xc));
  std::vector<double> x(3 * (nf / dim_), 0.0);
  for (PetscInt a = 0; a < nf / dim_; ++a)
    for (int d = 0; d < dim_; ++d)
      x[a * dim_ + d] = xf[a * dim_ + d];
  faceNormal(x.data(), (int)(nf / dim_), dim_, normal);
  // Orientation: from the cell's centroid to the face's (the cell is convex).
  double out = 0.0, length = 0.0;
  for (int d = 0; d < dim_; ++d) {
    double cf = 0.0, cc = 0.0;
    for (PetscInt a = 0; a < nf / dim_; ++a)
      cf += xf[a * dim_ + d] / (double)(nf / dim_);
    for (PetscInt a = 0; a < nc / dim_; ++a)
      cc += xc[a * dim_ + d] / (double)(nc / dim_);
    out += normal[d] * (cf - cc);
    length += normal[d] * normal[d];
  }
  length = std::sqrt(length);
  for (int d = 0; d < 3; ++d)
    normal[d] = d < dim_ ? (out < 0.0 ? -normal[d] : normal[d]) / length : 0.0;
  PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, cell, &nc, &xc));
  PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, face, &nf, &xf));
  PetscFunctionReturn(0);
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
  skeleton_committed_.clear();
  laws_.clear();
  for (const Region &r : scene.regions)
    laws_.push_back(skeletonLawOf(r));
  any_skeleton_history_ =
      std::any_of(laws_.begin(), laws_.end(), [](const SkeletonLaw &l) { return l.hasHistory(); });
  column_ = physics::GeostaticColumn{
      scene.surface_elevation, scene.water_level, scene.fluid_density, scene.gravity, {}};
  // Vertical extent of each region's cells on this rank (for the geostatic column).
  std::vector<double> bottom(scene.regions.size(), 1e300), top(scene.regions.size(), -1e300);

  DMLabel cellSets;
  PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
  Vec coords;
  PetscSection csec;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  std::string error;
  PointGeometry g;
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
    for (PetscInt a = dim_ - 1; a < n; a += dim_) {
      bottom[region] = std::min(bottom[region], (double)x[a]);
      top[region] = std::max(top[region], (double)x[a]);
    }
    double volume = 0.0;
    for (int q = 0; q < e.num_quadrature; ++q) {
      mapQuadraturePoint(e, x, q, g);
      volume += g.weight;
    }
    PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, c, &n, &x));
    bc.size = cellSize(e, volume);
    // Integration-point history only for laws that have one: a scene without them
    // allocates nothing.
    if (laws_[region].hasHistory()) {
      bc.history = skeleton_committed_.size();
      skeleton_committed_.resize(skeleton_committed_.size() + e.num_quadrature);
    }
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
  if (scene.geostatic) PetscCall(setupGeostatic(comm, bottom, top));
  {
    std::vector<PetscInt> points;
    points.reserve(cells_.size());
    for (const auto &cell : cells_)
      points.push_back(cell.cell);
    PetscCall(closures_.setup(dm, points));
  }
  node_places_.clear();
  if (curvedNodes(dm)) {
    PetscCall(displacementNodePlaces(dm, node_places_));
    // A curved cell can fold where its straight-sided one does not (a coarse cell on a tight
    // curve): its Jacobian must stay positive at every integration point.
    const PetscScalar *ca;
    std::vector<double> xg;
    PetscCall(VecGetArrayRead(coords, &ca));
    for (size_t i = 0; i < cells_.size() && error.empty(); ++i) {
      const ReferenceElement &e = elements_[cells_[i].element];
      cellGeometry(i, ca, xg);
      for (int q = 0; q < e.num_quadrature; ++q) {
        if (mapQuadraturePoint(e, xg.data(), q, g, true) > 0.0) continue;
        std::ostringstream msg;
        msg << "-mesh_geometry_order 2: the curved " << DMPolytopeTypes[e.type] << " cell "
            << cells_[i].cell << " near (" << g.x[0] << ", " << g.x[1] << ", "
            << (dim_ == 3 ? g.x[2] : 0.0)
            << ") folds (non-positive Jacobian determinant at an integration point): the "
               "cell is too coarse for its curve, or its second-order nodes are misplaced; "
               "refine the mesh there, or use -mesh_geometry_order 1";
        error = msg.str();
        break;
      }
    }
    PetscCall(VecRestoreArrayRead(coords, &ca));
    PetscCall(checkOnAllRanks(comm, error));
  }
  if (any_skeleton_history_) PetscCall(checkInitialYield(comm));
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
        initialTotalStress(x, scene_->regionIndexOfTag(tag), s0);
      },
      [this](const double x[]) { return initialPressure(x); }));

  PetscCall(setupLoadedFaces());

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

} // namespace poroseam
