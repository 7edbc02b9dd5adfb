// The problem's bulk cells (split from Problem::setup, problem.cpp): which cells of this rank
// are bulk cells and of which region, their reference elements, their sizes for the
// stabilisation and their history slots, their closures, and the checks of their geometry
// (the axis of an axisymmetric mesh, curved cells that fold). Part of Problem (problem.hpp).
#include "poroseam/problem.hpp"

#include "poroseam/closure_cache.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/curved_nodes.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/mesh_points.hpp"

#include <algorithm>
#include <cmath>
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

PetscErrorCode Problem::collectBulkCells(std::vector<double> &bottom, std::vector<double> &top,
                                         std::string *error)
{
  const Scene &scene = *scene_;
  PetscFunctionBeginUser;
  DMLabel cellSets;
  PetscCall(DMGetLabel(dm_, "Cell Sets", &cellSets));
  Vec coords;
  PetscSection csec;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm_, 0, &cStart, &cEnd));
  PointGeometry g;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm_, c, &ct));
    if (isCohesive(ct)) continue; // interfaces: InterfaceAssembly
    PetscInt tag = -1;
    if (cellSets) PetscCall(DMLabelGetValue(cellSets, c, &tag));
    const int region = scene.regionIndexOfTag((int)tag);
    if (region < 0) {
      std::ostringstream msg;
      msg << "cell " << c << " belongs to no region listed in -regions (its Gmsh physical tag is "
          << tag << "); every cell of the mesh needs a region with a material";
      *error = msg.str();
      break;
    }
    BulkCell bc{c, region, 0, 0.0};
    PetscCall(elementIndex(ct, &bc.element));
    const ReferenceElement &e = elements_[bc.element];
    PetscScalar *x = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm_, csec, coords, c, &n, &x));
    for (PetscInt a = dim_ - 1; a < n; a += dim_) {
      bottom[region] = std::min(bottom[region], (double)x[a]);
      top[region] = std::max(top[region], (double)x[a]);
    }
    double volume = 0.0;
    for (int q = 0; q < e.num_quadrature; ++q) {
      mapQuadraturePoint(e, x, q, g);
      volume += g.weight;
    }
    PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, c, &n, &x));
    bc.size = cellSize(e, volume);
    // Integration-point history only for laws that have one: a scene without them
    // allocates nothing.
    if (laws_[region].hasHistory()) {
      bc.history = skeleton_committed_.size();
      skeleton_committed_.resize(skeleton_committed_.size() + e.num_quadrature);
    }
    cells_.push_back(bc);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::checkAxisymmetricMesh(std::string *error) const
{
  // x is the radius: the mesh must lie on one side of the axis x = 0.
  Vec coords;
  const PetscScalar *xa;
  PetscInt nx;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(VecGetLocalSize(coords, &nx));
  PetscCall(VecGetArrayRead(coords, &xa));
  for (PetscInt k = 0; k < nx && error->empty(); k += dim_)
    if (xa[k] < -1e-12) {
      std::ostringstream msg;
      msg << "-axisymmetric: the mesh has a vertex at x = " << xa[k]
          << " < 0; x is the radius, the axis is x = 0";
      *error = msg.str();
    }
  PetscCall(VecRestoreArrayRead(coords, &xa));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::setupClosures()
{
  std::vector<PetscInt> points;
  PetscFunctionBeginUser;
  points.reserve(cells_.size());
  for (const auto &cell : cells_)
    points.push_back(cell.cell);
  PetscCall(closures_.setup(dm_, points));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::setupCurvedCells(MPI_Comm comm)
{
  PetscFunctionBeginUser;
  node_places_.clear();
  if (!curvedNodes(dm_)) PetscFunctionReturn(0);
  PetscCall(displacementNodePlaces(dm_, node_places_));
  // A curved cell can fold where its straight-sided one does not (a coarse cell on a tight
  // curve): its Jacobian must stay positive at every integration point.
  Vec coords;
  const PetscScalar *ca;
  std::vector<double> xg;
  PointGeometry g;
  std::string error;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
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
  PetscFunctionReturn(0);
}

} // namespace poroseam
