#include "steady_pressure.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

#include <algorithm>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode SteadyPressure::setup(DM dm, const Scene &scene, Vec initial)
{
  PetscFunctionBeginUser;
  dm_ = dm;
  initial_ = initial;
  enabled_ = scene.hasPressure();
  if (!enabled_) PetscFunctionReturn(0);
  for (const BoundaryCondition &c : scene.conditions)
    if (c.kind == BcKind::pressure || c.kind == BcKind::interface_pressure) defined_ = true;
  PetscCall(DMCreateLocalVector(dm, &steady_));
  PetscCall(VecDuplicate(steady_, &zero_rate_));
  PetscCall(VecSet(zero_rate_, 0.0));
  // The pressure unknowns: every field but the displacement (field 0).
  PetscInt nf;
  char **names;
  IS *fields;
  PetscCall(DMCreateFieldIS(dm, &nf, &names, &fields));
  if (nf > 2) {
    PetscCall(ISConcatenate(PetscObjectComm((PetscObject)dm), nf - 1, fields + 1, &pressure_));
    PetscCall(ISSort(pressure_));
  } else if (nf == 2) {
    PetscCall(PetscObjectReference((PetscObject)fields[1]));
    pressure_ = fields[1];
  }
  for (PetscInt f = 0; f < nf; ++f) {
    PetscCall(ISDestroy(&fields[f]));
    PetscCall(PetscFree(names[f]));
  }
  PetscCall(PetscFree(fields));
  PetscCall(PetscFree(names));
  if (!pressure_) enabled_ = false;
  PetscFunctionReturn(0);
}

std::vector<double> SteadyPressure::signature(const Scene &scene, double t) const
{
  std::vector<double> values;
  for (const BoundaryCondition &c : scene.conditions)
    if (c.kind == BcKind::pressure || c.kind == BcKind::interface_pressure ||
        c.kind == BcKind::flux)
      for (double v : c.value)
        values.push_back(v * c.time.factor(t));
  return values;
}

PetscErrorCode SteadyPressure::solve(const Problem &problem, double t, Vec local, Mat J,
                                     bool *solved)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  Vec X, F, f;
  PetscFunctionBeginUser;
  *solved = false;
  if (!ksp_) {
    PC pc;
    PetscCall(KSPCreate(comm, &ksp_));
    PetscCall(KSPSetType(ksp_, KSPPREONLY));
    PetscCall(KSPGetPC(ksp_, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    PetscCall(KSPSetErrorIfNotConverged(ksp_, PETSC_FALSE));
  }
  PetscCall(VecCopy(local, steady_));
  PetscCall(problem.insertBoundaryValues(t, steady_));
  PetscCall(DMGetGlobalVector(dm_, &X));
  PetscCall(DMGetGlobalVector(dm_, &F));
  PetscCall(DMGetLocalVector(dm_, &f));
  PetscCall(DMLocalToGlobal(dm_, steady_, INSERT_VALUES, X));
  // Rows in fluid volume rates (mass scale 1); no step: rates of non-linear quantities are 0.
  const ResidualMode mode{1.0, true, 0.0};
  double first = 0.0;
  bool failed = false;
  for (int it = 0; it < 2 && !failed; ++it) {
    PetscCall(problem.residual(t, steady_, zero_rate_, mode, f));
    PetscCall(VecSet(F, 0.0));
    PetscCall(DMLocalToGlobal(dm_, f, ADD_VALUES, F));
    Vec Fp, Xp, dp;
    PetscReal norm;
    PetscCall(VecGetSubVector(F, pressure_, &Fp));
    PetscCall(VecNorm(Fp, NORM_2, &norm));
    if (it == 0) first = norm;
    const bool done = it > 0 && norm <= 1e-10 * first;
    if (!done) {
      Mat Jpp;
      KSPConvergedReason reason;
      PetscCall(problem.jacobian(t, 0.0, steady_, zero_rate_, mode, J));
      PetscCall(MatCreateSubMatrix(J, pressure_, pressure_, MAT_INITIAL_MATRIX, &Jpp));
      PetscCall(KSPSetOperators(ksp_, Jpp, Jpp));
      PetscCall(VecDuplicate(Fp, &dp));
      // A singular block (no flow anywhere in a region) fails the factorisation; PETSc then
      // reports it through the KSP's reason.
      PetscCall(KSPSolve(ksp_, Fp, dp));
      PetscCall(KSPGetConvergedReason(ksp_, &reason));
      PetscReal step;
      PetscCall(VecNorm(dp, NORM_INFINITY, &step));
      failed = reason < 0 || std::isnan(step) || std::isinf(step);
      if (!failed) {
        PetscCall(VecGetSubVector(X, pressure_, &Xp));
        PetscCall(VecAXPY(Xp, -1.0, dp));
        PetscCall(VecRestoreSubVector(X, pressure_, &Xp));
        PetscCall(DMGlobalToLocal(dm_, X, INSERT_VALUES, steady_));
        PetscCall(problem.insertBoundaryValues(t, steady_));
      }
      PetscCall(VecDestroy(&dp));
      PetscCall(MatDestroy(&Jpp));
      PetscCall(KSPReset(ksp_));
    }
    PetscCall(VecRestoreSubVector(F, pressure_, &Fp));
    if (done) {
      *solved = true;
      break;
    }
  }
  // One Newton step solves the linear flow problem; a residual still above 1e-10 of the
  // first after it (not linear: apertures...) is accepted after the second step.
  if (!failed && !*solved) *solved = true;
  PetscCall(DMRestoreLocalVector(dm_, &f));
  PetscCall(DMRestoreGlobalVector(dm_, &F));
  PetscCall(DMRestoreGlobalVector(dm_, &X));
  if (failed) *solved = false;
  PetscFunctionReturn(0);
}

PetscErrorCode SteadyPressure::compute(const Problem &problem, double t, Vec local, Mat J,
                                       Vec *steady)
{
  PetscFunctionBeginUser;
  *steady = nullptr;
  if (!enabled_) PetscFunctionReturn(0);
  if (!defined_) {
    *steady = initial_;
    PetscFunctionReturn(0);
  }
  const std::vector<double> now = signature(problem.scene(), t);
  if (!have_ || now != signature_) {
    bool solved = false;
    PetscCall(solve(problem, t, local, J, &solved));
    if (!solved) {
      if (!warned_) {
        char when[32];
        std::snprintf(when, sizeof when, "%g", t);
        PetscCall(PetscPrintf(PetscObjectComm((PetscObject)dm_),
                              "steady pore pressure: the flow problem at t = %s s is singular (a "
                              "region without permeability, or water that no prescribed pressure "
                              "reaches): steady_pressure and excess_pressure use the initial "
                              "pressure instead\n",
                              when));
      }
      warned_ = true;
      defined_ = false;
      *steady = initial_;
      PetscFunctionReturn(0);
    }
    signature_ = now;
    have_ = true;
  }
  *steady = steady_;
  PetscFunctionReturn(0);
}

PetscErrorCode SteadyPressure::kept(std::vector<double> &values,
                                    std::vector<double> &conditions) const
{
  PetscFunctionBeginUser;
  values.clear();
  conditions.clear();
  if (!enabled_ || !defined_ || !have_) PetscFunctionReturn(0);
  const PetscScalar *a;
  PetscInt n;
  PetscCall(VecGetLocalSize(steady_, &n));
  PetscCall(VecGetArrayRead(steady_, &a));
  values.assign(a, a + n);
  PetscCall(VecRestoreArrayRead(steady_, &a));
  conditions = signature_;
  PetscFunctionReturn(0);
}

PetscErrorCode SteadyPressure::restore(const std::vector<double> &values,
                                       const std::vector<double> &conditions)
{
  PetscInt n;
  PetscScalar *a;
  PetscFunctionBeginUser;
  if (!enabled_ || !defined_) PetscFunctionReturn(0);
  PetscCall(VecGetLocalSize(steady_, &n));
  PetscCheck((PetscInt)values.size() == n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "steady pore pressure of the checkpoint: %zu values, the local vector has %" PetscInt_FMT,
             values.size(), n);
  PetscCall(VecGetArray(steady_, &a));
  std::copy(values.begin(), values.end(), a);
  PetscCall(VecRestoreArray(steady_, &a));
  signature_ = conditions;
  have_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode SteadyPressure::destroy()
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&steady_));
  PetscCall(VecDestroy(&zero_rate_));
  PetscCall(ISDestroy(&pressure_));
  PetscCall(KSPDestroy(&ksp_));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
