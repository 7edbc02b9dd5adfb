// Two boundaries prescribing the same unknown at a shared point: the later one holds, and a
// warning says so (see the header).
#include "poroseam/corner_conditions.hpp"

#include "poroseam/layout.hpp"

#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace poroseam {
namespace {

/// The two conditions give the same value at every time.
bool sameValues(const BoundaryCondition &a, const BoundaryCondition &b)
{
  return a.value == b.value && a.time == b.time;
}

/// "(x, y)" of a vertex (or of the first vertex of an edge: p3 lives on lateral edges).
PetscErrorCode pointPlace(DM dm, PetscInt point, int dim, std::string *text)
{
  PetscInt vStart, vEnd, off;
  Vec coords;
  PetscSection csec;
  const PetscScalar *x;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  if (point < vStart || point >= vEnd) {
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(dm, point, &cone));
    point = cone[0];
  }
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(PetscSectionGetOffset(csec, point, &off));
  PetscCall(VecGetArrayRead(coords, &x));
  std::ostringstream s;
  s << "(";
  for (int d = 0; d < dim; ++d)
    s << (d ? ", " : "") << x[off + d];
  s << ")";
  PetscCall(VecRestoreArrayRead(coords, &x));
  *text = s.str();
  PetscFunctionReturn(0);
}

/// The points where a Dirichlet condition holds: vertices of its boundary (porous ones for a
/// pressure), or the lateral edges of p3 (the same rule as createSolutionSection).
PetscErrorCode conditionPoints(DM dm, const BoundaryCondition &bc, std::vector<PetscInt> &points)
{
  DMLabel label, porous;
  IS is = nullptr;
  PetscInt vStart, vEnd;
  PetscFunctionBeginUser;
  points.clear();
  if (bc.kind == BcKind::interface_pressure) {
    PetscCall(lateralEdgesOnBoundary(dm, bc.boundary, points));
    PetscFunctionReturn(0);
  }
  PetscCall(DMGetLabel(dm, kPorousLabel, &porous));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetLabel(dm, boundaryLabelName(bc.boundary).c_str(), &label));
  if (label) PetscCall(DMLabelGetStratumIS(label, 1, &is));
  if (!is) PetscFunctionReturn(0);
  const PetscInt *idx;
  PetscInt n;
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetIndices(is, &idx));
  for (PetscInt k = 0; k < n; ++k) {
    if (idx[k] < vStart || idx[k] >= vEnd) continue; // u and p live on vertices
    PetscInt on = 1;
    if (bc.kind == BcKind::pressure && porous) PetscCall(DMLabelGetValue(porous, idx[k], &on));
    if (on == 1) points.push_back(idx[k]);
  }
  PetscCall(ISRestoreIndices(is, &idx));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

std::string described(const BoundaryCondition &bc)
{
  std::ostringstream s;
  s << bc.option << " " << bc.value[0];
  if (bc.time.kind() == TimeFunction::Kind::ramp) s << " (ramp)";
  if (bc.time.kind() == TimeFunction::Kind::table) s << " (table)";
  return s.str();
}

} // namespace

PetscErrorCode reportCornerConditions(DM dm, const Scene &scene)
{
  const int dim = scene.dim;
  const size_t n = scene.conditions.size();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  // (point, unknown) -> the conditions so far that prescribe it; unknown: 0..dim-1 the
  // displacement components, dim the pore pressure, dim + 1 p3.
  std::map<std::pair<PetscInt, int>, std::vector<size_t>> by_point;
  std::vector<long> shared(n * n, 0); // [earlier * n + later]: points where they differ
  std::vector<std::string> first_place(n * n);
  std::vector<PetscInt> points;
  PetscFunctionBeginUser;
  for (size_t i = 0; i < n; ++i) {
    const auto &bc = scene.conditions[i];
    if (!bc.dirichlet()) continue;
    const int unknown = bc.kind == BcKind::displacement ? bc.component
                        : bc.kind == BcKind::pressure   ? dim
                                                        : dim + 1;
    PetscCall(conditionPoints(dm, bc, points));
    for (PetscInt point : points) {
      auto &earlier = by_point[{point, unknown}];
      for (size_t j : earlier) {
        if (sameValues(scene.conditions[j], bc)) continue;
        if (shared[j * n + i]++ == 0)
          PetscCall(pointPlace(dm, point, dim, &first_place[j * n + i]));
      }
      earlier.push_back(i);
    }
  }
  // The mesh may be spread over the ranks: the counts are summed, the place is rank 0's (the
  // labels are set on the serial mesh, before distribution, where rank 0 holds every point).
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, shared.data(), (int)shared.size(), MPI_LONG, MPI_SUM, comm));
  for (size_t j = 0; j < n; ++j)
    for (size_t i = j + 1; i < n; ++i) {
      const long count = shared[j * n + i];
      if (!count) continue;
      const auto &a = scene.conditions[j], &b = scene.conditions[i];
      const std::string place =
          first_place[j * n + i].empty() ? "" : ", first at " + first_place[j * n + i];
      PetscCall(PetscPrintf(comm,
                            "poroseam: warning: %s and %s prescribe different values at %ld "
                            "point%s boundaries '%s' and '%s' share%s: %s holds there (at a "
                            "shared point the boundary listed later in -boundaries wins)\n",
                            described(a).c_str(), described(b).c_str(), count,
                            count == 1 ? "" : "s", a.boundary.c_str(), b.boundary.c_str(),
                            place.c_str(), b.option.c_str()));
    }
  PetscFunctionReturn(0);
}

} // namespace poroseam
