// A step that is cut back says so as it happens: one line per failed attempt, before the
// attempt with the smaller step starts (a step cut back 8 times used to print nothing until it
// ended). TS calls its pre-stage hook before every Newton solve of a step; a rejection counter
// above the one already announced means the attempt before has just failed.

#include "run.hpp"

#include <cstdio>
#include <petscsnes.h>

namespace poroseam {
namespace simulation_detail {

namespace {

/// Why the last attempt was rejected, from the state its Newton solve left.
PetscErrorCode rejectionCause(Run &run, SNES snes, std::string *cause)
{
  SNESConvergedReason reason;
  PetscInt its;
  PetscFunctionBeginUser;
  PetscCall(SNESGetConvergedReason(snes, &reason));
  PetscCall(SNESGetIterationNumber(snes, &its));
  char text[160];
  if (reason < 0) {
    std::snprintf(text, sizeof text, "Newton failed (%s after %d iteration%s",
                  SNESConvergedReasons[reason], (int)its, its == 1 ? "" : "s");
    *cause = text;
    if (reason == SNES_DIVERGED_LINEAR_SOLVE) {
      KSP ksp;
      KSPConvergedReason linear;
      PetscCall(SNESGetKSP(snes, &ksp));
      PetscCall(KSPGetConvergedReason(ksp, &linear));
      *cause += std::string(": the linear solve ") + KSPConvergedReasons[linear];
    }
    *cause += ")";
  } else {
    // Newton converged; the step controller refused the step (its error estimate).
    *cause = run.time.adaptive() ? "time error estimate too large" : "step rejected";
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode announceCutBack(TS ts, PetscReal)
{
  void *ctx;
  PetscInt rejects;
  PetscFunctionBeginUser;
  PetscCall(TSGetApplicationContext(ts, &ctx));
  Run &run = *static_cast<Run *>(ctx);
  PetscCall(TSGetStepRejections(ts, &rejects));
  if (rejects <= run.announced_rejects) PetscFunctionReturn(0);
  run.announced_rejects = rejects;
  SNES snes;
  double dt;
  std::string cause;
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(TSGetTimeStep(ts, &dt));
  PetscCall(rejectionCause(run, snes, &cause));
  char line[400];
  std::snprintf(line, sizeof line, "  step %d: %s at dt %.4e s, retrying with dt %.4e s\n",
                run.step + 1, cause.c_str(), run.attempted_dt, dt);
  run.progress_line.print(PetscObjectComm((PetscObject)ts), line, StopRequest::received);
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
