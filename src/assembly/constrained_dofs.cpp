// The constrained dofs (split from Problem::setup, problem.cpp): the local offsets of the
// unknowns each Dirichlet condition of the scene prescribes, and which condition sets each,
// for the prescribed values and their rates (problem_state.cpp). Part of Problem (problem.hpp).
#include "poroseam/problem.hpp"

#include "poroseam/layout.hpp"

#include <vector>

namespace poroseam {

PetscErrorCode Problem::collectConstrainedDofs()
{
  const Scene &scene = *scene_;
  PetscSection s;
  PetscInt numFields;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(PetscSectionGetNumFields(s, &numFields));
  for (size_t i = 0; i < scene.conditions.size(); ++i) {
    const auto &bc = scene.conditions[i];
    if (!bc.dirichlet()) continue;
    DMLabel label;
    PetscCall(DMGetLabel(dm_, boundaryLabelName(bc.boundary).c_str(), &label));
    if (bc.kind == BcKind::interface_pressure) {
      std::vector<PetscInt> edges;
      PetscCall(lateralEdgesOnBoundary(dm_, bc.boundary, edges));
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
