// How a run ended (split from simulation.cpp): it succeeded only if it reached its final time;
// any other end is an error that says where it stopped, why, and how to go on, and leaves a
// checkpoint of its last accepted step (docs/checkpoints.md). Then the run's record of it:
// run.yaml's summary and the closing line.

#include "run.hpp"
#include "run_steps.hpp"

#include "checkpoint.hpp"
#include "rolling_checkpoint.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode describeEnding(Run &run, Vec X, bool checkpoints, std::string *message,
                              RunEnding *ending)
{
  PetscFunctionBeginUser;
  TSConvergedReason reason;
  double t, t_end;
  PetscInt max_steps, rejects = 8;
  PetscCall(TSGetConvergedReason(run.ts, &reason));
  PetscCall(TSGetTime(run.ts, &t));
  PetscCall(TSGetMaxTime(run.ts, &t_end));
  PetscCall(TSGetMaxSteps(run.ts, &max_steps));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-ts_max_reject", &rejects, nullptr));
  const bool reached =
      reason >= 0 && t >= t_end - 1e-10 * std::max(std::abs(t_end), run.nominal_dt);
  std::string checkpoint_note;
  if (!reached && checkpoints && run.step > 0) {
    // Nothing is lost: the last accepted step becomes a checkpoint (unless it is one).
    if (run.checkpoint_step != run.step) {
      std::string path;
      PetscCall(writeCheckpoint(run, X, &path));
      run.checkpoint_step = run.step;
      run.latest_checkpoint = path;
      PetscCall(dropRollingCheckpoint(run)); // an older step's
    }
    checkpoint_note = "; a checkpoint of step " + std::to_string(run.step) + " is in " +
                      run.scene.output_dir + "/checkpoints";
  }
  const std::string restart_hint =
      checkpoint_note.empty() ? std::string() : "; continue with -restart " + run.scene.output_dir;
  const std::string steps_hint =
      (checkpoint_note.empty() ? "; rerun with" : " and") + std::string(" a larger -ts_max_steps");
  char text[4096] = "";
  *ending = reached ? RunEnding::success : RunEnding::step_limit;
  std::string linear_failure, linear_advice;
  PetscInt rejected = 0;
  PetscCall(TSGetStepRejections(run.ts, &rejected));
  const int attempts = (int)(rejected - run.last_rejects);
  if (reason < 0 && describeLinearFailure(run, attempts, t, &linear_failure, &linear_advice)) {
    // Not the time step's fault: no advice about it (solve_failure.cpp).
    *ending = RunEnding::failed_step;
    std::snprintf(text, sizeof(text),
                  "step %d failed (%s): %s. Results up to t = %g s are in %s%s%s. %s", run.step + 1,
                  TSConvergedReasons[reason], linear_failure.c_str(), t,
                  run.scene.output_dir.c_str(), checkpoint_note.c_str(),
                  restart_hint.empty() ? "" : (restart_hint + " and other solver options").c_str(),
                  linear_advice.c_str());
  } else if (reason < 0) {
    *ending = RunEnding::failed_step;
    const std::string newton =
        run.failure.step == run.step && run.failure.snes < 0
            ? std::string(" (") + SNESConvergedReasons[run.failure.snes] + ")"
            : std::string();
    std::snprintf(text, sizeof(text),
                  "step %d failed (%s): %s%s from t = %g s even after %d cuts of the time step "
                  "(last tried dt = %g s). Results up to t = %g s are in %s%s; a smaller -ts_dt, "
                  "more cuts (-ts_max_reject) or other solver options may help",
                  run.step + 1, TSConvergedReasons[reason],
                  run.time.adaptive() ? "its attempts were rejected (Newton did not converge or "
                                        "the error exceeded -ts_rtol)"
                                      : "Newton did not converge",
                  newton.c_str(), t, (int)rejects, run.attempted_dt, t,
                  run.scene.output_dir.c_str(), checkpoint_note.c_str());
  } else if (run.stop_signal) {
    *ending = RunEnding::signal;
    std::snprintf(text, sizeof(text),
                  "stopped at step %d, t = %g s of %g s, on signal %d (%s)%s. Results up to "
                  "t = %g s are in %s%s%s",
                  run.step, t, t_end, run.stop_signal, strsignal(run.stop_signal),
                  run.step_abandoned ? ", abandoning the step in progress" : "", t,
                  run.scene.output_dir.c_str(), checkpoint_note.c_str(), restart_hint.c_str());
  } else if (!reached) {
    std::snprintf(text, sizeof(text),
                  "stopped at step %d, t = %g s, before the final time %g s (-ts_max_time): the "
                  "step limit -ts_max_steps %d was reached. Results up to t = %g s are in %s%s%s",
                  run.step, t, t_end, (int)max_steps, t, run.scene.output_dir.c_str(),
                  checkpoint_note.c_str(), (restart_hint + steps_hint).c_str());
  }
  *message = text;
  PetscFunctionReturn(0);
}

PetscErrorCode recordEnding(MPI_Comm comm, Run &run, RunRecord &record, int first_step,
                            RunEnding ending, const std::string &message)
{
  PetscFunctionBeginUser;
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
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
