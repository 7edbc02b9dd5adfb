#include "poroseam/layout.hpp"

#include "poroseam/corner_conditions.hpp"
#include "poroseam/interfaces.hpp"

#include <vector>

namespace poroseam {

std::string boundaryLabelName(const std::string &boundary)
{
  return "boundary " + boundary;
}

PetscErrorCode lateralEdgesOnBoundary(DM dm, const std::string &boundary,
                                      std::vector<PetscInt> &edges)
{
  DMLabel lateral, label;
  IS is = nullptr;
  PetscFunctionBeginUser;
  edges.clear();
  PetscCall(DMGetLabel(dm, kInterfacePressureLabel, &lateral));
  PetscCall(DMGetLabel(dm, boundaryLabelName(boundary).c_str(), &label));
  if (lateral && label) PetscCall(DMLabelGetStratumIS(lateral, 1, &is));
  if (!is) PetscFunctionReturn(0);
  const PetscInt *idx;
  PetscInt n;
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetIndices(is, &idx));
  for (PetscInt k = 0; k < n; ++k) {
    // Either vertex of the split pair: where the interface ends between two bodies (a sheet
    // pile's head at the ground surface), the boundary's faces touch only one copy, and which
    // copy the split numbers first is not the side the boundary is on.
    const PetscInt *cone;
    PetscInt on0 = -1, on1 = -1;
    PetscCall(DMPlexGetCone(dm, idx[k], &cone));
    PetscCall(DMLabelGetValue(label, cone[0], &on0));
    PetscCall(DMLabelGetValue(label, cone[1], &on1));
    if (on0 == 1 || on1 == 1) edges.push_back(idx[k]);
  }
  PetscCall(ISRestoreIndices(is, &idx));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

PetscErrorCode markLayoutLabels(DM dm, const Scene &scene)
{
  DMLabel cellSets, faceSets, porous;
  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
  PetscCall(DMGetLabel(dm, "Face Sets", &faceSets));
  PetscCall(DMCreateLabel(dm, kPorousLabel));
  PetscCall(DMGetLabel(dm, kPorousLabel, &porous));
  if (scene.hasPressure() && cellSets) {
    for (const auto &r : scene.regions) {
      if (!r.porous()) continue;
      IS cells;
      PetscCall(DMLabelGetStratumIS(cellSets, r.tag, &cells));
      if (!cells) continue;
      const PetscInt *idx;
      PetscInt n;
      PetscCall(ISGetLocalSize(cells, &n));
      PetscCall(ISGetIndices(cells, &idx));
      for (PetscInt i = 0; i < n; ++i)
        PetscCall(DMLabelSetValue(porous, idx[i], 1));
      PetscCall(ISRestoreIndices(cells, &idx));
      PetscCall(ISDestroy(&cells));
    }
  }
  PetscCall(DMPlexLabelComplete(dm, porous));
  // Lateral edges of cohesive cells of interfaces with flow.
  PetscCall(DMCreateLabel(dm, kInterfacePressureLabel));
  if (scene.hasInterfacePressure()) {
    DMLabel lateral, iface;
    PetscCall(DMGetLabel(dm, kInterfacePressureLabel, &lateral));
    PetscCall(DMGetLabel(dm, kInterfaceLabel, &iface));
    PetscInt cStart, cEnd;
    PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
    for (PetscInt c = cStart; c < cEnd; ++c) {
      PetscInt which = -1;
      PetscCall(DMLabelGetValue(iface, c, &which));
      if (which < 1 || !scene.interfaces[which - 1].flow) continue;
      PetscInt n, *pts = nullptr;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
      for (PetscInt k = 0; k < n; ++k) {
        DMPolytopeType t;
        PetscCall(DMPlexGetCellType(dm, pts[2 * k], &t));
        if (t == DM_POLYTOPE_POINT_PRISM_TENSOR) PetscCall(DMLabelSetValue(lateral, pts[2 * k], 1));
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
    }
  }
  for (const auto &b : scene.boundaries) {
    DMLabel label;
    const std::string name = boundaryLabelName(b.name);
    PetscCall(DMCreateLabel(dm, name.c_str()));
    PetscCall(DMGetLabel(dm, name.c_str(), &label));
    IS faces = nullptr;
    DMLabel groups; // face groups, or physical points and curves (supports)
    PetscCall(DMGetLabel(dm, groupLabel(b.support_dim), &groups));
    if (groups) PetscCall(DMLabelGetStratumIS(groups, b.tag, &faces));
    if (faces) {
      const PetscInt *idx;
      PetscInt n;
      PetscCall(ISGetLocalSize(faces, &n));
      PetscCall(ISGetIndices(faces, &idx));
      for (PetscInt i = 0; i < n; ++i)
        PetscCall(DMLabelSetValue(label, idx[i], 1));
      PetscCall(ISRestoreIndices(faces, &idx));
      PetscCall(ISDestroy(&faces));
    }
    PetscCall(DMPlexLabelComplete(dm, label));
  }
  // A prescribed interface pressure needs an interface with flow that reaches the boundary.
  for (const auto &bc : scene.conditions) {
    if (bc.kind != BcKind::interface_pressure) continue;
    std::vector<PetscInt> edges;
    PetscCall(lateralEdgesOnBoundary(dm, bc.boundary, edges));
    long mine = (long)edges.size(), total = 0;
    PetscCallMPI(
        MPI_Allreduce(&mine, &total, 1, MPI_LONG, MPI_SUM, PetscObjectComm((PetscObject)dm)));
    PetscCheck(total > 0, PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT,
               "%s: no interface with flow (-interface_<i>_flow) meets boundary '%s', so there "
               "is no interface pressure there to prescribe; name a boundary that an "
               "interface with flow ends on",
               bc.option.c_str(), bc.boundary.c_str());
  }
  PetscCall(reportCornerConditions(dm, scene));
  PetscFunctionReturn(0);
}

namespace {

/// Displacement nodes on a point for the scene's order: every vertex; at order 2 also every edge
/// (P2 and Q2 alike: quadratic along the edge, one node at its middle) and every
/// quadrilateral or hexahedron (the centre node of Lagrange Q2). Triangles and tetrahedra
/// have none (P2). Other points (cohesive cells, their lateral edges) have none.
int displacementNodes(DMPolytopeType type, int order)
{
  if (type == DM_POLYTOPE_POINT) return 1;
  if (order < 2) return 0;
  return type == DM_POLYTOPE_SEGMENT || type == DM_POLYTOPE_QUADRILATERAL ||
                 type == DM_POLYTOPE_HEXAHEDRON
             ? 1
             : 0;
}

/// Whether a point is in stratum 1 of a label.
PetscErrorCode inLabel(DMLabel label, PetscInt point, bool *in)
{
  PetscInt value = -1;
  PetscFunctionBeginUser;
  if (label) PetscCall(DMLabelGetValue(label, point, &value));
  *in = value == 1;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode dirichletPoints(DM dm, const BoundaryCondition &bc, std::vector<PetscInt> &points)
{
  PetscFunctionBeginUser;
  points.clear();
  if (bc.kind == BcKind::interface_pressure) {
    PetscCall(lateralEdgesOnBoundary(dm, bc.boundary, points));
    PetscFunctionReturn(0);
  }
  DMLabel label;
  IS stratum = nullptr;
  PetscCall(DMGetLabel(dm, boundaryLabelName(bc.boundary).c_str(), &label));
  PetscCall(DMLabelGetStratumIS(label, 1, &stratum));
  if (!stratum) PetscFunctionReturn(0);
  const PetscInt *idx;
  PetscInt n;
  PetscCall(ISGetLocalSize(stratum, &n));
  PetscCall(ISGetIndices(stratum, &idx));
  points.assign(idx, idx + n);
  PetscCall(ISRestoreIndices(stratum, &idx));
  PetscCall(ISDestroy(&stratum));
  PetscFunctionReturn(0);
}

PetscErrorCode createSolutionSection(DM dm, const Scene &scene)
{
  const int dim = scene.dim;
  const bool interface_pressure = scene.hasInterfacePressure();
  const bool pressure = scene.hasPressure() || interface_pressure; // fields keep their numbers
  const int numFields = interface_pressure ? 3 : pressure ? 2 : 1;
  PetscInt pStart, pEnd;
  DMLabel porous, lateral;
  PetscSection s;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMGetLabel(dm, kPorousLabel, &porous));
  PetscCall(DMGetLabel(dm, kInterfacePressureLabel, &lateral));

  // Constrained components per point: bits 0..dim-1 displacement, bit dim pressure,
  // bit dim + 1 interface pressure.
  std::vector<unsigned> constrained(pEnd - pStart, 0u);
  std::vector<PetscInt> points;
  for (const auto &bc : scene.conditions) {
    if (!bc.dirichlet()) continue;
    PetscCall(dirichletPoints(dm, bc, points));
    const unsigned bit = bc.kind == BcKind::interface_pressure ? 1u << (dim + 1)
                         : bc.kind == BcKind::pressure         ? 1u << dim
                                                               : 1u << bc.component;
    for (PetscInt p : points)
      constrained[p - pStart] |= bit;
  }

  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, numFields));
  PetscCall(PetscSectionSetFieldName(s, kDisplacementField, "displacement"));
  PetscCall(PetscSectionSetFieldComponents(s, kDisplacementField, dim));
  if (pressure) {
    PetscCall(PetscSectionSetFieldName(s, kPressureField, "pressure"));
    PetscCall(PetscSectionSetFieldComponents(s, kPressureField, 1));
  }
  if (interface_pressure) {
    PetscCall(PetscSectionSetFieldName(s, kInterfacePressureField, "interface_pressure"));
    PetscCall(PetscSectionSetFieldComponents(s, kInterfacePressureField, 1));
  }
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));

  // Dofs per point and field: u on the displacement nodes (vertices; at order 2 edges and
  // tensor faces and cells too), p on porous vertices, p3 on flow lateral edges.
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  auto dofs = [&](PetscInt pt, int field_dofs[3], int field_constraints[3]) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const unsigned bits = constrained[pt - pStart];
    for (int f = 0; f < 3; ++f)
      field_dofs[f] = field_constraints[f] = 0;
    DMPolytopeType type;
    PetscCall(DMPlexGetCellType(dm, pt, &type));
    if (displacementNodes(type, scene.displacement_order)) {
      // Every constrained point of a boundary's closure (vertices, and at order 2 its edges
      // and faces) takes the condition: the label is complete (markLayoutLabels).
      field_dofs[0] = dim;
      for (int d = 0; d < dim; ++d)
        field_constraints[0] += (bits >> d) & 1u;
    }
    if (pt >= vStart && pt < vEnd) {
      bool hasP = false;
      if (scene.hasPressure()) PetscCall(inLabel(porous, pt, &hasP));
      field_dofs[1] = hasP ? 1 : 0;
      field_constraints[1] = hasP ? (int)((bits >> dim) & 1u) : 0;
    } else if (interface_pressure) {
      bool hasP3 = false;
      PetscCall(inLabel(lateral, pt, &hasP3));
      field_dofs[2] = hasP3 ? 1 : 0;
      field_constraints[2] = hasP3 ? (int)((bits >> (dim + 1)) & 1u) : 0;
    }
    PetscFunctionReturn(0);
  };
  for (PetscInt pt = pStart; pt < pEnd; ++pt) {
    int nd[3], nc[3];
    PetscCall(dofs(pt, nd, nc));
    PetscCall(PetscSectionSetDof(s, pt, nd[0] + nd[1] + nd[2]));
    for (int f = 0; f < numFields; ++f)
      PetscCall(PetscSectionSetFieldDof(s, pt, f, nd[f]));
    if (nc[0] + nc[1] + nc[2]) {
      PetscCall(PetscSectionSetConstraintDof(s, pt, nc[0] + nc[1] + nc[2]));
      for (int f = 0; f < numFields; ++f)
        PetscCall(PetscSectionSetFieldConstraintDof(s, pt, f, nc[f]));
    }
  }
  PetscCall(PetscSectionSetUp(s));
  for (PetscInt pt = pStart; pt < pEnd; ++pt) {
    int nd[3], nc[3];
    PetscCall(dofs(pt, nd, nc));
    if (!(nc[0] + nc[1] + nc[2])) continue;
    const unsigned bits = constrained[pt - pStart];
    PetscInt all[5], field[3][3], count[3] = {0, 0, 0}, na = 0;
    for (int d = 0; d < dim && nd[0]; ++d)
      if ((bits >> d) & 1u) field[0][count[0]++] = d, all[na++] = d;
    if (nc[1]) field[1][count[1]++] = 0, all[na++] = nd[0];
    if (nc[2]) field[2][count[2]++] = 0, all[na++] = nd[0] + nd[1];
    for (int f = 0; f < numFields; ++f)
      PetscCall(PetscSectionSetFieldConstraintIndices(s, pt, f, field[f]));
    PetscCall(PetscSectionSetConstraintIndices(s, pt, all));
  }
  PetscCall(DMSetLocalSection(dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(0);
}

PetscErrorCode pressureRows(PetscInt num_fields, const IS fields[], IS *rows)
{
  PetscFunctionBeginUser;
  *rows = nullptr;
  if (num_fields <= kPressureField) PetscFunctionReturn(0);
  PetscCall(ISDuplicate(fields[kPressureField], rows));
  for (PetscInt f = kPressureField + 1; f < num_fields; ++f) {
    IS merged;
    PetscCall(ISExpand(*rows, fields[f], &merged));
    PetscCall(ISDestroy(rows));
    *rows = merged;
  }
  PetscCall(ISSort(*rows));
  PetscFunctionReturn(0);
}

} // namespace poroseam
