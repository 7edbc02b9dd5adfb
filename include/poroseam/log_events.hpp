// PETSc profiling of a run: poroseam's own log events and the phases of a run, so that
// -log_view shows where the time goes next to PETSc's events (SNESFunctionEval, PCSetUp, ...).
// scripts/bench reads them.
#pragma once

#include <petsclog.h>
#include <petscsys.h>

namespace poroseam {

/// A phase of a run: a log stage, so that -log_view's table lists the events of each phase
/// apart, and an event of the same name, because the nested formats of -log_view
/// (:file:ascii_flamegraph, :file:ascii_xml, which scripts/bench reads for exclusive times)
/// ignore stages.
struct LogPhase {
  PetscLogStage stage = -1;
  PetscLogEvent event = -1;
};

/// Ids of poroseam's log events and phases, registered once per run (registerLogEvents) and
/// handed to whatever assembles or writes. Default-constructed, nothing is registered and the
/// helpers below do nothing: unit tests use the assembly without a run.
///
/// Events (class "poroseam"):
///   PsResidual        Problem::residual: bulk cells and boundary loads, with PsIfaceResidual
///                     inside it (PETSc's times are inclusive: bulk = PsResidual -
///                     PsIfaceResidual). Also the residuals of the outputs (reactions) and of
///                     the convergence test (force level), which SNESFunctionEval does not see.
///   PsJacobian        Problem::jacobian, MatAssemblyBegin/End included; PsIfaceJacobian inside
///   PsIfaceResidual   interface terms of the residual (contact, friction, interface flow)
///   PsIfaceJacobian   interface terms of the Jacobian
///   PsFirstJacobian   the run's first Jacobian (the matrix's first assembly), also in PsJacobian
///   PsOutput          time series rows, fields.h5, interfaces.h5 (opening, writing, closing)
/// Phases (stage "mesh" with event PsMesh, ...): "mesh" (gmsh or reading, scene options,
/// interface split), "distribution" (partition, distribution, orientation check), "layout"
/// (section, assembly set-up, probes, solver objects and the Jacobian's matrix, initial state
/// and its output row), "time stepping" (TSSolve).
struct LogEvents {
  PetscClassId classid = 0;
  PetscLogEvent residual = -1;
  PetscLogEvent jacobian = -1;
  PetscLogEvent interface_residual = -1;
  PetscLogEvent interface_jacobian = -1;
  PetscLogEvent first_jacobian = -1;
  PetscLogEvent output = -1;
  LogPhase mesh, distribution, layout, time_stepping;
};

/// Registers the class, events and phases (an existing stage or event of the same name is
/// reused, so a second run in the same process is fine). Not collective, but every rank must
/// call it at the same point: nested logging matches events across ranks by id.
PetscErrorCode registerLogEvents(LogEvents *events);

/// PetscLogEventBegin/End of a registered event; nothing for an unregistered one (-1).
inline PetscErrorCode beginLogEvent(PetscLogEvent event)
{
  return event >= 0 ? PetscLogEventBegin(event, 0, 0, 0, 0) : 0;
}
inline PetscErrorCode endLogEvent(PetscLogEvent event)
{
  return event >= 0 ? PetscLogEventEnd(event, 0, 0, 0, 0) : 0;
}

/// Enters a phase (pushes its stage, begins its event); nothing when it is not registered.
PetscErrorCode beginLogPhase(const LogPhase &phase);
/// Leaves the phase entered last (ends its event, pops its stage).
PetscErrorCode endLogPhase(const LogPhase &phase);

} // namespace poroseam
