// When Newton stops, how exactly each linear solve is asked to be, and where Newton starts
// (split from simulation.cpp).

#include "poroseam/option_registry.hpp"
#include "run.hpp"

#include "poroseam/newton_forcing.hpp"

#include <algorithm>
#include <cmath>
#include <petscsnes.h>
#include <string>
#include <vector>

namespace poroseam {
namespace simulation_detail {

/// The force test's target for the iterate X: reference_rtol times the force scale, the larger
/// of the gross residual of the zero state and the force level of X (convergenceTest).
PetscErrorCode forceTarget(Run &run, Vec X, double *target)
{
  double level = 0.0;
  PetscFunctionBeginUser;
  PetscCall(forceLevel(run, X, &level));
  *target = run.reference_rtol * std::max(run.zero_state_scale, level);
  PetscFunctionReturn(0);
}

/// Whether the last Newton update (lambda Y) is at round-off of every field:
/// |lambda Y_f| <= 1e-12 |X_f| for displacement, pressure and interface pressure alike.
PetscErrorCode updateAtRoundOff(Run &run, SNES snes, bool *round_off)
{
  Vec X, Y;
  SNESLineSearch ls;
  PetscReal lambda;
  PetscInt nf;
  char **names;
  IS *fields;
  PetscFunctionBeginUser;
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(SNESGetSolutionUpdate(snes, &Y));
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(SNESLineSearchGetLambda(ls, &lambda));
  PetscCall(DMCreateFieldIS(run.dm, &nf, &names, &fields));
  *round_off = true;
  for (PetscInt f = 0; f < nf; ++f) {
    Vec xf, yf;
    PetscReal nx, ny;
    PetscCall(VecGetSubVector(X, fields[f], &xf));
    PetscCall(VecGetSubVector(Y, fields[f], &yf));
    PetscCall(VecNorm(xf, NORM_2, &nx));
    PetscCall(VecNorm(yf, NORM_2, &ny));
    PetscCall(VecRestoreSubVector(Y, fields[f], &yf));
    PetscCall(VecRestoreSubVector(X, fields[f], &xf));
    if (std::fabs(lambda) * ny > 1e-12 * nx) *round_off = false;
    PetscCall(ISDestroy(&fields[f]));
    PetscCall(PetscFree(names[f]));
  }
  PetscCall(PetscFree(fields));
  PetscCall(PetscFree(names));
  PetscFunctionReturn(0);
}

/// Norm of the force (displacement) rows of the residual F. Their index set is made once per
/// run (DMCreateFieldIS at every step cost 0.24 ms per step on the coarse 3D Terzaghi column,
/// +9 % of its stepping).
PetscErrorCode forceRowsNorm(Run &run, Vec F, double *norm)
{
  PetscFunctionBeginUser;
  if (!run.force_rows) {
    PetscInt nf;
    char **names;
    IS *fields;
    PetscCall(DMCreateFieldIS(run.dm, &nf, &names, &fields));
    for (PetscInt f = 0; f < nf; ++f) {
      if (std::string(names[f]) == "displacement" && !run.force_rows) {
        run.force_rows = fields[f];
        PetscCall(PetscObjectReference((PetscObject)run.force_rows));
      }
      PetscCall(ISDestroy(&fields[f]));
      PetscCall(PetscFree(names[f]));
    }
    PetscCall(PetscFree(fields));
    PetscCall(PetscFree(names));
  }
  *norm = 0.0;
  if (!run.force_rows) PetscFunctionReturn(0);
  Vec ff;
  PetscReal n;
  PetscCall(VecGetSubVector(F, run.force_rows, &ff));
  PetscCall(VecNorm(ff, NORM_2, &n));
  PetscCall(VecRestoreSubVector(F, run.force_rows, &ff));
  *norm = n;
  PetscFunctionReturn(0);
}

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
  // A stop from outside between two Newton iterations of a long step (stop_points.cpp).
  PetscCall(stopDuringStep(run, reason));
  if (run.step_abandoned) PetscFunctionReturn(0);
  // A user's -snes_ksp_ew (PETSc's Eisenstat-Walker forcing) wins over ours: PETSc then sets
  // the linear tolerances itself, and we leave them alone.
  PetscBool eisenstat_walker;
  PetscCall(SNESKSPGetUseEW(snes, &eisenstat_walker));
  auto setLinearTolerance = [&](double rtol) -> PetscErrorCode {
    if (eisenstat_walker) return 0;
    return KSPSetTolerances(ksp, rtol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT);
  };
  const double contraction =
      it > 0 && run.newton_last_fnorm > 0.0 ? fnorm / run.newton_last_fnorm : 0.0;
  run.newton_last_fnorm = fnorm;
  if (it == 0) {
    Vec F;
    PetscCall(SNESGetFunction(snes, &F, nullptr, nullptr));
    run.newton_first_fnorm = fnorm;
    PetscCall(forceRowsNorm(run, F, &run.newton_first_force_fnorm));
    // The target is known before the first solve too: a step that ends in one Newton
    // iteration (steady sliding, late consolidation) needs its solve a hundred times below
    // the target, not to -ksp_rtol (whole 37k caisson run, fieldsplit preset: 59 -> 37 outer
    // iterations in each such step).
    // (Not computed for a direct solve, whose tolerance means nothing: -ksp_type preonly.)
    PetscBool direct = PETSC_FALSE;
    PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPPREONLY, &direct));
    double target = 0.0;
    if (!eisenstat_walker && !direct && fnorm > 0.0) {
      Vec X;
      PetscCall(SNESGetSolution(snes, &X));
      PetscCall(forceTarget(run, X, &target));
    }
    PetscCall(setLinearTolerance(
        linearTolerance(run.ksp_rtol, fnorm > 0.0 ? target / fnorm : 0.0, run.first_contraction)));
    PetscFunctionReturn(0);
  }
  // PETSc's small-update test (snorm < stol |x|) alone is no convergence here: |x| holds
  // absolute pore pressures (hydrostatic included) and metres side by side, so it passes
  // whenever the pressures are large, whatever the forces still out of balance (measured: a
  // joint column step accepted with its residual 15 times above the target). It counts only
  // when the update of every field is at round-off of that field (updateAtRoundOff): then
  // Newton cannot do better and the residual is at its floor (e.g. bodies with E = 1e20).
  const bool small_update = *reason == SNES_CONVERGED_SNORM_RELATIVE;
  if (small_update) *reason = SNES_CONVERGED_ITERATING;
  // PETSc's relative test (fnorm < -snes_rtol times the first residual) is measured against
  // the first residual of the force rows when the water rows made up the first residual
  // (1e3 times the force rows' part or more). Those rows are scaled by dt, so that a pressure
  // that jumps at the start of a long step makes them 1e17 - 1e21 against forces of 1e6, and
  // 1e-12 of that says nothing of the forces: measured on Sneddon's crack with dt = 1e6 s, the
  // test accepted the first Newton iterate, its crack still held shut (the opening 99.97 %
  // short). A step that starts with the forces out of balance (a displacement-driven step of
  // a stiff body) keeps PETSc's test as it is.
  if (*reason == SNES_CONVERGED_FNORM_RELATIVE &&
      run.newton_first_fnorm > 1e3 * run.newton_first_force_fnorm) {
    PetscReal rtol;
    PetscCall(SNESGetTolerances(snes, nullptr, &rtol, nullptr, nullptr, nullptr));
    if (!(fnorm <= rtol * run.newton_first_force_fnorm)) {
      PetscCall(PetscInfo(snes,
                          "poroseam: residual %g below -snes_rtol of the first one, %g, "
                          "but not of its force rows' part, %g: iterating on\n",
                          (double)fnorm, run.newton_first_fnorm, run.newton_first_force_fnorm));
      *reason = SNES_CONVERGED_ITERATING;
    }
  }
  if (*reason != SNES_CONVERGED_ITERATING) PetscFunctionReturn(0);
  Vec X;
  double target = 0.0;
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(forceTarget(run, X, &target));
  PetscCall(PetscInfo(snes, "poroseam: residual %g, target %g\n", (double)fnorm, target));
  const bool converged = target > 0.0 && fnorm <= target;
  if (it == 1) run.first_contraction = converged ? 0.0 : contraction;
  bool round_off = false;
  if (!converged && small_update) PetscCall(updateAtRoundOff(run, snes, &round_off));
  if (converged) {
    *reason = SNES_CONVERGED_FNORM_ABS;
  } else if (round_off) {
    PetscCall(PetscInfo(snes, "poroseam: update at round-off, residual %g at its floor\n",
                        (double)fnorm));
    *reason = SNES_CONVERGED_SNORM_RELATIVE;
  } else if (small_update && contraction >= 1.0) {
    // Stalled: a small update that did not lower the residual. Iterating on repeats it up to
    // -snes_max_it; fail now so that the step is cut back (or the run stops) at once.
    PetscCall(PetscInfo(snes, "poroseam: stalled at residual %g above the target %g\n",
                        (double)fnorm, target));
    *reason = SNES_DIVERGED_LOCAL_MIN;
  } else if (fnorm > 0.0) {
    PetscCall(setLinearTolerance(linearTolerance(run.ksp_rtol, target / fnorm, contraction)));
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

namespace {

/// W = X - lambda Y, G = F(W) and its norm; false on a domain error.
PetscErrorCode evaluateAt(SNES snes, Vec X, Vec Y, double lambda, Vec W, Vec G, double *norm,
                          bool *ok)
{
  PetscBool domain;
  PetscReal n;
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(W, -lambda, Y, X));
  PetscCall(SNESComputeFunction(snes, W, G));
  PetscCall(SNESGetFunctionDomainError(snes, &domain));
  *ok = !domain;
  if (domain) PetscFunctionReturn(0);
  PetscCall(VecNorm(G, NORM_2, &n));
  *ok = !PetscIsInfOrNanReal(n);
  *norm = n;
  PetscFunctionReturn(0);
}

/// Where some interface point changes branch on the step from X to X - Y, over all ranks,
/// sorted, in (0, 1).
PetscErrorCode stepKinks(Run &run, Vec X, Vec Y, Vec W, std::vector<double> &kinks)
{
  Vec lx, lw;
  PetscFunctionBeginUser;
  kinks.clear();
  PetscCall(VecWAXPY(W, -1.0, Y, X));
  PetscCall(DMGetLocalVector(run.dm, &lx));
  PetscCall(DMGetLocalVector(run.dm, &lw));
  PetscCall(DMGlobalToLocal(run.dm, X, INSERT_VALUES, lx));
  PetscCall(DMGlobalToLocal(run.dm, W, INSERT_VALUES, lw));
  PetscCall(run.problem.insertBoundaryValues(run.stage_time, lx));
  PetscCall(run.problem.insertBoundaryValues(run.stage_time, lw));
  std::vector<double> local;
  PetscCall(run.problem.interfaces().stateChanges(lx, lw, local));
  PetscCall(DMRestoreLocalVector(run.dm, &lw));
  PetscCall(DMRestoreLocalVector(run.dm, &lx));
  std::sort(local.begin(), local.end());
  local.erase(std::unique(local.begin(), local.end()), local.end());
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscMPIInt size, n = (PetscMPIInt)local.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size, 0);
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r)
    offsets[r] = offsets[r - 1] + counts[r - 1];
  kinks.resize(offsets[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(local.data(), n, MPI_DOUBLE, kinks.data(), counts.data(),
                              offsets.data(), MPI_DOUBLE, comm));
  std::sort(kinks.begin(), kinks.end());
  std::vector<double> distinct;
  for (double s : kinks)
    if (s < 1.0 - 1e-9 && (distinct.empty() || s > distinct.back() + 1e-9)) distinct.push_back(s);
  kinks.swap(distinct);
  PetscFunctionReturn(0);
}

} // namespace

/// Line search for scenes with contact interfaces or plastic regions (-snes_kink_linesearch, on
/// by default there).
///
/// The contact law is piecewise linear in the displacements: penalty contact or none, stick or
/// Coulomb slip. Newton's model of a step is exact up to the first point that changes branch;
/// a full step that crosses many such kinks can land where the real residual is larger, and
/// from there Newton may jump back: measured, the axisymmetric caisson with mu = 10 cycled
/// between two residuals (2.3e6, 2.7e7) for 400 iterations with the full step ('basic'), and
/// with backtracking ('bt') crept forward by 1 % per iteration (its smooth interpolation picks
/// lambda ~ 0.01, well before the first kink, so the next direction is the same). Here:
///   1. the full step, if it lowers the residual norm (Armijo, 1e-4);
///   2. otherwise the residual is evaluated just past each kink on the step, in order (at most
///      12, spread over them), while it keeps falling; the lowest is taken. Up to the first kink
///      Newton's model holds, so the norm falls there by the step's fraction at least, and the
///      next Jacobian sees the points that changed branch;
///   3. otherwise (smooth non-linearity: the cubic law, storage) halving from 1/2 to 1/1024.
/// A step that lowers the residual nowhere fails the line search (the time step is cut back).
PetscErrorCode kinkLineSearch(SNESLineSearch ls, void *ctx)
{
  Run &run = *static_cast<Run *>(ctx);
  SNES snes;
  Vec X, F, Y, W, G;
  PetscReal xnorm, fnorm, ynorm;
  PetscFunctionBeginUser;
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  PetscCall(SNESLineSearchGetNorms(ls, &xnorm, &fnorm, &ynorm));
  PetscCall(VecNorm(Y, NORM_2, &ynorm));
  PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_SUCCEEDED));
  const double armijo = 1e-4;
  double lambda = 1.0, gnorm = 0.0;
  bool ok;
  PetscCall(evaluateAt(snes, X, Y, 1.0, W, G, &gnorm, &ok));
  if (!ok) {
    PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_DOMAIN));
    PetscFunctionReturn(0);
  }
  bool accepted = gnorm <= (1.0 - armijo) * fnorm;
  if (!accepted) {
    std::vector<double> kinks;
    PetscCall(stepKinks(run, X, Y, W, kinks));
    // Candidates just past each kink (inside the next piece), at most 12 spread over them.
    std::vector<double> candidates;
    const size_t nk = kinks.size(), max_candidates = 12;
    for (size_t j = 0; j < std::min(nk, max_candidates); ++j) {
      const size_t i = nk <= max_candidates ? j : (j * (nk - 1)) / (max_candidates - 1);
      const double next = i + 1 < nk ? kinks[i + 1] : 1.0;
      candidates.push_back(kinks[i] + 1e-3 * (next - kinks[i]));
    }
    double best = fnorm, best_lambda = 0.0, previous = fnorm, value = 0.0, last = 0.0;
    for (double c : candidates) {
      PetscCall(evaluateAt(snes, X, Y, c, W, G, &value, &ok));
      last = ok ? c : 0.0;
      if (!ok) break;
      PetscCall(PetscInfo(snes, "poroseam: kink search lambda %g residual %g\n", c, value));
      if (value < best) best = value, best_lambda = c;
      if (value > previous) break;
      previous = value;
    }
    if (best_lambda > 0.0 && best <= (1.0 - armijo * best_lambda) * fnorm) {
      lambda = best_lambda, accepted = true;
      if (last != best_lambda) PetscCall(evaluateAt(snes, X, Y, lambda, W, G, &value, &ok));
      gnorm = best;
    }
    for (double c = 0.5; !accepted && c >= 1.0 / 1024.0; c *= 0.5) {
      PetscCall(evaluateAt(snes, X, Y, c, W, G, &value, &ok));
      if (ok && value <= (1.0 - armijo * c) * fnorm) lambda = c, gnorm = value, accepted = true;
    }
    PetscCall(PetscInfo(snes, "poroseam: %zu kinks on the step; lambda %g, residual %g -> %g\n", nk,
                        accepted ? lambda : 0.0, (double)fnorm, accepted ? gnorm : fnorm));
  }
  if (!accepted) {
    // No point of the step lowers the residual. If the iterate already meets the force test
    // (a start at equilibrium to round-off, whose Newton step is round-off amplified by a
    // penalty-stiff tangent: measured with K_N = K_T = 1e14), it stays: a zero step, which
    // convergenceTest then accepts. Otherwise the line search fails.
    double target = 0.0;
    PetscCall(forceTarget(run, X, &target));
    if (!(fnorm <= target)) {
      PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_REDUCT));
      PetscFunctionReturn(0);
    }
    PetscCall(PetscInfo(snes, "poroseam: no decrease, iterate meets the target: zero step\n"));
    PetscCall(SNESLineSearchSetLambda(ls, 0.0));
    PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, 0.0));
    PetscFunctionReturn(0);
  }
  PetscCall(VecCopy(W, X));
  PetscCall(VecCopy(G, F));
  PetscCall(SNESLineSearchSetLambda(ls, lambda));
  PetscCall(VecNorm(X, NORM_2, &xnorm));
  PetscCall(SNESLineSearchSetNorms(ls, xnorm, gnorm, lambda * ynorm));
  PetscFunctionReturn(0);
}

PetscErrorCode configureLineSearch(Run &run, SNES snes)
{
  // Also for skeleton laws with history (plasticity): their returns are kinks too (not located
  // on the step, so the search halves), and the full step can overshoot into another branch
  // (measured on tests/plasticity/element.py --case undrained: with 'basic' the step where the
  // element yields diverged for 50 iterations and was cut back 5 times; with this search the
  // 40 steps take 8 Newton iterations in all, none cut back).
  PetscBool use =
      run.scene.interfaces.empty() && !run.problem.hasSkeletonHistory() ? PETSC_FALSE : PETSC_TRUE;
  SNESLineSearch ls;
  PetscFunctionBeginUser;
  PetscOptionsBegin(PetscObjectComm((PetscObject)snes), nullptr, "poroseam line search",
                    "docs/scenes.md");
  const OptionSpec &option = spec(Option::snes_kink_linesearch);
  PetscCall(PetscOptionsBool(option.flag, option.help, option.doc, use, &use, nullptr));
  PetscOptionsEnd();
  if (!use) PetscFunctionReturn(0);
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHSHELL));
  PetscCall(SNESLineSearchShellSetUserFunc(ls, kinkLineSearch, &run));
  PetscFunctionReturn(0);
}

PetscErrorCode configureKeepPreconditioner(Run &run, SNES snes)
{
  PetscInt lag;
  PetscFunctionBeginUser;
  PetscOptionsBegin(PetscObjectComm((PetscObject)snes), nullptr, "poroseam linear solver reuse",
                    "docs/performance.md");
  const OptionSpec &option = spec(Option::snes_keep_preconditioner);
  PetscCall(PetscOptionsBool(option.flag, option.help, option.doc, run.keep_preconditioner,
                             &run.keep_preconditioner, nullptr));
  PetscOptionsEnd();
  PetscCall(SNESGetLagPreconditioner(snes, &lag)); // the user's own lag wins over keeping it
  if (lag != 1) run.keep_preconditioner = PETSC_FALSE;
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
