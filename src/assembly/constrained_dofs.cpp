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
  std::vector<PetscInt> points;
  for (size_t i = 0; i < scene.conditions.size(); ++i) {
    const auto &bc = scene.conditions[i];
    if (!bc.dirichlet()) continue;
    const int field = bc.kind == BcKind::interface_pressure ? kInterfacePressureField
                      : bc.kind == BcKind::pressure         ? kPressureField
                                                            : kDisplacementField;
    if (field >= numFields) continue;
    PetscCall(dirichletPoints(dm_, bc, points));
    for (PetscInt point : points) {
      PetscInt dof = 0, off = 0;
      PetscCall(PetscSectionGetFieldDof(s, point, field, &dof));
      if (!dof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, point, field, &off));
      constrained_.push_back({off + (field == kDisplacementField ? bc.component : 0), (int)i});
    }
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
