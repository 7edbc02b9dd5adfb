// PETSc's own viewers of the solution vector (-ts_monitor_solution_vtk, -ts_monitor_solution
// hdf5:..., -snes_view_solution vtk:..., draw and GLVis viewers). DMPlex views a global vector
// through a pooled local work vector (VecView_Plex) and inserts prescribed values only for
// PetscDS boundary conditions; poroseam's prescribed values are PetscSection constraints, so
// their entries kept whatever the work vector last held: the residual's reactions, which
// showed as displacements of 6.6e7 m on the caisson. The solution vector therefore gets a view
// operation (inherited by the vectors TS and SNES duplicate from it) that fills a local vector
// with the unknowns and the prescribed values, and lets DMPlex view that local vector (which
// handles VTK, HDF5, draw and GLVis). That vector lives on a copy of the mesh with the
// displacement and the pressure on every vertex, NaN pressure where the solution has none
// (vertices of non-porous regions only): PETSc's VTK writer reads a field at its offset
// whether or not the vertex has it, so the steel showed its displacement as pressure. Other
// viewers (ASCII, binary) see the unknowns as PETSc shows them.

#include "run.hpp"

#include "poroseam/layout.hpp"

#include <limits>

namespace poroseam {
namespace simulation_detail {
namespace {

constexpr const char *kViewContext = "poroseam_solution_view";

struct ViewContext {
  const Run *run = nullptr;
  DM vertex_dm = nullptr; ///< the mesh with displacement (and pressure) on every vertex
  bool pressure = false;  ///< the solution has a pressure field
};

PetscErrorCode destroyContext(void *context)
{
  auto *c = static_cast<ViewContext *>(context);
  PetscErrorCode error = DMDestroy(&c->vertex_dm);
  delete c;
  return error;
}

/// A copy of `dm` (same mesh and labels) whose section has the displacement (dim components)
/// and, with `pressure`, the pressure on every vertex, and nothing elsewhere.
PetscErrorCode vertexFieldsDM(DM dm, PetscInt dim, bool pressure, DM *out)
{
  PetscSection s;
  PetscInt pStart, pEnd, vStart, vEnd;
  PetscFunctionBeginUser;
  PetscCall(DMClone(dm, out));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, pressure ? 2 : 1));
  PetscCall(PetscSectionSetFieldName(s, 0, "displacement"));
  PetscCall(PetscSectionSetFieldComponents(s, 0, dim));
  if (pressure) {
    PetscCall(PetscSectionSetFieldName(s, 1, "pressure"));
    PetscCall(PetscSectionSetFieldComponents(s, 1, 1));
  }
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscCall(PetscSectionSetFieldDof(s, v, 0, dim));
    if (pressure) PetscCall(PetscSectionSetFieldDof(s, v, 1, 1));
    PetscCall(PetscSectionSetDof(s, v, dim + (pressure ? 1 : 0)));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(*out, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(0);
}

/// `local` (a local vector of the solution DM) copied onto the vertex DM's local vector `out`.
PetscErrorCode copyToVertices(DM dm, Vec local, const ViewContext &c, Vec out)
{
  PetscSection from, to;
  PetscInt vStart, vEnd, dim;
  const PetscScalar *a;
  PetscScalar *b;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetLocalSection(dm, &from));
  PetscCall(DMGetLocalSection(c.vertex_dm, &to));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(VecGetArrayRead(local, &a));
  PetscCall(VecGetArray(out, &b));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt dof, off, target;
    PetscCall(PetscSectionGetFieldDof(from, v, kDisplacementField, &dof));
    PetscCall(PetscSectionGetFieldOffset(from, v, kDisplacementField, &off));
    PetscCall(PetscSectionGetFieldOffset(to, v, 0, &target));
    for (PetscInt d = 0; d < dim; ++d)
      b[target + d] = d < dof ? a[off + d] : 0.0;
    if (!c.pressure) continue;
    PetscCall(PetscSectionGetFieldDof(from, v, kPressureField, &dof));
    PetscCall(PetscSectionGetFieldOffset(from, v, kPressureField, &off));
    PetscCall(PetscSectionGetFieldOffset(to, v, 1, &target));
    b[target] = dof > 0 ? a[off] : std::numeric_limits<double>::quiet_NaN();
  }
  PetscCall(VecRestoreArray(out, &b));
  PetscCall(VecRestoreArrayRead(local, &a));
  PetscFunctionReturn(0);
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
  Vec local, vertices;
  const char *name;
  PetscCall(VecGetDM(X, &dm));
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
  // The time of the state: the last residual's (a Newton iterate's, or the accepted step's
  // when a monitor views it after the step).
  PetscCall(context->run->problem.insertBoundaryValues(context->run->stage_time, local));
  PetscCall(DMGetLocalVector(context->vertex_dm, &vertices));
  PetscCall(copyToVertices(dm, local, *context, vertices));
  PetscCall(PetscObjectGetName((PetscObject)X, &name));
  PetscCall(PetscObjectSetName((PetscObject)vertices, name));
  PetscCall(VecView(vertices, viewer));
  PetscCall(DMRestoreLocalVector(context->vertex_dm, &vertices));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode attachSolutionView(const Run &run, Vec X)
{
  PetscContainer container;
  PetscFunctionBeginUser;
  PetscSection section;
  PetscInt fields, dim;
  PetscCall(DMGetLocalSection(run.dm, &section));
  PetscCall(PetscSectionGetNumFields(section, &fields));
  PetscCall(DMGetDimension(run.dm, &dim));
  auto *context = new ViewContext;
  context->run = &run;
  context->pressure = fields > kPressureField;
  PetscCall(vertexFieldsDM(run.dm, dim, context->pressure, &context->vertex_dm));
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
