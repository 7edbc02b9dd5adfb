// When Newton stops, how exactly each linear solve is asked to be, and where Newton starts
// (split from simulation.cpp).

#include "run.hpp"

#include "poroseam/newton_forcing.hpp"

#include <algorithm>
#include <cmath>

namespace poroseam {
namespace simulation_detail {

/// PETSc's default tests (with -snes_rtol 1e-12 by default), plus the one that normally
/// decides: after at least one Newton update, converged when the residual is below
/// reference_rtol times a force scale, the larger of the gross residual of the zero state
/// (weight, initial stresses) and the force level of the current iterate (reactions, loads,
/// interface forces). Relative to the initial residual is no good here: a step that starts
/// near equilibrium cannot reduce its tiny residual by rtol before round-off, and a
/// displacement-driven step of a stiff body starts with a huge residual that says nothing
/// of the forces that matter.
///
/// It also sets the linear tolerance of the next Newton solve (an inexact Newton method;
/// linearTolerance), so that an iterative solver does not solve more exactly than the next
/// Newton iterate can use.
PetscErrorCode convergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                               PetscReal fnorm, SNESConvergedReason *reason, void *ctx)
{
  Run &run = *static_cast<Run *>(ctx);
  KSP ksp;
  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, nullptr));
  const double contraction =
      it > 0 && run.newton_last_fnorm > 0.0 ? fnorm / run.newton_last_fnorm : 0.0;
  run.newton_last_fnorm = fnorm;
  if (it == 0) {
    PetscCall(KSPSetTolerances(ksp, linearTolerance(run.ksp_rtol, 0.0, run.first_contraction),
                               PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    PetscFunctionReturn(0);
  }
  if (*reason != SNES_CONVERGED_ITERATING) PetscFunctionReturn(0);
  Vec X;
  double level = 0.0;
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(forceLevel(run, X, &level));
  const double scale = std::max(run.zero_state_scale, level);
  const double target = run.reference_rtol * scale;
  PetscCall(PetscInfo(snes, "poroseam: residual %g, force scale %g\n", (double)fnorm, scale));
  const bool converged = scale > 0.0 && fnorm <= target;
  if (it == 1) run.first_contraction = converged ? 0.0 : contraction;
  if (converged) {
    *reason = SNES_CONVERGED_FNORM_ABS;
  } else if (fnorm > 0.0) {
    PetscCall(KSPSetTolerances(ksp, linearTolerance(run.ksp_rtol, target / fnorm, contraction),
                               PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  }
  PetscFunctionReturn(0);
}

/// Backward Euler's extrapolated start (TimeIntegration::extrapolate): X (the last accepted
/// state, where the theta method leaves Newton) + dt / dt_last times the last accepted
/// increment, except on a retry after a failed attempt, whose cut step starts from the last
/// state. Kept in the Run, so that a checkpoint holds it and a restarted run takes the same
/// first step as the uninterrupted one.
///
/// Safeguard of the extrapolated start (either this one or BDF's): Newton starts from the
/// extrapolation only when its residual is smaller than that of the last accepted state. Where the
/// loading reverses, the extrapolation points the wrong way: measured on 50 shear reversals of soft
/// blocks (nodal), it raised the worst step from 4 to 9 Newton iterations; with this choice the
/// reversals cost what they did before. Two residual evaluations per step.
PetscErrorCode chooseInitialGuess(SNES snes, Vec X, void *ctx)
{
  Run &run = *static_cast<Run *>(ctx);
  Vec last, F;
  PetscFunctionBeginUser;
  if (run.time.extrapolate() && run.last_dt > 0.0) {
    PetscInt rejects;
    PetscCall(TSGetStepRejections(run.ts, &rejects));
    double dt;
    PetscCall(currentDt(run, &dt));
    if (rejects == run.last_rejects) PetscCall(VecAXPY(X, dt / run.last_dt, run.last_increment));
  }
  PetscCall(DMGetGlobalVector(run.dm, &last));
  PetscCall(DMGetGlobalVector(run.dm, &F));
  PetscCall(DMLocalToGlobal(run.dm, run.previous, INSERT_VALUES, last));
  PetscReal distance;
  PetscCall(VecAXPY(last, -1.0, X));
  PetscCall(VecNorm(last, NORM_INFINITY, &distance));
  PetscCall(VecAXPY(last, 1.0, X));
  if (distance > 0.0) {
    PetscReal extrapolated, unchanged;
    PetscCall(SNESComputeFunction(snes, X, F));
    PetscCall(VecNorm(F, NORM_2, &extrapolated));
    PetscCall(SNESComputeFunction(snes, last, F));
    PetscCall(VecNorm(F, NORM_2, &unchanged));
    PetscCall(PetscInfo(snes,
                        "poroseam: residual of the extrapolated start %g, of the last state %g\n",
                        (double)extrapolated, (double)unchanged));
    if (!(extrapolated < unchanged)) PetscCall(VecCopy(last, X));
  }
  PetscCall(DMRestoreGlobalVector(run.dm, &F));
  PetscCall(DMRestoreGlobalVector(run.dm, &last));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
