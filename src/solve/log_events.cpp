#include "poroseam/log_events.hpp"

namespace poroseam {
namespace {

PetscErrorCode registerPhase(const char *stage, const char *event, PetscClassId classid,
                             LogPhase *phase)
{
  PetscFunctionBeginUser;
  // PETSc refuses a second stage of the same name (events it deduplicates itself).
  PetscCall(PetscLogStageGetId(stage, &phase->stage));
  if (phase->stage < 0) PetscCall(PetscLogStageRegister(stage, &phase->stage));
  PetscCall(PetscLogEventRegister(event, classid, &phase->event));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode registerLogEvents(LogEvents *events)
{
  LogEvents e;
  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("poroseam", &e.classid));
  PetscCall(PetscLogEventRegister("PsResidual", e.classid, &e.residual));
  PetscCall(PetscLogEventRegister("PsJacobian", e.classid, &e.jacobian));
  PetscCall(PetscLogEventRegister("PsIfaceResidual", e.classid, &e.interface_residual));
  PetscCall(PetscLogEventRegister("PsIfaceJacobian", e.classid, &e.interface_jacobian));
  PetscCall(PetscLogEventRegister("PsFirstJacobian", e.classid, &e.first_jacobian));
  PetscCall(PetscLogEventRegister("PsOutput", e.classid, &e.output));
  PetscCall(registerPhase("mesh", "PsMesh", e.classid, &e.mesh));
  PetscCall(registerPhase("distribution", "PsDistribution", e.classid, &e.distribution));
  PetscCall(registerPhase("layout", "PsLayout", e.classid, &e.layout));
  PetscCall(registerPhase("time stepping", "PsTimeStepping", e.classid, &e.time_stepping));
  *events = e;
  PetscFunctionReturn(0);
}

PetscErrorCode beginLogPhase(const LogPhase &phase)
{
  PetscFunctionBeginUser;
  if (phase.stage >= 0) PetscCall(PetscLogStagePush(phase.stage));
  PetscCall(beginLogEvent(phase.event));
  PetscFunctionReturn(0);
}

PetscErrorCode endLogPhase(const LogPhase &phase)
{
  PetscFunctionBeginUser;
  PetscCall(endLogEvent(phase.event));
  if (phase.stage >= 0) PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

} // namespace poroseam
