// One run from its options to its end (simulate, runSimulation): output directory, mesh,
// layout, time stepper and solver set-up, the force scale, the outputs, TSSolve and the run's
// record. What TS calls inside a step is in step_callbacks.cpp.
#include "poroseam/simulation.hpp"
#include "poroseam/option_registry.hpp"

#include "run.hpp"

#include "checkpoint.hpp"
#include "restart_check.hpp"
#include "rolling_checkpoint.hpp"

#include "poroseam/field_writer.hpp"
#include "poroseam/interface_writer.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/log_events.hpp"
#include "poroseam/mass_balance_test.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/nullspace.hpp"
#include "poroseam/option_check.hpp"
#include "poroseam/option_listing.hpp"
#include "poroseam/penalty_check.hpp"
#include "poroseam/petsc_choices.hpp"
#include "poroseam/probes.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/run_options.hpp"
#include "poroseam/scene.hpp"
#include "poroseam/schur_selfp.hpp"
#include "poroseam/solver_preset.hpp"
#include "poroseam/support_check.hpp"
#include "poroseam/time_integration.hpp"
#include "poroseam/vertex_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <petscts.h>
#include <string>
#include <utility>
#include <vector>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode printFieldSizes(Run &run, std::vector<std::pair<std::string, long>> *fields)
{
  PetscSection gs;
  PetscInt pStart, pEnd, numFields;
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(run.dm, &gs));
  PetscCall(PetscSectionGetChart(gs, &pStart, &pEnd));
  PetscCall(PetscSectionGetNumFields(gs, &numFields));
  std::vector<long> local(numFields, 0), total(numFields, 0);
  for (PetscInt p = pStart; p < pEnd; ++p)
    for (PetscInt f = 0; f < numFields; ++f) {
      PetscInt dof, cdof, off;
      PetscCall(PetscSectionGetOffset(gs, p, &off));
      if (off < 0) continue; // not owned
      PetscCall(PetscSectionGetFieldDof(gs, p, f, &dof));
      PetscCall(PetscSectionGetFieldConstraintDof(gs, p, f, &cdof));
      local[f] += dof - cdof;
    }
  PetscCallMPI(MPI_Allreduce(local.data(), total.data(), numFields, MPI_LONG, MPI_SUM, comm));
  PetscSection s;
  PetscCall(DMGetLocalSection(run.dm, &s));
  for (PetscInt f = 0; f < numFields; ++f) {
    const char *name;
    PetscCall(PetscSectionGetFieldName(s, f, &name));
    PetscCall(PetscPrintf(comm, "field %-14s %10ld unknowns\n", name, total[f]));
    fields->emplace_back(name, total[f]);
  }
  PetscFunctionReturn(0);
}

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

/// The run: set-up, time loop, ending; run.yaml through `record`.
PetscErrorCode simulate(MPI_Comm comm, Run &run, RunRecord &record)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(registerLogEvents(&run.events));
  run.problem.setLogEvents(run.events);
  // The options as given, before poroseam adds its own: what a checkpoint keeps and a restart
  // compares (restart_check.hpp).
  PetscCall(givenOptions(comm, &run.given_options, &run.given_option_files));
  PetscCall(readMeshOptions(comm, run.scene));
  RestartOptions restart;
  PetscCall(readCheckpointOptions(comm, run, &restart));
  PetscCall(readRollingCheckpointOptions(comm, &run.rolling));
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
  // A restart that cannot continue its run is refused before anything in its directory changes.
  std::string checkpoint_path;
  if (restart.restart)
    PetscCall(chooseRestartCheckpoint(comm, restart, run.given_options, run.given_option_files,
                                      &checkpoint_path));
  { // rank 0 creates it; every rank learns whether that worked, so none waits for the others
    std::error_code failed;
    if (rank == 0) std::filesystem::create_directories(run.scene.output_dir, failed);
    int ok = !failed;
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
    const std::string why = failed ? ": " + failed.message() : "";
    PetscCheck(ok, comm, PETSC_ERR_FILE_OPEN,
               "cannot create the output directory '%s' (option -output_dir)%s",
               run.scene.output_dir.c_str(), why.c_str());
  }
  if (!restart.restart) PetscCall(clearEarlierRun(comm, run.scene.output_dir));
  PetscCall(record.begin(comm, run.scene.output_dir, restart.restart));
  std::vector<PhysicalName> names;
  int dim;
  PetscCall(beginLogPhase(run.events.mesh));
  PetscCall(loadGmshMesh(comm, run.scene.mesh_file, run.scene.mesh_size_factor,
                         run.scene.output_dir + "/mesh", &run.dm, &names, &dim,
                         run.scene.mesh_geometry_order, run.scene.displacement_order));
  PetscCall(readSceneOptions(comm, names, dim, run.scene));
  PetscCall(splitInterfaces(&run.dm, run.scene));
  PetscCall(checkBodiesSupported(run.dm, run.scene)); // no part free of every support
  PetscCall(markLayoutLabels(run.dm, run.scene));
  // Before distribution: rank 0 holds both sides of every interface face.
  PetscCall(warnAboutPenalties(run.dm, run.scene));
  PetscCall(endLogPhase(run.events.mesh));
  PetscCall(beginLogPhase(run.events.distribution));
  PetscCall(distributeMesh(&run.dm));
  PetscCall(checkCellOrientation(run.dm));
  PetscCall(endLogPhase(run.events.distribution));
  PetscCall(beginLogPhase(run.events.layout));
  PetscCall(createSolutionSection(run.dm, run.scene));
  PetscCall(run.problem.setup(run.dm, run.scene));
  PetscCall(run.probes.setup(run.dm, run.scene));
  PetscCall(collectBoundaryDofs(run));
  std::vector<std::pair<std::string, long>> fields;
  PetscCall(printFieldSizes(run, &fields));
  PetscCall(record.setUnknowns(comm, fields));
  long unknowns = 0;
  for (const auto &f : fields)
    unknowns += f.second;
  {
    std::string solver;
    PetscCall(
        applySolverPreset(comm, run.scene.dim, run.scene.displacement_order, unknowns, &solver));
    PetscCall(record.setSolver(comm, solver));
  }

  // Initial state and its boundary values.
  PetscCall(DMCreateLocalVector(run.dm, &run.previous));
  PetscCall(VecDuplicate(run.previous, &run.initial));
  PetscCall(run.problem.initialState(run.initial));
  PetscCall(run.steady.setup(run.dm, run.scene, run.initial));
  PetscCall(VecCopy(run.initial, run.previous));
  Vec X;
  PetscCall(DMCreateGlobalVector(run.dm, &X));
  PetscCall(PetscObjectSetName((PetscObject)X, "solution"));
  PetscCall(attachSolutionView(run, X));
  PetscCall(DMLocalToGlobal(run.dm, run.initial, INSERT_VALUES, X));
  PetscCall(VecDuplicate(X, &run.last_increment));
  PetscCall(VecSet(run.last_increment, 0.0));
  CheckpointInfo resumed;
  if (restart.restart) PetscCall(readCheckpoint(run, checkpoint_path, X, &resumed));

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
  SNES snes;
  PetscCall(TSGetSNES(run.ts, &snes));
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
  PetscCall(registerVertexBlocksPC());
  PetscCall(registerSchurSelfpPC());
  PetscCall(checkPetscChoices(comm)); // -ksp_type gmress: one line, not PETSc's traceback
  PetscCall(readUnusedOptionsOk(comm, &run.unused_options));
  PetscCall(run.time.beforeOptions(run.ts));
  PetscCall(TSSetFromOptions(run.ts));
  PetscCall(checkTimeSteppingOptions(run.ts)); // -ts_max_time/_steps > 0, -ts_max_reject >= 0
  PetscCall(configureFieldSplit(run.ts, run.dm, run.scene, &run.jacobian_diagonal));
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
  if (restart.restart) {
    PetscReal t_end;
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
  }
  {
    PetscReal t0;
    PetscCall(TSGetTime(run.ts, &t0));
    PetscCall(run.time.afterOptions(run.ts, run.dm, run.problem, t0, run.initial));
    PetscCall(
        PetscPrintf(comm, "time integration: %s, %s\n", run.time.name(),
                    run.time.adaptive() ? "adaptive steps (-ts_adapt_type basic)" : "fixed steps"));
  }
  // BDF2 and TSAdapt keep their memory (earlier states, the last error) inside PETSc, where a
  // checkpoint cannot reach it: a restart could not continue them exactly.
  const bool checkpoints = !run.time.bdf() && !run.time.adaptive();
  run.rolling.enabled = run.rolling.enabled && checkpoints;
  PetscCheck(checkpoints || (!restart.restart && run.checkpoint_every == 0), comm,
             PETSC_ERR_USER_INPUT,
             "%s: checkpoints and restarts are supported with backward Euler at fixed steps (the "
             "default); %s%s keeps its history inside PETSc",
             restart.restart ? "-restart" : "-checkpoint_every", run.time.name(),
             run.time.adaptive() ? " with adaptive steps" : "");
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
  // Set up now what TSSolve would at its first step (the Jacobian matrix and its
  // preallocation), so that -log_view counts it in the layout stage, not in the first step.
  PetscCall(TSSetSolution(run.ts, X));
  PetscCall(TSSetUp(run.ts));
  PetscCall(SNESSetUp(snes));
  run.unused_options.ts = run.ts; // -ts_dtt stops here; -fieldsplit_*_pc_typ at the first solve
  PetscCall(checkUnusedOptionsAfterSetUp(comm, &run.unused_options));

  {
    // Force scale for the convergence test: the residual of the zero state at t = 0, where
    // weight and initial stresses appear without the pore pressure that balances them.
    Vec zero, f, F;
    PetscCall(DMGetLocalVector(run.dm, &zero));
    PetscCall(DMGetLocalVector(run.dm, &f));
    PetscCall(DMGetGlobalVector(run.dm, &F));
    PetscCall(VecSet(zero, 0.0));
    PetscCall(run.problem.residual(0.0, zero, zero, ResidualMode{1.0, true}, f));
    PetscCall(VecSet(F, 0.0));
    PetscCall(DMLocalToGlobal(run.dm, f, ADD_VALUES, F));
    PetscReal norm;
    PetscCall(VecNorm(F, NORM_2, &norm));
    run.zero_state_scale = norm;
    PetscCall(DMRestoreGlobalVector(run.dm, &F));
    PetscCall(DMRestoreLocalVector(run.dm, &f));
    PetscCall(DMRestoreLocalVector(run.dm, &zero));
  }
  PetscCall(beginLogEvent(run.events.output));
  PetscCall(
      run.series.open(comm, run.scene, run.scene.output_dir, restart.restart ? resumed.step : -1));
  if (run.scene.output_every > 0) {
    const std::vector<double> *times = restart.restart ? &resumed.output_times : nullptr;
    PetscCall(run.fields.open(run.dm, run.scene.output_dir, "fields", times));
    std::vector<PetscInt> cells;
    std::vector<int> regions;
    std::vector<std::string> names;
    run.problem.cellRegions(cells, regions);
    for (const Region &r : run.scene.regions)
      names.push_back(r.name);
    {
      CellFields declared; // the names of the cell fields, from the initial state
      PetscCall(run.problem.cellFields(run.initial, declared));
      run.fields.declareCellFields(declared);
    }
    PetscCall(run.fields.writeRegions(cells, regions, names));
  }
  if (run.scene.interface_output_every > 0) {
    const std::vector<double> *times = restart.restart ? &resumed.interface_output_times : nullptr;
    PetscCall(run.interface_fields.open(comm, run.scene, run.scene.output_dir, times));
  }
  PetscCall(endLogEvent(run.events.output));
  if (!restart.restart) {
    // Row 0: the initial state.
    Vec rate;
    PetscCall(DMGetLocalVector(run.dm, &rate));
    PetscCall(VecSet(rate, 0.0));
    PetscCall(recordStep(run, 0.0, 0.0, run.initial, rate, 0, 0, 0, 0.0));
    PetscCall(DMRestoreLocalVector(run.dm, &rate));
  }
  run.step_start = MPI_Wtime();
  run.loop_start_wall = run.step_start;
  PetscCall(TSGetTime(run.ts, &run.loop_start_time));
  run.stage_time = run.loop_start_time; // the state PETSc's monitors view at step 0
  PetscCall(TSGetMaxTime(run.ts, &run.t_end));
  const int first_step = run.step;
  PetscCall(TSSetErrorIfStepFails(run.ts, PETSC_FALSE));
  PetscCall(endLogPhase(run.events.layout));
  PetscCall(beginLogPhase(run.events.time_stepping));
  PetscCall(run.stop.install());
  PetscCall(noteStart(run)); // a stop in the first step
  PetscCall(TSSolve(run.ts, X));
  PetscCall(endLogPhase(run.events.time_stepping));
  PetscCall(restoreAbandonedStep(run, X));
  std::string message; // empty: the run reached its final time
  RunEnding ending;
  PetscCall(describeEnding(run, X, checkpoints, &message, &ending));
  if (ending == RunEnding::success) PetscCall(endRollingCheckpoint(run));
  // From here the run writes its own record; a signal now only sets the flag.
  StopRequest::disarmRecord();
  {
    RunSummary summary;
    PetscInt newton, krylov, rejected;
    PetscCall(TSGetSNESIterations(run.ts, &newton));
    PetscCall(TSGetKSPIterations(run.ts, &krylov));
    PetscCall(TSGetStepRejections(run.ts, &rejected));
    PetscCall(TSGetTime(run.ts, &summary.time));
    summary.steps = run.step - first_step, summary.first_step = first_step;
    summary.last_step = run.step, summary.steps_cut_back = run.steps_cut_back;
    summary.newton = newton, summary.krylov = krylov, summary.rejected = rejected;
    summary.stepping_wall = MPI_Wtime() - run.loop_start_wall;
    PetscCall(record.finish(comm, ending, message, summary, run.stop_signal));
  }
  PetscCall(reportRollingCheckpoints(run)); // printed after the record: stdout may block
  PetscCall(run.stop.restore());
  if (message.empty())
    PetscCall(PetscPrintf(comm, "poroseam: %d steps in %.2f s, results in %s\n", run.step,
                          MPI_Wtime() - run.loop_start_wall, run.scene.output_dir.c_str()));
  PetscCall(beginLogEvent(run.events.output));
  run.series.close();
  PetscCall(run.fields.close());
  PetscCall(run.interface_fields.close());
  PetscCall(endLogEvent(run.events.output));
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
