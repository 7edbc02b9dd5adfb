// Time integration of a run (docs/time_stepping.md): which PETSc integrators poroseam accepts
// (backward Euler; BDF of order 1 or 2), the difference formula that gives the rates of
// prescribed values (PETSc differentiates only the unknowns), and the adaptive step control
// with per-field tolerances.
#pragma once

#include "poroseam/problem.hpp"

#include <petscts.h>

namespace poroseam {

/// The share of a step below which the time left after it is round-off, not a step of its own:
/// the step is stretched by it instead (docs/time_stepping.md, "The last step").
constexpr double kFinalTimeMerge = 1e-6;

/// TS pre-step hook: a step that would end within kFinalTimeMerge of itself before the final
/// time (-ts_max_time), or beyond it, is set to end on the final time.
PetscErrorCode landOnFinalTime(TS ts);
/// After a step that was set to land on the final time: its end time is made exactly the
/// final time (t + (t_end - t) can round off by an ulp) and TS is told the run is done.
/// `t` is the step's end time, updated.
PetscErrorCode settleOnFinalTime(TS ts, double *t);

class TimeIntegration {
public:
  TimeIntegration() = default;
  TimeIntegration(const TimeIntegration &) = delete;
  TimeIntegration &operator=(const TimeIntegration &) = delete;

  /// Before TSSetFromOptions: fixed steps unless -ts_adapt_type is given (TSBDF would adapt
  /// by default), and whether Newton starts backward Euler's steps from the extrapolation of
  /// the last increment (extrapolate(); BDF extrapolates by itself).
  PetscErrorCode beforeOptions(TS ts);
  /// After TSSetFromOptions: refuses integrators, orders and tolerances that are not
  /// supported, with the reason; with -ts_adapt_type basic sets up the per-field error
  /// control. `initial` is the local initial state (boundary values included) at time t0.
  PetscErrorCode afterOptions(TS ts, DM dm, const Problem &problem, double t0, Vec initial);

  /// For a residual at (stage) time t: the time since the last accepted state, and the
  /// integrator's difference formula for prescribed values, on `previous` (the local last
  /// accepted state) and the states before it.
  PetscErrorCode stencil(TS ts, double t, Vec previous, RateStencil *stencil, double *since);
  /// The time from the last accepted state to t (what stencil() reports as `since`).
  double sinceAccepted(double t) const { return t - accepted_time_[0]; }
  /// After an accepted step at time t, before the caller overwrites `previous` (the local
  /// state of the step before) with the new state; `global` is the new solution.
  PetscErrorCode accept(double t, Vec previous, Vec global);

  bool adaptive() const { return adaptive_; }
  /// Backward Euler: Newton starts from last state + dt/dt_last * last increment.
  bool extrapolate() const { return extrapolate_; }
  bool bdf() const { return bdf_; }
  /// "backward Euler", "BDF2", ... for the progress lines.
  const char *name() const;

  PetscErrorCode destroy();

private:
  friend PetscErrorCode timeIntegrationCheckStage(TSAdapt, TS, PetscReal, Vec, PetscBool *);
  /// Absolute tolerances of every unknown from the field scales and the stage Y.
  PetscErrorCode updateTolerances(Vec Y);
  PetscErrorCode fieldChanges(Vec X, double change[3]) const;

  const Problem *problem_ = nullptr;
  bool bdf_ = false;
  int order_ = 1;
  bool adaptive_ = false;
  bool extrapolate_ = false;
  double rtol_ = 0.0;
  /// Times of the last two accepted states (accepted_ of them known) and the local state of
  /// the older one (the newer one is the caller's `previous`).
  double accepted_time_[2] = {0.0, 0.0};
  int accepted_ = 0;
  Vec before_previous_ = nullptr;
  /// BDF start-up: PETSc's TSBDF first takes a backward-Euler half step to t0 + dt/2 and then
  /// BDF2 through t0, t0 + dt/2 and t0 + dt; the prescribed values at the half step.
  double half_time_ = -1.0;
  Vec half_ = nullptr;
  /// Error control: field of every unknown (global), the initial state, the absolute
  /// tolerances (global), and the largest change of each field since the initial state over
  /// the accepted states.
  Vec field_ = nullptr, initial_global_ = nullptr, tolerance_ = nullptr;
  TSAdapt adapt_ = nullptr; ///< borrowed from the TS
  double scale_[3] = {0.0, 0.0, 0.0};
};

} // namespace poroseam
