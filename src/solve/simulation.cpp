// One run from its options to its end (simulate, runSimulation), as the sequence of its steps:
// the set-up (run_setup.cpp), the time stepper and its solvers (time_stepper_setup.cpp), the
// outputs (run_outputs.cpp), the time loop (time_loop.cpp) and its ending (run_ending.cpp); the
// steps are declared in run_steps.hpp. What TS calls inside a step is in step_callbacks.cpp.
#include "poroseam/simulation.hpp"

#include "run_steps.hpp"

#include "poroseam/option_listing.hpp"
#include "poroseam/unused_options.hpp"

#include <petscts.h>
#include <string>
#include <vector>

namespace poroseam {
namespace simulation_detail {

/// The run's vectors, time stepper and mesh, at its end (or after -help's listing).
PetscErrorCode releaseRun(Run &run, Vec *X)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&run.last_increment));
  PetscCall(VecDestroy(X));
  PetscCall(VecDestroy(&run.previous));
  PetscCall(VecDestroy(&run.jacobian_diagonal));
  PetscCall(ISDestroy(&run.force_rows));
  PetscCall(run.steady.destroy());
  PetscCall(VecDestroy(&run.initial));
  PetscCall(run.time.destroy());
  PetscCall(run.problem.release());
  PetscCall(TSDestroy(&run.ts));
  PetscCall(DMDestroy(&run.dm));
  PetscFunctionReturn(0);
}

/// The run: set-up, time loop, ending; run.yaml through `record`. The order of the steps is
/// that of PETSc's option reads and object creation: keep it.
PetscErrorCode simulate(MPI_Comm comm, Run &run, RunRecord &record)
{
  PetscFunctionBeginUser;
  RestartOptions restart;
  PetscCall(readRunOptions(comm, run, &restart));
  run.record = &record;
  if (restart.restart) run.scene.output_dir = restart.dir; // the run continues where it was
  // -help: set up as far as every option is read (PETSc lists each with its value), write
  // nothing to the output directory, stop before the first step (option_listing.hpp).
  bool listing = false;
  OptionListing scratch; // removed when this function returns, also after an error
  const std::string output_dir = run.scene.output_dir;
  PetscCall(listingOptions(&listing));
  if (listing) {
    restart = RestartOptions();
    PetscCall(scratch.begin(comm, &run.scene.output_dir));
  }
  std::string checkpoint_path; // the one a restart continues from
  PetscCall(prepareOutputDirectory(comm, run, restart, record, &checkpoint_path));
  PetscCall(loadMesh(comm, run));

  PetscCall(beginLogPhase(run.events.layout));
  PetscCall(layOutUnknowns(comm, run, record));
  Vec X;
  CheckpointInfo resumed;
  PetscCall(createInitialState(run, restart.restart ? &checkpoint_path : nullptr, &X, &resumed));
  SNES snes;
  PetscCall(createTimeStepper(comm, run, &snes));
  PetscCall(configureNewton(comm, run, snes));
  PetscCall(applySolverOptions(comm, run, snes));
  if (restart.restart) PetscCall(resumeTimeStepper(comm, run, resumed, checkpoint_path));
  bool checkpoints; // whether the time integrator can write them
  PetscCall(startTimeIntegration(comm, run, restart.restart, &checkpoints));
  if (listing) {
    PetscCall(endLogPhase(run.events.layout));
    PetscCall(releaseRun(run, &X));
    PetscCall(scratch.end(comm, output_dir));
    PetscFunctionReturn(0);
  }
  if (restart.restart)
    PetscCall(PetscPrintf(comm, "restart from %s: step %d, t = %g s; output continues in %s\n",
                          checkpoint_path.c_str(), resumed.step, resumed.time,
                          run.scene.output_dir.c_str()));
  PetscCall(setUpSolvers(comm, run, X, snes));
  PetscCall(measureForceScale(run));
  PetscCall(openOutputs(comm, run, restart.restart ? &resumed : nullptr));
  if (!restart.restart) PetscCall(recordInitialState(run));
  int first_step;
  PetscCall(prepareTimeLoop(run, &first_step));
  PetscCall(endLogPhase(run.events.layout));

  PetscCall(runTimeLoop(run, X));
  std::string message; // empty: the run reached its final time
  RunEnding ending;
  PetscCall(describeEnding(run, X, checkpoints, &message, &ending));
  PetscCall(recordEnding(comm, run, record, first_step, ending, message));
  PetscCall(closeOutputs(run));
  PetscCall(releaseRun(run, &X));
  PetscCall(reportUnusedOptions(comm));
  PetscCheck(message.empty(), comm, PETSC_ERR_NOT_CONVERGED, "%s", message.c_str());
  PetscFunctionReturn(0);
}

} // namespace simulation_detail

PetscErrorCode runSimulation(MPI_Comm comm, const std::vector<std::string> &typed_options)
{
  using namespace simulation_detail;
  Run run;
  RunRecord record;
  PetscFunctionBeginUser;
  run.unused_options.typed = typed_options;
  const PetscErrorCode error = simulate(comm, run, record);
  // An error anywhere after the record's start still ends it (failed steps, step limits and
  // signals have ended it already, with their summary).
  if (error) {
    StopRequest::disarmRecord(); // a signal from now on must not overwrite this ending
    record.abandon(error);
  }
  PetscCall(error);
  PetscFunctionReturn(0);
}

} // namespace poroseam
