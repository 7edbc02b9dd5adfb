#include "poroseam/layout.hpp"

#include <vector>

namespace poroseam {

std::string boundaryLabelName(const std::string &boundary)
{
  return "boundary " + boundary;
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
  for (const auto &b : scene.boundaries) {
    DMLabel label;
    const std::string name = boundaryLabelName(b.name);
    PetscCall(DMCreateLabel(dm, name.c_str()));
    PetscCall(DMGetLabel(dm, name.c_str(), &label));
    IS faces = nullptr;
    if (faceSets) PetscCall(DMLabelGetStratumIS(faceSets, b.tag, &faces));
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
  PetscFunctionReturn(0);
}

PetscErrorCode createSolutionSection(DM dm, const Scene &scene)
{
  const int dim = scene.dim;
  const bool pressure = scene.hasPressure();
  PetscInt pStart, pEnd, vStart, vEnd;
  DMLabel porous;
  PetscSection s;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetLabel(dm, kPorousLabel, &porous));

  // Constrained components per vertex: bits 0..dim-1 displacement, bit dim pressure.
  std::vector<unsigned> constrained(vEnd - vStart, 0u);
  for (const auto &bc : scene.conditions) {
    if (!bc.dirichlet()) continue;
    DMLabel label;
    PetscCall(DMGetLabel(dm, boundaryLabelName(bc.boundary).c_str(), &label));
    IS points = nullptr;
    PetscCall(DMLabelGetStratumIS(label, 1, &points));
    if (!points) continue;
    const PetscInt *idx;
    PetscInt n;
    PetscCall(ISGetLocalSize(points, &n));
    PetscCall(ISGetIndices(points, &idx));
    const unsigned bit = bc.kind == BcKind::pressure ? 1u << dim : 1u << bc.component;
    for (PetscInt i = 0; i < n; ++i)
      if (idx[i] >= vStart && idx[i] < vEnd) constrained[idx[i] - vStart] |= bit;
    PetscCall(ISRestoreIndices(points, &idx));
    PetscCall(ISDestroy(&points));
  }

  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, pressure ? 2 : 1));
  PetscCall(PetscSectionSetFieldName(s, kDisplacementField, "displacement"));
  PetscCall(PetscSectionSetFieldComponents(s, kDisplacementField, dim));
  if (pressure) {
    PetscCall(PetscSectionSetFieldName(s, kPressureField, "pressure"));
    PetscCall(PetscSectionSetFieldComponents(s, kPressureField, 1));
  }
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  auto hasPressure = [&](PetscInt v, bool *has) -> PetscErrorCode {
    PetscInt value = -1;
    PetscFunctionBeginUser;
    if (pressure) PetscCall(DMLabelGetValue(porous, v, &value));
    *has = value == 1;
    PetscFunctionReturn(0);
  };
  for (PetscInt v = vStart; v < vEnd; ++v) {
    bool hasP = false;
    PetscCall(hasPressure(v, &hasP));
    const unsigned bits = constrained[v - vStart];
    int cu = 0;
    for (int d = 0; d < dim; ++d)
      cu += (bits >> d) & 1u;
    const int cp = hasP && ((bits >> dim) & 1u);
    PetscCall(PetscSectionSetDof(s, v, dim + (hasP ? 1 : 0)));
    PetscCall(PetscSectionSetFieldDof(s, v, kDisplacementField, dim));
    if (pressure) PetscCall(PetscSectionSetFieldDof(s, v, kPressureField, hasP ? 1 : 0));
    if (cu + cp) {
      PetscCall(PetscSectionSetConstraintDof(s, v, cu + cp));
      PetscCall(PetscSectionSetFieldConstraintDof(s, v, kDisplacementField, cu));
      if (pressure) PetscCall(PetscSectionSetFieldConstraintDof(s, v, kPressureField, cp));
    }
  }
  PetscCall(PetscSectionSetUp(s));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    const unsigned bits = constrained[v - vStart];
    PetscInt cdof;
    PetscCall(PetscSectionGetConstraintDof(s, v, &cdof));
    if (!cdof) continue;
    PetscInt all[4], fieldU[3], fieldP[1], nu = 0, np = 0, na = 0;
    for (int d = 0; d < dim; ++d)
      if ((bits >> d) & 1u) fieldU[nu++] = d, all[na++] = d;
    bool hasP = false;
    PetscCall(hasPressure(v, &hasP));
    if (hasP && ((bits >> dim) & 1u)) fieldP[np++] = 0, all[na++] = dim;
    PetscCall(PetscSectionSetFieldConstraintIndices(s, v, kDisplacementField, fieldU));
    if (pressure) PetscCall(PetscSectionSetFieldConstraintIndices(s, v, kPressureField, fieldP));
    PetscCall(PetscSectionSetConstraintIndices(s, v, all));
  }
  PetscCall(DMSetLocalSection(dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(0);
}

} // namespace poroseam
