// The time stepper of a run and its solvers (split from simulate, simulation.cpp): PETSc's TS
// with poroseam's callbacks, Newton's options and convergence test, the user's solver options
// and what depends on them, the position a restart continues from, the time integrator, and
// the set-up TSSolve would do at its first step. The order of these calls is the order in
// which PETSc reads the options (-help, -options_left): keep it.
#include "run_steps.hpp"

#include "poroseam/option_registry.hpp"

#include "restart_check.hpp"

#include "poroseam/mass_balance_test.hpp"
#include "poroseam/nullspace.hpp"
#include "poroseam/petsc_choices.hpp"
#include "poroseam/run_options.hpp"
#include "poroseam/schur_selfp.hpp"
#include "poroseam/vertex_blocks.hpp"

#include <algorithm>
#include <string>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode createTimeStepper(MPI_Comm comm, Run &run, SNES *snes)
{
  PetscFunctionBeginUser;
  PetscCall(TSCreate(comm, &run.ts));
  PetscCall(TSSetDM(run.ts, run.dm));
  PetscCall(TSSetApplicationContext(run.ts, &run));
  PetscCall(TSSetType(run.ts, TSBEULER));
  PetscCall(TSSetProblemType(run.ts, TS_NONLINEAR));
  PetscCall(DMTSSetBoundaryLocal(run.dm, boundaryLocal, &run));
  PetscCall(DMTSSetIFunctionLocal(run.dm, iFunctionLocal, &run));
  PetscCall(DMTSSetIJacobianLocal(run.dm, iJacobianLocal, &run));
  PetscCall(TSSetTimeStep(run.ts, 1.0));
  PetscCall(TSSetMaxTime(run.ts, 1.0));
  PetscCall(TSSetExactFinalTime(run.ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSSetMaxSNESFailures(run.ts, -1)); // failures are bounded per step by -ts_max_reject
  PetscCall(TSSetMaxStepRejections(run.ts, 8));
  TSAdapt adapt;
  PetscCall(TSGetAdapt(run.ts, &adapt));
  PetscCall(TSAdaptSetScaleSolveFailed(adapt, 0.5));
  PetscCall(TSSetPreStep(run.ts, landOnFinalTime));
  PetscCall(TSSetPostStep(run.ts, postStep));
  PetscCall(TSSetPostStage(run.ts, noteAttempt));    // why an attempt failed (solve_failure.cpp)
  PetscCall(TSSetPreStage(run.ts, announceCutBack)); // a cut-back says so as it happens
  PetscCall(TSGetSNES(run.ts, snes));
  PetscFunctionReturn(0);
}

PetscErrorCode configureNewton(MPI_Comm comm, Run &run, SNES snes)
{
  PetscFunctionBeginUser;
  PetscCall(SNESSetType(snes, SNESNEWTONLS));
  PetscOptionsBegin(comm, nullptr, "poroseam Newton convergence", "docs/scenes.md");
  const OptionSpec &rtol = spec(Option::snes_reference_rtol),
                   &fail_dt = spec(Option::test_fail_dt_above),
                   &delay = spec(Option::test_step_delay),
                   &delay_after = spec(Option::test_step_delay_after);
  PetscCall(PetscOptionsReal(rtol.flag, rtol.help, rtol.doc, run.reference_rtol,
                             &run.reference_rtol, nullptr));
  PetscCall(PetscOptionsReal(fail_dt.flag, fail_dt.help, fail_dt.doc, run.fail_dt_above,
                             &run.fail_dt_above, nullptr));
  PetscCall(PetscOptionsReal(delay.flag, delay.help, delay.doc, run.step_delay, &run.step_delay,
                             nullptr));
  PetscCall(PetscOptionsInt(delay_after.flag, delay_after.help, delay_after.doc,
                            run.step_delay_after, &run.step_delay_after, nullptr));
  PetscOptionsEnd();
  PetscCall(SNESSetConvergenceTest(snes, convergenceTest, &run, nullptr));
  PetscCall(SNESSetComputeInitialGuess(snes, chooseInitialGuess, &run));
  PetscCall(
      SNESSetTolerances(snes, PETSC_DEFAULT, 1e-12, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscFunctionReturn(0);
}

PetscErrorCode applySolverOptions(MPI_Comm comm, Run &run, SNES snes)
{
  PetscFunctionBeginUser;
  PetscCall(registerVertexBlocksPC());
  PetscCall(registerSchurSelfpPC());
  PetscCall(checkPetscChoices(comm)); // -ksp_type gmress: one line, not PETSc's traceback
  PetscCall(readUnusedOptionsOk(comm, &run.unused_options));
  PetscCall(run.time.beforeOptions(run.ts));
  PetscCall(TSSetFromOptions(run.ts));
  PetscCall(checkTimeSteppingOptions(run.ts)); // -ts_max_time/_steps > 0, -ts_max_reject >= 0
  PetscCall(configureFieldSplit(run.ts, run.dm, run.scene, run.problem, &run.jacobian_diagonal));
  PetscCall(configureLineSearch(run, snes));         // contact kinks (newton_control.cpp)
  PetscCall(configureKeepPreconditioner(run, snes)); // linear scenes (newton_control.cpp)
  {
    KSP ksp;
    PetscReal rtol;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(configureMassBalanceTest(ksp, run.dm)); // after the KSP's type and scaling are set
    PetscCall(KSPGetTolerances(ksp, &rtol, nullptr, nullptr, nullptr));
    run.ksp_rtol = rtol;
  }
  PetscCall(TSGetTimeStep(run.ts, &run.nominal_dt));
  PetscCheck(run.nominal_dt > 0.0, comm, PETSC_ERR_USER_INPUT, "-ts_dt %g: must be > 0",
             run.nominal_dt);
  PetscFunctionReturn(0);
}

PetscErrorCode resumeTimeStepper(MPI_Comm comm, Run &run, const CheckpointInfo &resumed,
                                 const std::string &checkpoint_path)
{
  PetscReal t_end;
  PetscFunctionBeginUser;
  PetscCall(TSGetMaxTime(run.ts, &t_end));
  PetscCall(checkFinalTime(comm, t_end, resumed.time, checkpoint_path));
  // Where the checkpoint was: its time, its step count (-ts_max_steps counts all steps),
  // and its next step (smaller than -ts_dt while growing back after a cut-back).
  PetscCall(TSSetTime(run.ts, resumed.time));
  PetscCall(TSSetStepNumber(run.ts, resumed.step));
  PetscCall(TSSetTimeStep(run.ts, std::min(resumed.next_dt, run.nominal_dt)));
  run.step = resumed.step;
  run.checkpoint_step = resumed.step;
  run.latest_checkpoint = checkpoint_path; // kept: not this run's rolling checkpoint
  PetscFunctionReturn(0);
}

PetscErrorCode startTimeIntegration(MPI_Comm comm, Run &run, bool restart, bool *checkpoints)
{
  PetscReal t0;
  PetscFunctionBeginUser;
  PetscCall(TSGetTime(run.ts, &t0));
  PetscCall(run.time.afterOptions(run.ts, run.dm, run.problem, t0, run.initial));
  PetscCall(
      PetscPrintf(comm, "time integration: %s, %s\n", run.time.name(),
                  run.time.adaptive() ? "adaptive steps (-ts_adapt_type basic)" : "fixed steps"));
  // BDF2 and TSAdapt keep their memory (earlier states, the last error) inside PETSc, where a
  // checkpoint cannot reach it: a restart could not continue them exactly.
  *checkpoints = !run.time.bdf() && !run.time.adaptive();
  run.rolling.enabled = run.rolling.enabled && *checkpoints;
  PetscCheck(*checkpoints || (!restart && run.checkpoint_every == 0), comm, PETSC_ERR_USER_INPUT,
             "%s: checkpoints and restarts are supported with backward Euler at fixed steps (the "
             "default); %s%s keeps its history inside PETSc",
             restart ? "-restart" : "-checkpoint_every", run.time.name(),
             run.time.adaptive() ? " with adaptive steps" : "");
  PetscFunctionReturn(0);
}

PetscErrorCode setUpSolvers(MPI_Comm comm, Run &run, Vec X, SNES snes)
{
  PetscFunctionBeginUser;
  PetscCall(TSSetSolution(run.ts, X));
  PetscCall(TSSetUp(run.ts));
  PetscCall(SNESSetUp(snes));
  run.unused_options.ts = run.ts; // -ts_dtt stops here; -fieldsplit_*_pc_typ at the first solve
  PetscCall(checkUnusedOptionsAfterSetUp(comm, &run.unused_options));
  PetscFunctionReturn(0);
}

PetscErrorCode measureForceScale(Run &run)
{
  // The residual of the zero state at t = 0, where weight and initial stresses appear without
  // the pore pressure that balances them.
  Vec zero, f, F;
  PetscReal norm;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(run.dm, &zero));
  PetscCall(DMGetLocalVector(run.dm, &f));
  PetscCall(DMGetGlobalVector(run.dm, &F));
  PetscCall(VecSet(zero, 0.0));
  PetscCall(run.problem.residual(0.0, zero, zero, ResidualMode{1.0, true}, f));
  PetscCall(VecSet(F, 0.0));
  PetscCall(DMLocalToGlobal(run.dm, f, ADD_VALUES, F));
  PetscCall(VecNorm(F, NORM_2, &norm));
  run.zero_state_scale = norm;
  PetscCall(DMRestoreGlobalVector(run.dm, &F));
  PetscCall(DMRestoreLocalVector(run.dm, &f));
  PetscCall(DMRestoreLocalVector(run.dm, &zero));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
