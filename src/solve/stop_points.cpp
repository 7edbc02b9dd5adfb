// Where a run looks for a stop from outside (stop_request.hpp), and what it leaves then:
// after each accepted step (its checkpoint written, run.yaml noting it, the step line
// printed without blocking) and between two Newton iterations of a long step.

#include "run.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace poroseam {
namespace simulation_detail {

namespace {

/// Rank 0: the record of the run after its last accepted step, and the one a stop signal
/// leaves (armed for the handler).
void noteProgress(Run &run, double t)
{
  int rank = 0;
  MPI_Comm_rank(PetscObjectComm((PetscObject)run.dm), &rank);
  if (rank != 0 || !run.record) return;
  RunProgress progress;
  progress.step = run.step;
  progress.time = t;
  progress.checkpoint = run.latest_checkpoint;
  // A record that cannot be written now is not the end of the run: the final one, written
  // collectively, says so if the disk still refuses.
  (void)run.record->progress(progress);
  StopRequest::armRecord(run.record->path(), run.record->textIfStopped(StopRequest::kSignalMark));
}

} // namespace

PetscErrorCode noteStart(Run &run)
{
  PetscFunctionBeginUser;
  PetscCall(TSGetTimeStep(run.ts, &run.accepted_next_dt));
  noteProgress(run, run.loop_start_time);
  PetscFunctionReturn(0);
}

PetscErrorCode noteAcceptedStep(Run &run, const StepRow &row, bool kept)
{
  PetscFunctionBeginUser;
  PetscCall(TSGetTimeStep(run.ts, &run.accepted_next_dt));
  noteProgress(run, row.time);
  // The coming steps: the nominal size at fixed steps (a cut step grows back within a few
  // steps), the controller's choice at adaptive steps.
  run.time_to_finish.addStep(row.wall);
  const std::string eta = formatDuration(run.time_to_finish.seconds(
      row.time, run.t_end, run.time.adaptive() ? run.accepted_next_dt : run.nominal_dt));
  char line[512];
  std::snprintf(line, sizeof(line),
                "step %4d  t %11.5e/%.5e s  dt %10.4e  load %6.4f  newton %2d  krylov %4d%s"
                "  %.2f s  eta %s%s\n",
                row.step, row.time, run.t_end, row.dt, row.load, row.newton, row.krylov,
                row.rejected ? "  (cut back)" : "", row.wall, eta.c_str(),
                kept ? "  checkpoint" : "");
  run.progress_line.print(PetscObjectComm((PetscObject)run.dm), line, StopRequest::received);
  PetscFunctionReturn(0);
}

PetscErrorCode delayStepForTests(const Run &run)
{
  PetscFunctionBeginUser;
  // From step -test_step_delay_after on: waits like a long computation that no signal
  // interrupts (a sleep ends early on a signal: sleep again until the time is up).
  if (run.step < run.step_delay_after) PetscFunctionReturn(0);
  for (const double end = MPI_Wtime() + run.step_delay; MPI_Wtime() < end;)
    usleep(10000);
  PetscFunctionReturn(0);
}

PetscErrorCode stopAfterStep(Run &run, TSConvergedReason reason)
{
  int signal = 0;
  PetscFunctionBeginUser;
  PetscCall(run.stop.pending(PetscObjectComm((PetscObject)run.ts), &signal));
  // Unless this was the last step anyway.
  if (signal && reason == TS_CONVERGED_ITERATING) {
    run.stop_signal = signal;
    PetscCall(TSSetConvergedReason(run.ts, TS_CONVERGED_USER));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode stopDuringStep(Run &run, SNESConvergedReason *reason)
{
  int signal = 0;
  PetscFunctionBeginUser;
  if (!run.ts) PetscFunctionReturn(0);
  PetscCall(run.stop.pending(PetscObjectComm((PetscObject)run.ts), &signal));
  if (!signal) PetscFunctionReturn(0);
  // A step that has just converged is kept only if the last accepted one is not on disk: one
  // checkpoint must be written anyway, and this step's is as quick. Otherwise accepting it
  // would mean writing another checkpoint in the second mpiexec leaves before its SIGKILL
  // (measured: 0.6-1.5 s per checkpoint with the machine loaded), and being killed while at it.
  if (*reason > 0 && run.checkpoint_step != run.step) PetscFunctionReturn(0);
  // TS leaves its step loop when it has a reason: the step is neither retried nor accepted
  // (postStep records nothing of it).
  run.stop_signal = signal;
  run.step_abandoned = true;
  *reason = SNES_DIVERGED_FUNCTION_COUNT; // PETSc 3.18 has no reason of a user's own
  PetscCall(TSSetConvergedReason(run.ts, TS_CONVERGED_USER));
  PetscFunctionReturn(0);
}

PetscErrorCode restoreAbandonedStep(Run &run, Vec X)
{
  PetscFunctionBeginUser;
  if (!run.step_abandoned) PetscFunctionReturn(0);
  // run.previous is the last accepted state (with its boundary values); the step size is the
  // one chosen after it (the failed attempt may have cut it).
  PetscCall(DMLocalToGlobal(run.dm, run.previous, INSERT_VALUES, X));
  if (run.accepted_next_dt > 0.0) PetscCall(TSSetTimeStep(run.ts, run.accepted_next_dt));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
