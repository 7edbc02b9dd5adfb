// The steps of one run, in the order simulate() (simulation.cpp) takes them (internal to
// src/solve): the set-up up to the initial state (run_setup.cpp), the time stepper and its
// solvers (time_stepper_setup.cpp), the outputs (run_outputs.cpp), the time loop
// (time_loop.cpp) and the record of its ending (run_ending.cpp). Split so that simulate() reads
// as its sequence of steps; the order of these calls is the order of PETSc's option reads and
// object creation (-options_left, -help, prefixes), so keep it.
#pragma once

#include "checkpoint.hpp"
#include "run.hpp"

#include "poroseam/run_record.hpp"

#include <petscts.h>
#include <string>

namespace poroseam {
namespace simulation_detail {

// run_setup.cpp: from the options to the initial state.

/// The options read before the mesh: -log_view events, the options as given (what a
/// checkpoint keeps and a restart compares), the mesh's options, -checkpoint_every, -restart
/// and the rolling checkpoint's options.
PetscErrorCode readRunOptions(MPI_Comm comm, Run &run, RestartOptions *restart);
/// Refuses a restart that cannot continue its run (its checkpoint in *checkpoint_path), then
/// creates the output directory, clears an earlier run's files (not on a restart) and begins
/// run.yaml. Collective.
PetscErrorCode prepareOutputDirectory(MPI_Comm comm, Run &run, const RestartOptions &restart,
                                      RunRecord &record, std::string *checkpoint_path);
/// The mesh, the scene's options that need its physical names, the interfaces split, the
/// checks of the whole mesh (on rank 0), then its distribution (-log_view phases "mesh" and
/// "distribution").
PetscErrorCode loadMesh(MPI_Comm comm, Run &run);
/// The unknowns on the distributed mesh: the solution section, the problem, the probes, the
/// boundary dofs; prints the unknowns per field into stdout and run.yaml, and chooses the
/// solver preset from their number.
PetscErrorCode layOutUnknowns(MPI_Comm comm, Run &run, RunRecord &record);
/// The initial state (run.initial, run.previous, the steady pressure) and the solution vector
/// *X made from it; on a restart (`checkpoint_path` not null) X and the run's state come from
/// that checkpoint, described by *resumed.
PetscErrorCode createInitialState(Run &run, const std::string *checkpoint_path, Vec *X,
                                  CheckpointInfo *resumed);

// time_stepper_setup.cpp: the time stepper, Newton and the linear solver.

/// The time stepper on run.dm with poroseam's callbacks and defaults (before the options), and
/// its Newton solver in *snes.
PetscErrorCode createTimeStepper(MPI_Comm comm, Run &run, SNES *snes);
/// poroseam's Newton options (convergence test, test hooks), its callbacks and tolerance.
PetscErrorCode configureNewton(MPI_Comm comm, Run &run, SNES snes);
/// The user's time-stepping and solver options (TSSetFromOptions) and what depends on them:
/// the fieldsplit, the line search, the preconditioner reuse, the mass-balance test,
/// run.ksp_rtol and run.nominal_dt (checked > 0).
PetscErrorCode applySolverOptions(MPI_Comm comm, Run &run, SNES snes);
/// A restart: the time stepper continues at the checkpoint's time, step and step size.
PetscErrorCode resumeTimeStepper(MPI_Comm comm, Run &run, const CheckpointInfo &resumed,
                                 const std::string &checkpoint_path);
/// The time integrator after the options (prints which); *checkpoints: whether this
/// integrator can write checkpoints (a restart or -checkpoint_every with one that cannot is
/// refused).
PetscErrorCode startTimeIntegration(MPI_Comm comm, Run &run, bool restart, bool *checkpoints);
/// What TSSolve would set up at its first step (the Jacobian and its preallocation), now, so
/// that -log_view counts it in the layout phase; then the check of options nothing read.
PetscErrorCode setUpSolvers(MPI_Comm comm, Run &run, Vec X, SNES snes);
/// run.zero_state_scale: the force scale of the convergence test.
PetscErrorCode measureForceScale(Run &run);

// run_outputs.cpp: the run's output files.

/// Opens timeseries.csv, the field and interface files (continuing those of `resumed` on a
/// restart, nullptr otherwise).
PetscErrorCode openOutputs(MPI_Comm comm, Run &run, const CheckpointInfo *resumed);
/// Row 0 of the outputs: the initial state (a new run only).
PetscErrorCode recordInitialState(Run &run);
/// Closes what openOutputs opened.
PetscErrorCode closeOutputs(Run &run);

// time_loop.cpp: the time loop.

/// Where and when the loop starts (progress lines, summary); *first_step: the step it starts
/// after.
PetscErrorCode prepareTimeLoop(Run &run, int *first_step);
/// TSSolve from X to the final time or the run's end (-log_view phase "time stepping"), with
/// a stop signal's handler installed; X ends at the last accepted step.
PetscErrorCode runTimeLoop(Run &run, Vec X);

// run_ending.cpp: how the run ended (describeEnding, run.hpp) and its record.

/// After describeEnding: ends the rolling checkpoint of a run that succeeded, finishes
/// run.yaml with the run's summary (steps since `first_step`, iterations), restores the
/// signal handlers and prints the closing line of a run that reached its final time.
PetscErrorCode recordEnding(MPI_Comm comm, Run &run, RunRecord &record, int first_step,
                            RunEnding ending, const std::string &message);

} // namespace simulation_detail
} // namespace poroseam
