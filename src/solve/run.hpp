// The state of one run shared by its parts (internal to src/solve): the set-up and time loop
// (simulation.cpp and the steps of run_steps.hpp), the callbacks TS calls in it
// (step_callbacks.cpp), the forces and flows it reports (run_resultants.cpp) and the control of
// Newton's iterations (newton_control.cpp).
#pragma once

#include "poroseam/field_writer.hpp"
#include "poroseam/interface_assembly.hpp"
#include "poroseam/interface_writer.hpp"
#include "poroseam/log_events.hpp"
#include "poroseam/probes.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/run_record.hpp"
#include "poroseam/scene.hpp"
#include "poroseam/time_integration.hpp"
#include "poroseam/time_series.hpp"
#include "poroseam/time_to_finish.hpp"
#include "poroseam/unused_options.hpp"

#include "progress_line.hpp"
#include "rolling_checkpoint.hpp"
#include "steady_pressure.hpp"
#include "stop_request.hpp"

#include <petscts.h>
#include <string>
#include <vector>

namespace poroseam {
namespace simulation_detail {

/// Per boundary, the local offsets of the prescribed unknowns whose reactions and outflows it
/// reports: each prescribed unknown once, for the first boundary in -boundaries order that
/// prescribes it (docs/outputs.md, "Forces and flows through boundaries").
struct BoundaryDofs {
  std::vector<PetscInt> displacement[3];    ///< per component
  std::vector<PetscInt> pressure;           ///< pore pressure
  std::vector<PetscInt> interface_pressure; ///< p3 of interfaces ending here
};

/// Why the attempts of the step in progress failed (solve_failure.cpp): the last failed
/// attempt's Newton reason and, when its linear solve failed, that solve's reason.
struct AttemptFailure {
  int step = -1; ///< the accepted steps before the attempts (run.step): whose attempts these are
  SNESConvergedReason snes = SNES_CONVERGED_ITERATING; ///< of the last failed attempt
  KSPConvergedReason ksp = KSP_CONVERGED_ITERATING;    ///< its last linear solve's
  PetscInt ksp_its = 0;                                ///< that solve's iterations
  PCFailedReason pc = PC_NOERROR;                      ///< the preconditioner's
  std::string ksp_type, pc_type;
  int linear_in_row = 0;  ///< consecutive attempts whose linear solve failed
  int linear_in_step = 0; ///< attempts of the step whose linear solve failed
};

struct Run {
  Scene scene;
  DM dm = nullptr;
  Problem problem;
  Probes probes;
  FieldWriter fields;
  InterfaceWriter interface_fields;
  TS ts = nullptr;
  TimeIntegration time;   ///< integrator checks, rates of prescribed values, error control
  Vec previous = nullptr; ///< local state of the last accepted step (boundary values included)
  /// While set (postStep), the residual copies the integrator's local rate here.
  Vec capture_rate = nullptr;
  Vec initial = nullptr; ///< local initial state
  SteadyPressure steady; ///< the steady pore pressure of the outputs
  std::vector<BoundaryDofs> boundary_dofs;
  /// Per interface: its prescribed interface-pressure dofs, where water leaves along it.
  std::vector<std::vector<PetscInt>> interface_end_dofs;
  TimeSeries series; ///< timeseries.csv
  double nominal_dt = 0.0;
  double fail_dt_above = 0.0;    ///< test hook: step attempts with a larger dt fail
  double step_delay = 0.0;       ///< test hook: each residual evaluation waits this long [s]
  PetscInt step_delay_after = 0; ///< test hook: ... in the steps after this one
  double attempted_dt = 0.0;     ///< dt of the last residual evaluation
  PetscInt last_snes_its = 0, last_ksp_its = 0, last_rejects = 0;
  double step_start = 0.0;
  int step = 0;
  /// Progress (step line, run summary): where and when the time loop started, its final time,
  /// and the accepted steps that needed a cut-back.
  double loop_start_wall = 0.0, loop_start_time = 0.0, t_end = 0.0;
  int steps_cut_back = 0;
  double zero_state_scale = 0.0; ///< gross residual of the zero state (weight, initial stress)
  double stage_time = 0.0;       ///< time of the step being solved
  double reference_rtol = 1e-9;  ///< -snes_reference_rtol
  double ksp_rtol = 0.0;         ///< -ksp_rtol: the tightest linear tolerance Newton asks for
  /// Inexact Newton forcing (convergenceTest): the residual norm of the last Newton iterate,
  /// and how much the first Newton iteration of the last step reduced the residual (0: no
  /// step yet, or one that converged in its first iteration).
  double newton_last_fnorm = 0.0;
  double first_contraction = 0.0;
  /// The first residual of this step's Newton iterations, and the part of it in the force
  /// (displacement) rows: PETSc's relative test is measured against the latter when the water
  /// rows dominate (convergenceTest).
  double newton_first_fnorm = 0.0, newton_first_force_fnorm = 0.0;
  IS force_rows = nullptr; ///< the displacement rows of the global vector (made at first use)
  Vec jacobian_diagonal = nullptr; ///< with a fieldsplit: diag of the Jacobian (vertex_blocks)
  /// -snes_keep_preconditioner: the linear solver keeps its factorisation or preconditioner
  /// while the Jacobian is unchanged (Problem::jacobianRepeated), instead of redoing it for
  /// every Newton iteration; off when the user lags it himself (-snes_lag_preconditioner).
  PetscBool keep_preconditioner = PETSC_TRUE;
  /// Profiling: -log_view events and phases of this run, and whether the first Jacobian
  /// (PsFirstJacobian) is behind us.
  LogEvents events;
  bool jacobian_assembled = false;
  /// Newton's extrapolated start (backward Euler): the last accepted increment of the
  /// unknowns (global) and the step it was taken over (0: none yet).
  Vec last_increment = nullptr;
  double last_dt = 0.0;
  /// Checkpoints (checkpoint.hpp): every this many steps (0: only when a run stops early),
  /// the step of the last one written (-1: none), and the signals that ask a run to stop.
  int checkpoint_every = 0;
  int checkpoint_step = -1;
  /// What a checkpoint keeps for a restart to compare (restart_check.hpp): the options given
  /// to the run and the content hashes of the files they name.
  std::string given_options, given_option_files;
  StopRequest stop;
  int stop_signal = 0; ///< the signal that stopped the run (0: none)
  /// A stop from outside (stop_points.cpp): the rolling checkpoint, the newest checkpoint on
  /// disk ("": none), the record that notes each accepted step, the step line that never
  /// blocks, whether a stop came between two Newton iterations of a step (then abandoned),
  /// and the step size chosen after the last accepted step.
  RollingCheckpoint rolling;
  std::string latest_checkpoint;
  RunRecord *record = nullptr;
  ProgressLine progress_line;
  bool step_abandoned = false;
  double accepted_next_dt = 0.0;
  AttemptFailure failure;           ///< why the step in progress failed so far
  UnusedOptionCheck unused_options; ///< options typed that nothing reads (unused_options.hpp)
  /// Step rejections already announced by a cut-back line (cut_back_line.cpp).
  PetscInt announced_rejects = 0;
  /// The wall time still needed, on the step line (time_to_finish.hpp).
  TimeToFinish time_to_finish;
};

inline PetscErrorCode currentDt(Run &run, double *dt)
{
  PetscFunctionBeginUser;
  PetscCall(TSGetTimeStep(run.ts, dt));
  PetscFunctionReturn(0);
}

// run_resultants.cpp: forces and flows through boundaries and interfaces.

/// The local dofs of every named boundary (run.boundary_dofs, run.interface_end_dofs).
PetscErrorCode collectBoundaryDofs(Run &run);
/// Force and water resultants of every boundary at (t, dt) from the residual without loads.
PetscErrorCode boundaryResultants(Run &run, double t, double dt, Vec local, Vec rate,
                                  std::vector<double> &out);
/// Entries per interface in interfaceResultants' output.
int interfaceBlock(const Scene &scene, const Interface &i);
/// Forces, water and gap storage of every interface and interface part.
PetscErrorCode interfaceResultants(Run &run, Vec local, const InterfaceRates &rates,
                                   std::vector<double> &out);
/// Force level of the iterate X (sum of the magnitudes of boundary and interface forces).
PetscErrorCode forceLevel(Run &run, Vec X, double *level);

// newton_control.cpp: when Newton stops, how exactly it solves, where it starts.

/// SNES convergence test (context: the Run).
PetscErrorCode convergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                               PetscReal fnorm, SNESConvergedReason *reason, void *ctx);
/// SNES initial guess (context: the Run).
PetscErrorCode chooseInitialGuess(SNES snes, Vec X, void *ctx);
/// With contact interfaces, Newton's line search steps over the kinks of the contact law
/// (kinkLineSearch; -snes_kink_linesearch 0 keeps PETSc's -snes_linesearch_type).
PetscErrorCode configureLineSearch(Run &run, SNES snes);
/// Reads -snes_keep_preconditioner (run.keep_preconditioner; off when the user lags the
/// preconditioner himself, -snes_lag_preconditioner). Call after TSSetFromOptions.
PetscErrorCode configureKeepPreconditioner(Run &run, SNES snes);

// solution_view.cpp: PETSc's own viewers of the solution show the prescribed values too.

/// Gives X (and the vectors TS and SNES duplicate from it) a view operation for VTK, HDF5,
/// draw and GLVis viewers that inserts the prescribed values at run.stage_time first.
PetscErrorCode attachSolutionView(const Run &run, Vec X);

// stop_points.cpp: where a run looks for a stop from outside, and what it leaves then.

/// Before the first step: the run.yaml a stop in that step leaves (stop_request.hpp).
PetscErrorCode noteStart(Run &run);
/// After an accepted step (its checkpoint written, `kept` if not the rolling one): notes it in
/// run.yaml and arms the record a stop signal writes; rank 0 prints the step line.
PetscErrorCode noteAcceptedStep(Run &run, const StepRow &row, bool kept);
/// Test hook (-test_step_delay): a residual evaluation as slow as a large run's, without its
/// cost (scripts/stop_trials: a stop in the middle of a long step).
PetscErrorCode delayStepForTests(const Run &run);
/// Collective, after an accepted step: a stop signal on any rank ends the time loop there.
PetscErrorCode stopAfterStep(Run &run, TSConvergedReason reason);
/// Collective, between two Newton iterations (the convergence test): a stop signal on any
/// rank abandons the step in progress (its last accepted one is on disk already, or is
/// written by describeEnding). Sets *reason to a divergence then (run.step_abandoned).
PetscErrorCode stopDuringStep(Run &run, SNESConvergedReason *reason);
/// After TSSolve: a step abandoned by a stop leaves X and the step size as after the last
/// accepted step.
PetscErrorCode restoreAbandonedStep(Run &run, Vec X);

// solve_failure.cpp: why an attempt failed; a failed linear solve is not the time step's fault.

/// TS post-stage hook (after every Newton solve, converged or not): notes a failed attempt in
/// run.failure, and ends the step (no more cuts) after kLinearFailureCuts + 1 attempts in a
/// row whose linear solve failed.
PetscErrorCode noteAttempt(TS ts, PetscReal stage_time, PetscInt stage, Vec *Y);
/// When the last attempt of the failed step (of `attempts`, from time t) failed in its linear
/// solve: what failed (reasons, solver, counts) and what to try instead; false otherwise.
bool describeLinearFailure(const Run &run, int attempts, double t, std::string *failure,
                           std::string *advice);

// step_record.cpp: what one step leaves in the outputs.

/// One row of timeseries.csv and, every output_every steps and at the `last` step of the run,
/// the fields; the interfaces likewise every interface_output_every steps.
PetscErrorCode recordStep(Run &run, double t, double dt, Vec local, Vec rate, PetscInt newton,
                          PetscInt ksp, PetscInt rejected, double wall, bool last = false);

// cut_back_line.cpp: a cut-back says so as it happens.

/// TS pre-stage hook: after a rejected attempt, rank 0 prints one line naming the step, why
/// the attempt failed, its dt and the dt of the retry. No communication.
PetscErrorCode announceCutBack(TS ts, PetscReal stage_time);

// step_callbacks.cpp: what PETSc's time stepper calls during a step (context: the Run).

/// DMTS boundary-local function: the prescribed values at t and their rates.
PetscErrorCode boundaryLocal(DM, PetscReal t, Vec local, Vec local_rate, void *ctx);
/// DMTS implicit function: the residual at (t, local, local_rate).
PetscErrorCode iFunctionLocal(DM, PetscReal t, Vec local, Vec local_rate, Vec f, void *ctx);
/// DMTS implicit Jacobian: d residual / d unknowns + shift * d residual / d rates.
PetscErrorCode iJacobianLocal(DM, PetscReal t, Vec local, Vec local_rate, PetscReal shift, Mat J,
                              Mat P, void *ctx);
/// TS post-step hook: records, commits and checkpoints an accepted step; sets the next step.
PetscErrorCode postStep(TS ts);

// run_ending.cpp: how the run ended.

/// After TSSolve: the error message of a run that did not reach its final time (empty when it
/// did), writing a checkpoint of its last accepted step if `checkpoints` and none exists, and
/// which of the ways to end it was.
PetscErrorCode describeEnding(Run &run, Vec X, bool checkpoints, std::string *message,
                              RunEnding *ending);

} // namespace simulation_detail
} // namespace poroseam
