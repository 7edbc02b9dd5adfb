// A run's time loop (split from simulate, simulation.cpp): where and when it starts, and
// PETSc's TSSolve with a stop signal's handler installed. What TS calls inside a step is in
// step_callbacks.cpp; how the loop ended, in run_ending.cpp.
#include "run_steps.hpp"

namespace poroseam {
namespace simulation_detail {

PetscErrorCode prepareTimeLoop(Run &run, int *first_step)
{
  PetscFunctionBeginUser;
  run.step_start = MPI_Wtime();
  run.loop_start_wall = run.step_start;
  PetscCall(TSGetTime(run.ts, &run.loop_start_time));
  run.stage_time = run.loop_start_time; // the state PETSc's monitors view at step 0
  PetscCall(TSGetMaxTime(run.ts, &run.t_end));
  *first_step = run.step;
  // Failed steps end TSSolve with a reason, not an error: describeEnding says what happened.
  PetscCall(TSSetErrorIfStepFails(run.ts, PETSC_FALSE));
  PetscFunctionReturn(0);
}

PetscErrorCode runTimeLoop(Run &run, Vec X)
{
  PetscFunctionBeginUser;
  PetscCall(beginLogPhase(run.events.time_stepping));
  PetscCall(run.stop.install());
  PetscCall(noteStart(run)); // a stop in the first step
  PetscCall(TSSolve(run.ts, X));
  PetscCall(endLogPhase(run.events.time_stepping));
  PetscCall(restoreAbandonedStep(run, X));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
