// The set-up warning of docs/interface_parameters.md: an interface penalty far outside the
// range its mesh and materials call for (too soft: visible overlap and a softer structure;
// too stiff: conditioning). One line per interface and stiffness, from rank 0.
#include "poroseam/penalty_check.hpp"

#include "poroseam/interfaces.hpp"
#include "poroseam/penalty_advice.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
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

/// Height of a bulk cell over one of its faces: volume / face measure, times the dimension on
/// simplices (a triangle's height is 2 A / b).
PetscErrorCode heightOver(DM dm, PetscInt cell, PetscInt face, int dim, double *h)
{
  PetscReal volume, area, centroid[3], normal[3];
  DMPolytopeType type;
  PetscFunctionBeginUser;
  PetscCall(DMPlexComputeCellGeometryFVM(dm, cell, &volume, centroid, normal));
  PetscCall(DMPlexComputeCellGeometryFVM(dm, face, &area, centroid, normal));
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
                  "%.3g (h = %.3g m, E = %.3g Pa), so the faces overlap and slide elastically as "
                  "much as an element deforms; a sensible %s is 10 to 1000 E / h, here %.2g to "
                  "%.2g Pa/m (docs/interface_parameters.md)\n",
                  iface.c_str(), name, K, x.soft_ratio, x.soft_h, x.soft_E, name,
                  10 * x.soft_E / x.soft_h, 1000 * x.soft_E / x.soft_h);
  else if (x.stiff_ratio > kPenaltyRatioStiff)
    std::snprintf(line, sizeof line,
                  "poroseam: warning: interface %s: %s = %g Pa/m is stiff for its mesh: K h / E = "
                  "%.3g (h = %.3g m, E = %.3g Pa), so it dominates the conditioning (slow "
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
      PetscCall(heightOver(dm, cell, cone[side], scene.dim, &hs));
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
