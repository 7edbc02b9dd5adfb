// PETSc's own viewers of the solution vector (-ts_monitor_solution_vtk, -ts_monitor_solution
// hdf5:..., -snes_view_solution vtk:..., draw and GLVis viewers). DMPlex views a global vector
// through a pooled local work vector (VecView_Plex) and inserts prescribed values only for
// PetscDS boundary conditions; poroseam's prescribed values are PetscSection constraints, so
// their entries kept whatever the work vector last held: the residual's reactions, which
// showed as displacements of 6.6e7 m on the caisson. The solution vector therefore gets a view
// operation (inherited by the vectors TS and SNES duplicate from it) that fills a local vector
// with the unknowns and the prescribed values, and lets DMPlex view that local vector (which
// handles VTK, HDF5, draw and GLVis). Other viewers (ASCII, binary) see the unknowns as PETSc
// shows them.

#include "run.hpp"

namespace poroseam {
namespace simulation_detail {
namespace {

constexpr const char *kViewContext = "poroseam_solution_view";

struct ViewContext {
  const Run *run = nullptr;
};

PetscErrorCode destroyContext(void *context)
{
  delete static_cast<ViewContext *>(context);
  return 0;
}

PetscErrorCode viewSolution(Vec X, PetscViewer viewer)
{
  PetscContainer container = nullptr;
  ViewContext *context = nullptr;
  PetscBool mesh;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)X, kViewContext, (PetscObject *)&container));
  PetscCheck(container, PetscObjectComm((PetscObject)X), PETSC_ERR_PLIB,
             "viewSolution: the vector has no view context");
  PetscCall(PetscContainerGetPointer(container, (void **)&context));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)viewer, &mesh, PETSCVIEWERVTK, PETSCVIEWERHDF5,
                                      PETSCVIEWERDRAW, PETSCVIEWERGLVIS, ""));
  if (!mesh) {
    // The unknowns as a plain vector (no DM): what PETSc shows of a DMPlex vector here.
    Vec plain;
    PetscInt n, bs;
    const char *name;
    PetscCall(VecGetLocalSize(X, &n));
    PetscCall(VecGetBlockSize(X, &bs));
    PetscCall(VecCreate(PetscObjectComm((PetscObject)X), &plain));
    PetscCall(VecSetSizes(plain, n, PETSC_DETERMINE));
    PetscCall(VecSetBlockSize(plain, bs));
    PetscCall(VecSetType(plain, VECSTANDARD));
    PetscCall(PetscObjectGetName((PetscObject)X, &name));
    PetscCall(PetscObjectSetName((PetscObject)plain, name));
    PetscCall(VecCopy(X, plain));
    PetscCall(VecView(plain, viewer));
    PetscCall(VecDestroy(&plain));
    PetscFunctionReturn(0);
  }
  DM dm;
  Vec local;
  const char *name;
  PetscCall(VecGetDM(X, &dm));
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(PetscObjectGetName((PetscObject)X, &name));
  PetscCall(PetscObjectSetName((PetscObject)local, name));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
  // The time of the state: the last residual's (a Newton iterate's, or the accepted step's
  // when a monitor views it after the step).
  PetscCall(context->run->problem.insertBoundaryValues(context->run->stage_time, local));
  PetscCall(VecView(local, viewer));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode attachSolutionView(const Run &run, Vec X)
{
  PetscContainer container;
  PetscFunctionBeginUser;
  auto *context = new ViewContext;
  context->run = &run;
  PetscCall(PetscContainerCreate(PetscObjectComm((PetscObject)X), &container));
  PetscCall(PetscContainerSetPointer(container, context));
  PetscCall(PetscContainerSetUserDestroy(container, destroyContext));
  PetscCall(PetscObjectCompose((PetscObject)X, kViewContext, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscCall(VecSetOperation(X, VECOP_VIEW, (void (*)(void))viewSolution));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
