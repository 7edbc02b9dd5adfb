// The set-up warning of docs/interface_parameters.md: an interface penalty far outside the
// range its mesh and materials call for (too soft: visible overlap and a softer structure;
// too stiff: conditioning). One line per interface and stiffness, from rank 0.
#include "poroseam/penalty_check.hpp"

#include "poroseam/curved_nodes.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/mesh_points.hpp"
#include "poroseam/penalty_advice.hpp"
#include "poroseam/reference_element.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <petscdmplex.h>
#include <vector>

namespace poroseam {
namespace {

/// The worst face of one interface for one stiffness: the smallest K h / E_soft and the
/// largest K h / E_stiff, with the h and E that gave them (for the message).
struct Extremes {
  double soft_ratio = std::numeric_limits<double>::infinity();
  double soft_h = 0.0, soft_E = 0.0;
  double stiff_ratio = 0.0;
  double stiff_h = 0.0, stiff_E = 0.0, stiff_E_soft = 0.0; ///< E_soft: for the advised range
};

/// Measure of a curved cell or face (-mesh_geometry_order 2): its quadrature through the
/// isoparametric map of its nodes. A node's place is found in the table by the place its
/// straight-sided point would have (the vertex basis at the node's reference point: the mean
/// of the vertices it lies between), so the element's own node numbering is all it needs.
/// `space`: the coordinate dimension (a face is one dimension lower).
PetscErrorCode curvedMeasure(DM dm, const CurvedNodes &nodes, PetscInt point, int space,
                             std::map<DMPolytopeType, ReferenceElement> &elements, double *measure)
{
  DMPolytopeType type;
  PetscSection csec;
  Vec coords;
  const PetscScalar *ca;
  std::vector<PetscInt> vertices;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetCellType(dm, point, &type));
  if (!elements.count(type)) PetscCall(ReferenceElement::create(type, &elements[type], 2));
  const ReferenceElement &e = elements[type];
  PetscCall(closureVertices(dm, point, vertices));
  PetscCheck((int)vertices.size() == e.num_vertices, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "penalty check: point %" PetscInt_FMT " has %zu vertices, its element %d", point,
             vertices.size(), e.num_vertices);
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(VecGetArrayRead(coords, &ca));
  std::vector<double> xv(e.num_vertices * space), xn(e.num_nodes * space), phi(e.num_vertices);
  for (int a = 0; a < e.num_vertices; ++a) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(csec, vertices[a], &off));
    for (int d = 0; d < space; ++d)
      xv[a * space + d] = PetscRealPart(ca[off + d]);
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  for (int a = 0; a < e.num_nodes; ++a) {
    e.evaluate(&e.node_coords[a * e.dim], phi.data(), nullptr);
    double straight[3] = {0, 0, 0}, curved[3] = {0, 0, 0};
    int corners = 0;
    for (int v = 0; v < e.num_vertices; ++v) {
      if (std::fabs(phi[v]) < 1e-12) continue;
      ++corners;
      for (int d = 0; d < space; ++d)
        straight[d] += phi[v] * xv[v * space + d];
    }
    const bool found = corners == 1 || nodes.find(corners, straight, curved);
    PetscCheck(found, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "-mesh_geometry_order 2: no second-order node of mesh point %" PetscInt_FMT
               " at (%g, %g, %g)",
               point, straight[0], straight[1], straight[2]);
    for (int d = 0; d < space; ++d)
      xn[a * space + d] = corners == 1 ? straight[d] : curved[d];
  }
  *measure = 0.0;
  PointGeometry g;
  for (int q = 0; q < e.num_quadrature; ++q)
    if (e.dim == space) {
      mapQuadraturePoint(e, xn.data(), q, g, true);
      *measure += g.weight;
    } else
      *measure += surfaceWeight(e, xn.data(), space, q, true);
  PetscFunctionReturn(0);
}

/// Height of a bulk cell over one of its faces: volume / face measure, times the dimension on
/// simplices (a triangle's height is 2 A / b). Curved cells (`nodes`): both measures from the
/// curved cell and face (an annular sector of thickness t inside its arc of radius r has
/// h = t (2 r - t) / (2 r), where the straight-sided trapezoid gives cos(theta / 2) times that
/// for a sector of angle theta).
PetscErrorCode heightOver(DM dm, PetscInt cell, PetscInt face, int dim, const CurvedNodes *nodes,
                          std::map<DMPolytopeType, ReferenceElement> &elements, double *h)
{
  PetscReal volume, area, centroid[3], normal[3];
  DMPolytopeType type;
  PetscFunctionBeginUser;
  if (nodes) {
    double v, a;
    PetscCall(curvedMeasure(dm, *nodes, cell, dim, elements, &v));
    PetscCall(curvedMeasure(dm, *nodes, face, dim, elements, &a));
    volume = v, area = a;
  } else {
    PetscCall(DMPlexComputeCellGeometryFVM(dm, cell, &volume, centroid, normal));
    PetscCall(DMPlexComputeCellGeometryFVM(dm, face, &area, centroid, normal));
  }
  PetscCall(DMPlexGetCellType(dm, cell, &type));
  const bool simplex = type == DM_POLYTOPE_TRIANGLE || type == DM_POLYTOPE_TETRAHEDRON;
  *h = area > 0.0 ? (simplex ? dim : 1) * std::abs(volume) / area : 0.0;
  PetscFunctionReturn(0);
}

void account(Extremes &x, double K, double h, double E_soft, double E_stiff)
{
  if (K * h / E_soft < x.soft_ratio) x.soft_ratio = K * h / E_soft, x.soft_h = h, x.soft_E = E_soft;
  if (K * h / E_stiff > x.stiff_ratio)
    x.stiff_ratio = K * h / E_stiff, x.stiff_h = h, x.stiff_E = E_stiff, x.stiff_E_soft = E_soft;
}

/// The worst faces over all ranks: each rank's extremes, the global one chosen by MINLOC and
/// MAXLOC of the ratio, its h and E then broadcast from the rank that has it.
PetscErrorCode reduce(MPI_Comm comm, Extremes &x)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  struct {
    double value;
    int rank;
  } soft_in = {x.soft_ratio, rank}, soft_out, stiff_in = {x.stiff_ratio, rank}, stiff_out;
  PetscCallMPI(MPI_Allreduce(&soft_in, &soft_out, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm));
  PetscCallMPI(MPI_Allreduce(&stiff_in, &stiff_out, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm));
  double soft[3] = {x.soft_ratio, x.soft_h, x.soft_E};
  double stiff[4] = {x.stiff_ratio, x.stiff_h, x.stiff_E, x.stiff_E_soft};
  PetscCallMPI(MPI_Bcast(soft, 3, MPI_DOUBLE, soft_out.rank, comm));
  PetscCallMPI(MPI_Bcast(stiff, 4, MPI_DOUBLE, stiff_out.rank, comm));
  x.soft_ratio = soft[0], x.soft_h = soft[1], x.soft_E = soft[2];
  x.stiff_ratio = stiff[0], x.stiff_h = stiff[1], x.stiff_E = stiff[2], x.stiff_E_soft = stiff[3];
  PetscFunctionReturn(0);
}

PetscErrorCode warn(MPI_Comm comm, const std::string &iface, const char *name, double K,
                    const Extremes &x)
{
  // Formatted by the C library: PetscPrintf's %g writes 1e5 as "100000.".
  char line[640] = "";
  PetscFunctionBeginUser;
  if (x.soft_ratio < kPenaltyRatioSoft)
    std::snprintf(line, sizeof line,
                  "poroseam: warning: interface %s: %s = %g Pa/m is soft for its mesh: K h / E = "
                  "%.3g (h = %.4g m, E = %.3g Pa), so the faces overlap and slide elastically as "
                  "much as an element deforms; a sensible %s is 10 to 1000 E / h, here %.2g to "
                  "%.2g Pa/m (docs/interface_parameters.md)\n",
                  iface.c_str(), name, K, x.soft_ratio, x.soft_h, x.soft_E, name,
                  10 * x.soft_E / x.soft_h, 1000 * x.soft_E / x.soft_h);
  else if (x.stiff_ratio > kPenaltyRatioStiff)
    std::snprintf(line, sizeof line,
                  "poroseam: warning: interface %s: %s = %g Pa/m is stiff for its mesh: K h / E = "
                  "%.3g (h = %.4g m, E = %.3g Pa), so it dominates the conditioning (slow "
                  "iterative solves; with Gauss integration, oscillating tractions); a sensible "
                  "%s is 10 to 1000 E / h of the softer side, here %.2g to %.2g Pa/m "
                  "(docs/interface_parameters.md)\n",
                  iface.c_str(), name, K, x.stiff_ratio, x.stiff_h, x.stiff_E, name,
                  10 * x.stiff_E_soft / x.stiff_h, 1000 * x.stiff_E_soft / x.stiff_h);
  if (line[0]) PetscCall(PetscPrintf(comm, "%s", line));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode warnAboutPenalties(DM dm, const Scene &scene)
{
  MPI_Comm comm;
  DMLabel iface, cellSets;
  PetscInt cStart, cEnd;
  PetscFunctionBeginUser;
  if (scene.interfaces.empty()) PetscFunctionReturn(0);
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCall(DMGetLabel(dm, kInterfaceLabel, &iface));
  PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
  if (!iface || !cellSets) PetscFunctionReturn(0);
  std::vector<Extremes> normal(scene.interfaces.size()), tangential(scene.interfaces.size());
  const CurvedNodes *nodes = curvedNodes(dm); // curved cells: their own measures
  std::map<DMPolytopeType, ReferenceElement> elements;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(dm, c, &t));
    if (!isCohesive(t)) continue;
    PetscInt which = -1;
    PetscCall(DMLabelGetValue(iface, c, &which));
    if (which < 1 || which > (PetscInt)scene.interfaces.size()) continue;
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    double h = std::numeric_limits<double>::infinity(), E[2] = {0.0, 0.0};
    bool both = true;
    for (int side = 0; side < 2; ++side) {
      PetscInt cell, tag = -1;
      PetscCall(bulkNeighbour(dm, cone[side], &cell));
      if (cell < 0) {
        both = false;
        break;
      }
      PetscCall(DMLabelGetValue(cellSets, cell, &tag));
      const int r = scene.regionIndexOfTag((int)tag);
      if (r < 0) {
        both = false;
        break;
      }
      double hs = 0.0;
      PetscCall(heightOver(dm, cell, cone[side], scene.dim, nodes, elements, &hs));
      h = std::min(h, hs);
      E[side] = scene.regions[r].young;
    }
    if (!both || !(h > 0.0) || !(E[0] > 0.0) || !(E[1] > 0.0)) continue;
    const Interface &in = scene.interfaces[which - 1];
    const double soft = std::min(E[0], E[1]), stiff = std::max(E[0], E[1]);
    account(normal[which - 1], in.normal_stiffness, h, soft, stiff);
    account(tangential[which - 1], in.tangential_stiffness, h, soft, stiff);
  }
  for (size_t i = 0; i < scene.interfaces.size(); ++i) {
    PetscCall(reduce(comm, normal[i]));
    PetscCall(reduce(comm, tangential[i]));
    PetscCall(warn(comm, scene.interfaces[i].name, "K_N", scene.interfaces[i].normal_stiffness,
                   normal[i]));
    PetscCall(warn(comm, scene.interfaces[i].name, "K_T", scene.interfaces[i].tangential_stiffness,
                   tangential[i]));
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
