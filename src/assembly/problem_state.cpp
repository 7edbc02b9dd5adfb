// The problem's states: the initial state (hydrostatic pressure, geostatic stress), prescribed
// values and their rates at the constrained dofs, the load factor shown in progress lines.
// Part of Problem (problem.hpp); set-up in problem.cpp, assembly in problem_assembly.cpp.
#include "poroseam/problem.hpp"

#include "poroseam/layout.hpp"

#include <petscdmplex.h>

namespace poroseam {

double Problem::gravityVector(int d) const
{
  return d == dim_ - 1 ? -scene_->gravity : 0.0;
}

double Problem::initialPressure(const double x[]) const
{
  if (scene_->gravity <= 0.0) return 0.0;
  return physics::hydrostaticPressure(column_, x[dim_ - 1]);
}

void Problem::initialStress(const double x[], int region, double stress[3][3]) const
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      stress[i][j] = 0.0;
  const Region &r = scene_->regions[region];
  // Structures (regions outside the ground column) start unstressed: their weight is a load.
  if (!scene_->geostatic || !r.inGround()) return;
  physics::geostaticStress(column_, x[dim_ - 1], r.k0, r.porous() ? r.biot_coefficient : 0.0, dim_,
                           stress);
}

void Problem::initialTotalStress(const double x[], int region, double stress[3][3]) const
{
  initialStress(x, region, stress);
  const Region &r = scene_->regions[region];
  if (!scene_->geostatic || !r.inGround() || !r.porous()) return;
  const double p = initialPressure(x);
  for (int i = 0; i < 3; ++i)
    stress[i][i] -= r.biot_coefficient * p;
}

PetscErrorCode Problem::initialState(Vec local) const
{
  PetscSection s, csec;
  Vec coords;
  const PetscScalar *x;
  PetscScalar *u;
  PetscInt vStart, vEnd, numFields;
  PetscFunctionBeginUser;
  PetscCall(VecSet(local, 0.0));
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(PetscSectionGetNumFields(s, &numFields));
  if (numFields <= kPressureField) PetscFunctionReturn(0);
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &vStart, &vEnd));
  PetscCall(VecGetArrayRead(coords, &x));
  PetscCall(VecGetArray(local, &u));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt dof, off, coff;
    PetscCall(PetscSectionGetFieldDof(s, v, kPressureField, &dof));
    if (!dof) continue;
    PetscCall(PetscSectionGetFieldOffset(s, v, kPressureField, &off));
    PetscCall(PetscSectionGetOffset(csec, v, &coff));
    u[off] = initialPressure(&x[coff]);
  }
  if (numFields > kInterfacePressureField) {
    // p3 starts hydrostatic too, at the position of its lateral edge's vertices.
    PetscInt eStart, eEnd;
    PetscCall(DMPlexGetDepthStratum(dm_, 1, &eStart, &eEnd));
    for (PetscInt e = eStart; e < eEnd; ++e) {
      PetscInt dof, off, coff;
      PetscCall(PetscSectionGetFieldDof(s, e, kInterfacePressureField, &dof));
      if (!dof) continue;
      const PetscInt *cone;
      PetscCall(DMPlexGetCone(dm_, e, &cone));
      PetscCall(PetscSectionGetFieldOffset(s, e, kInterfacePressureField, &off));
      PetscCall(PetscSectionGetOffset(csec, cone[0], &coff));
      u[off] = initialPressure(&x[coff]);
    }
  }
  PetscCall(VecRestoreArray(local, &u));
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::insertBoundaryValues(double t, Vec local) const
{
  PetscScalar *u;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(local, &u));
  for (const auto &c : constrained_) {
    const auto &bc = scene_->conditions[c.condition];
    u[c.offset] = bc.value[0] * bc.time.factor(t);
  }
  PetscCall(VecRestoreArray(local, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::insertBoundaryRates(double t, const RateStencil &stencil,
                                            Vec local_rate) const
{
  PetscScalar *rate;
  const PetscScalar *state[2] = {nullptr, nullptr};
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(local_rate, &rate));
  for (int k = 0; k < stencil.count; ++k)
    PetscCall(VecGetArrayRead(stencil.state[k], &state[k]));
  for (const auto &c : constrained_) {
    const auto &bc = scene_->conditions[c.condition];
    double r = stencil.now * bc.value[0] * bc.time.factor(t);
    for (int k = 0; k < stencil.count; ++k)
      r += stencil.weight[k] * state[k][c.offset];
    rate[c.offset] = r;
  }
  for (int k = 0; k < stencil.count; ++k)
    PetscCall(VecRestoreArrayRead(stencil.state[k], &state[k]));
  PetscCall(VecRestoreArray(local_rate, &rate));
  PetscFunctionReturn(0);
}

} // namespace poroseam
