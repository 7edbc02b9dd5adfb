// The callbacks PETSc's time stepper calls during a step: boundary values and their rates,
// the residual and Jacobian of the discrete system (DMTS local functions), and the post-step
// hook that records, commits and checkpoints each accepted step. Apart from the run's steps
// (simulation.cpp, run_steps.hpp), which set the run up and drive TSSolve, because these run
// inside TSSolve, once per stage or step. Internal to src/solve (declared in run.hpp).
#include "run.hpp"

#include "checkpoint.hpp"
#include "rolling_checkpoint.hpp"

#include "poroseam/log_events.hpp"
#include "poroseam/time_integration.hpp"

#include <algorithm>
#include <petscts.h>
#include <string>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode boundaryLocal(DM, PetscReal t, Vec local, Vec local_rate, void *ctx)
{
  Run &run = *static_cast<Run *>(ctx);
  RateStencil stencil;
  double since;
  PetscFunctionBeginUser;
  PetscCall(run.problem.insertBoundaryValues(t, local));
  if (!local_rate) PetscFunctionReturn(0);
  // PETSc differentiates the unknowns only: prescribed values get the integrator's formula.
  PetscCall(run.time.stencil(run.ts, t, run.previous, &stencil, &since));
  PetscCall(run.problem.insertBoundaryRates(t, stencil, local_rate));
  PetscFunctionReturn(0);
}

PetscErrorCode iFunctionLocal(DM, PetscReal t, Vec local, Vec local_rate, Vec f, void *ctx)
{
  Run &run = *static_cast<Run *>(ctx);
  double dt;
  PetscFunctionBeginUser;
  PetscCall(currentDt(run, &dt));
  // Rates of prescribed values are in local_rate already (boundaryLocal, which PETSc calls
  // before this); the non-linear rates need only the time since the last accepted state.
  const double since = run.time.sinceAccepted(t);
  if (run.capture_rate) {
    PetscCall(VecCopy(local_rate, run.capture_rate));
    PetscCall(VecSet(f, 0.0));
    PetscFunctionReturn(0);
  }
  run.attempted_dt = dt;
  run.stage_time = t;
  PetscCall(delayStepForTests(run));
  if (run.fail_dt_above > 0.0 && dt > run.fail_dt_above) {
    // Test hook standing in for a step too large to converge (see -test_fail_dt_above).
    SNES snes;
    PetscCall(TSGetSNES(run.ts, &snes));
    PetscCall(SNESSetFunctionDomainError(snes));
  }
  // The mass balance scaled by the step (a constant factor per step: rows in force units);
  // rates of non-linear quantities over the time since the last accepted state.
  const double mass_scale = -dt * run.problem.massBalanceScale();
  PetscCall(run.problem.residual(t, local, local_rate, ResidualMode{mass_scale, true, since}, f));
  PetscFunctionReturn(0);
}

PetscErrorCode iJacobianLocal(DM, PetscReal t, Vec local, Vec local_rate, PetscReal shift, Mat J,
                              Mat P, void *ctx)
{
  Run &run = *static_cast<Run *>(ctx);
  double dt;
  PetscFunctionBeginUser;
  PetscCall(currentDt(run, &dt));
  const double since = run.time.sinceAccepted(t);
  // The first assembly also sets up the matrix's communication: part of the set-up cost.
  const bool first = !run.jacobian_assembled;
  if (first) PetscCall(beginLogEvent(run.events.first_jacobian));
  PetscCall(run.problem.jacobian(t, shift, local, local_rate,
                                 ResidualMode{-dt * run.problem.massBalanceScale(), true, since},
                                 P));
  if (run.jacobian_diagonal) PetscCall(MatGetDiagonal(P, run.jacobian_diagonal));
  if (first) PetscCall(endLogEvent(run.events.first_jacobian));
  if (run.keep_preconditioner) {
    // A linear scene at a fixed step has one Jacobian: factorising it at every step was most
    // of the stepping time (a 3D column at order 2, docs/performance.md). SNES decides right
    // after this callback whether the KSP keeps its preconditioner, from the lag: -1 keeps
    // it, 1 rebuilds it. A new step size, BDF's start-up, or a restart builds it afresh.
    SNES snes;
    PetscCall(TSGetSNES(run.ts, &snes));
    PetscCall(SNESSetLagPreconditioner(snes, run.problem.jacobianRepeated() ? -1 : 1));
  }
  run.jacobian_assembled = true;
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

/// Makes the next linear solve set up its direct (LU/Cholesky) preconditioner afresh.
PetscErrorCode resetDirectSolver(TS ts)
{
  SNES snes;
  KSP ksp;
  PC pc;
  PetscBool direct;
  PetscFunctionBeginUser;
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &direct, PCLU, PCCHOLESKY, ""));
  if (direct) PetscCall(PCReset(pc));
  PetscFunctionReturn(0);
}

PetscErrorCode postStep(TS ts)
{
  void *ctx;
  PetscFunctionBeginUser;
  PetscCall(TSGetApplicationContext(ts, &ctx));
  Run &run = *static_cast<Run *>(ctx);
  TSConvergedReason reason;
  PetscCall(TSGetConvergedReason(ts, &reason));
  // TS calls this after a failed step too, and after one abandoned for a stop: record nothing
  if (reason < 0 || run.step_abandoned) PetscFunctionReturn(0);
  ++run.step;
  double t, t_previous;
  PetscCall(TSGetTime(ts, &t));
  PetscCall(settleOnFinalTime(ts, &t)); // the last step ends on -ts_max_time exactly
  PetscCall(TSGetConvergedReason(ts, &reason));
  PetscCall(TSGetPrevTime(ts, &t_previous));
  const double dt = t - t_previous; // the step just taken (after any cut-back)
  Vec X, local, rate;
  PetscCall(TSGetSolution(ts, &X));
  PetscCall(DMGetLocalVector(run.dm, &local));
  PetscCall(DMGetLocalVector(run.dm, &rate));
  PetscCall(DMGlobalToLocal(run.dm, X, INSERT_VALUES, local));
  PetscCall(run.problem.insertBoundaryValues(t, local));
  if (!run.time.bdf()) {
    // Backward Euler's own rate: the difference with the last accepted state.
    PetscCall(VecWAXPY(rate, -1.0, run.previous, local));
    PetscCall(VecScale(rate, 1.0 / dt));
  } else {
    // The rates the outputs report (fluxes with storage, gap storage rate) are BDF's own at
    // the accepted state: its nonlinear function evaluated there (its shift and history are
    // those of the step just taken) hands them to iFunctionLocal. (Not for TSTHETA, whose
    // function differentiates against a start state it has already moved on.)
    SNES snes;
    Vec F;
    PetscCall(TSGetSNES(ts, &snes));
    PetscCall(DMGetGlobalVector(run.dm, &F));
    run.capture_rate = rate;
    PetscCall(SNESComputeFunction(snes, X, F));
    run.capture_rate = nullptr;
    PetscCall(DMRestoreGlobalVector(run.dm, &F));
  }

  PetscInt snes_its, ksp_its, rejects;
  PetscCall(TSGetSNESIterations(ts, &snes_its));
  PetscCall(TSGetKSPIterations(ts, &ksp_its));
  PetscCall(TSGetStepRejections(ts, &rejects));
  const PetscInt newton = snes_its - run.last_snes_its, krylov = ksp_its - run.last_ksp_its;
  const PetscInt rejected = rejects - run.last_rejects;
  run.last_snes_its = snes_its, run.last_ksp_its = ksp_its, run.last_rejects = rejects;
  const double wall = MPI_Wtime() - run.step_start;
  // The run's last step: it reached the final time or the step limit (TS has said so; a stop
  // from outside is decided after this, in stopAfterStep, and keeps its state in the checkpoint).
  const bool last = reason != TS_CONVERGED_ITERATING;
  PetscCall(recordStep(run, t, dt, local, rate, newton, krylov, rejected, wall, last));
  if (rejected) ++run.steps_cut_back;
  PetscCall(run.problem.commit(local)); // only accepted steps reach here
  PetscCall(run.time.accept(t, run.previous, X));
  // Newton's extrapolated start of the next step: this step's increment of the unknowns.
  PetscCall(DMLocalToGlobal(run.dm, run.previous, INSERT_VALUES, run.last_increment));
  PetscCall(VecAYPX(run.last_increment, -1.0, X));
  run.last_dt = dt;
  PetscCall(VecCopy(local, run.previous));
  PetscCall(DMRestoreLocalVector(run.dm, &rate));
  PetscCall(DMRestoreLocalVector(run.dm, &local));
  // Fixed steps: after a cut-back the step grows again, by 2 per accepted step, up to the
  // nominal size. Adaptive steps: TSAdapt has chosen the next step.
  // Never past the final time: TS (TS_EXACTFINALTIME_MATCHSTEP) clipped its next step to land
  // on -ts_max_time before this hook ran, and growing it again overshot (measured: a cut first
  // step of 6 s, then 12 s, ended a run with -ts_max_time 12 at t = 18 s).
  if (!run.time.adaptive() && dt < run.nominal_dt) {
    double next = std::min(run.nominal_dt, 2.0 * dt);
    if (run.t_end - t > 0.0) next = std::min(next, run.t_end - t);
    PetscCall(TSSetTimeStep(ts, next));
  }
  // A kept checkpoint every checkpoint_every steps; otherwise the rolling one of this step
  // (rolling_checkpoint.hpp), so that a stop from outside finds this step on disk.
  const bool checkpoint = run.checkpoint_every > 0 && run.step % run.checkpoint_every == 0;
  PetscCall(beginLogEvent(run.events.output));
  if (checkpoint) {
    std::string path;
    PetscCall(writeCheckpoint(run, X, &path));
    run.checkpoint_step = run.step;
    run.latest_checkpoint = path;
    PetscCall(dropRollingCheckpoint(run));
    // A run restarted here factors its first matrix from scratch, and the direct solver's
    // pivot order depends on that matrix's values (MUMPS's analysis); it would differ at
    // round-off from this run, which reuses its analysis of step 1. Redo ours at the next step
    // too, so that a restart continues this very computation.
    PetscCall(resetDirectSolver(ts));
  } else {
    PetscCall(updateRollingCheckpoint(run, X, wall));
  }
  PetscCall(endLogEvent(run.events.output));
  PetscCall(noteAcceptedStep(run,
                             StepRow{run.step, t, dt, run.problem.loadFactor(t), (int)newton,
                                     (int)krylov, (int)rejected, wall},
                             checkpoint));
  PetscCall(stopAfterStep(run, reason));
  run.step_start = MPI_Wtime();
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
