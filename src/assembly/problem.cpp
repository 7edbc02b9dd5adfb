// The problem's set-up (Problem::setup) as the sequence of its steps: the bulk cells and their
// checks (problem_cells.cpp), the geostatic column and its checks (here), the curved cells, the
// mass-balance scale, the interfaces, the loaded faces (boundary_loads.cpp) and the constrained
// dofs (constrained_dofs.cpp). Part of Problem (problem.hpp); the states are in
// problem_state.cpp, the assembly in problem_assembly.cpp.
#include "poroseam/problem.hpp"

#include "poroseam/biot.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/elastic.hpp"
#include "poroseam/interfaces.hpp"

#include <algorithm>
#include <cmath>
#include <petscsf.h>
#include <sstream>

namespace poroseam {

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

/// The order of the steps matters: the cells' regions and extents before the geostatic column,
/// the closures before the curved cells' check (cellGeometry reads them), the geostatic column
/// before the yield check and the interfaces' initial contact (both read the initial state).
PetscErrorCode Problem::setup(DM dm, const Scene &scene)
{
  MPI_Comm comm;
  PetscFunctionBeginUser;
  takeScene(dm, scene);
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  // Vertical extent of each region's cells on this rank (for the geostatic column).
  std::vector<double> bottom(scene.regions.size(), 1e300), top(scene.regions.size(), -1e300);
  std::string error;
  PetscCall(collectBulkCells(bottom, top, &error));
  if (scene.axisymmetric && error.empty()) PetscCall(checkAxisymmetricMesh(&error));
  PetscCall(checkOnAllRanks(comm, error));
  if (scene.geostatic) PetscCall(setupGeostatic(comm, bottom, top));
  PetscCall(setupClosures());
  PetscCall(setupCurvedCells(comm));
  if (any_skeleton_history_) PetscCall(checkInitialYield(comm));
  PetscCall(setupMassBalanceScale(comm));
  PetscCall(interfaces_.setup(
      dm, scene,
      [this](const double x[], int tag, double s0[3][3]) {
        initialTotalStress(x, scene_->regionIndexOfTag(tag), s0);
      },
      [this](const double x[]) { return initialPressure(x); }));
  PetscCall(setupLoadedFaces());
  PetscCall(collectConstrainedDofs());
  PetscFunctionReturn(0);
}

void Problem::takeScene(DM dm, const Scene &scene)
{
  dm_ = dm;
  scene_ = &scene;
  dim_ = scene.dim;
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
}

PetscErrorCode Problem::setupMassBalanceScale(MPI_Comm comm)
{
  const Scene &scene = *scene_;
  double local[3] = {0.0, 0.0, 0.0}, global[3]; // sum h, count, max modulus (porous cells)
  PetscFunctionBeginUser;
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
  PetscFunctionReturn(0);
}

} // namespace poroseam
