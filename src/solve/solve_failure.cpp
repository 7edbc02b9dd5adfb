// Why a step attempt failed: Newton, or the linear solver inside it. A failed linear solve is
// the solver's or the matrix's problem, not the time step's: the step is cut at most
// kLinearFailureCuts times for it, and the run's last message names the linear solver's
// reason and what to try instead of a smaller -ts_dt (issue 24: a scene without a solver line
// spent 9 attempts of 10,000 GMRES iterations each and blamed the time step).

#include "run.hpp"

#include <cstdio>
#include <string>

namespace poroseam {
namespace simulation_detail {
namespace {

/// Cuts of the time step after attempts whose linear solve failed, in a row. A smaller step
/// can help (contact that stays closed keeps a body held; a better-conditioned storage block),
/// so not none; but a solver that fails three times running will not be saved by more halving.
constexpr int kLinearFailureCuts = 2;

bool directSolver(const AttemptFailure &f)
{
  return f.pc_type == PCLU || f.pc_type == PCCHOLESKY;
}

} // namespace

PetscErrorCode noteAttempt(TS ts, PetscReal stage_time, PetscInt stage, Vec *Y)
{
  void *ctx;
  SNES snes;
  SNESConvergedReason reason;
  PetscFunctionBeginUser;
  PetscCall(TSGetApplicationContext(ts, &ctx));
  Run &run = *static_cast<Run *>(ctx);
  AttemptFailure &f = run.failure;
  if (f.step != run.step) f = AttemptFailure(), f.step = run.step; // a new step's attempts
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetConvergedReason(snes, &reason));
  if (reason >= 0 || run.step_abandoned) {
    f.snes = SNES_CONVERGED_ITERATING, f.linear_in_row = 0;
    PetscFunctionReturn(0);
  }
  f.snes = reason;
  if (reason != SNES_DIVERGED_LINEAR_SOLVE) {
    f.linear_in_row = 0;
    PetscFunctionReturn(0);
  }
  KSP ksp;
  PC pc;
  KSPType ksp_type;
  PCType pc_type;
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetConvergedReason(ksp, &f.ksp));
  PetscCall(KSPGetIterationNumber(ksp, &f.ksp_its));
  PetscCall(KSPGetType(ksp, &ksp_type));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCGetType(pc, &pc_type));
  PetscCall(PCGetFailedReason(pc, &f.pc));
  f.ksp_type = ksp_type ? ksp_type : "";
  f.pc_type = pc_type ? pc_type : "";
  ++f.linear_in_row;
  ++f.linear_in_step;
  if (f.linear_in_row > kLinearFailureCuts) {
    // No more cuts: TS sees the step as failed and leaves its loop (TSAdaptCheckStage does not
    // cut once a reason is set); describeEnding says why.
    PetscCall(PetscInfo(ts, "poroseam: %d attempts in a row failed in the linear solve: stop\n",
                        f.linear_in_row));
    PetscCall(TSSetConvergedReason(ts, TS_DIVERGED_NONLINEAR_SOLVE));
  }
  PetscFunctionReturn(0);
}

bool describeLinearFailure(const Run &run, int attempts, double t, std::string *failure,
                           std::string *advice)
{
  const AttemptFailure &f = run.failure;
  if (f.step != run.step || f.snes != SNES_DIVERGED_LINEAR_SOLVE) return false;
  std::string what = std::string("the linear solver failed, not Newton (") +
                     SNESConvergedReasons[f.snes] + "): KSP " + KSPConvergedReasons[f.ksp] +
                     " after " + std::to_string((long)f.ksp_its) + " iteration" +
                     (f.ksp_its == 1 ? "" : "s") + " (-ksp_type " + f.ksp_type + ", -pc_type " +
                     f.pc_type;
  if (f.pc != PC_NOERROR) what += std::string(", PC ") + PCFailedReasons[f.pc];
  char where[256];
  std::snprintf(where, sizeof where,
                ") in %d of the step's %d attempt%s from t = %g s (last tried dt = %g s)",
                f.linear_in_step, attempts, attempts == 1 ? "" : "s", t, run.attempted_dt);
  what += where;
  if (f.linear_in_row > kLinearFailureCuts)
    what += "; the time step was cut " + std::to_string(kLinearFailureCuts) +
            " times for it and no more (a smaller step seldom mends a linear solver)";
  // What to try, by what failed.
  const std::string singular =
      "the matrix is singular or nearly so: check that the boundary conditions hold every body "
      "against rigid-body motion (also a body held only by an interface that opens) and that "
      "each porous region's water can drain or has its pressure prescribed somewhere";
  const std::string direct = "Try the direct solver (-solver_preset direct, MUMPS LU)";
  std::string remedy;
  if (f.pc == PC_FACTOR_OUTMEMORY)
    remedy = "The factorisation ran out of memory: take the iterative solver (-solver_preset "
             "fieldsplit) or more ranks";
  else if (f.ksp == KSP_DIVERGED_PC_FAILED && directSolver(f))
    remedy = "A factorisation that fails means " + singular;
  else if (f.ksp == KSP_DIVERGED_ITS)
    remedy = direct + " or more iterations (-ksp_max_it, now " + std::to_string((long)f.ksp_its) +
             "); if the direct solver fails too, " + singular;
  else if (directSolver(f))
    remedy = "Check the solver options; or " + singular;
  else
    remedy = direct + "; if it fails too, " + singular;
  *failure = what;
  *advice = remedy + " (-ksp_converged_reason prints every linear solve).";
  return true;
}

} // namespace simulation_detail
} // namespace poroseam
