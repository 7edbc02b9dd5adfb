#include "poroseam/nullspace.hpp"

#include "poroseam/layout.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"
#include "poroseam/vertex_blocks.hpp"

#include <petscdmplex.h>
#include <unordered_set>
#include <vector>

namespace poroseam {

/// Rigid-body modes restricted to the free displacement dofs, orthonormalised. Built by hand
/// because MatNullSpaceCreateRigidBody needs whole blocks and constraints remove dofs. Every
/// point that carries displacement unknowns takes the mode at its node (a vertex; at order 2
/// also edge, face and cell nodes, displacementNodeLocation).
PetscErrorCode displacementRigidBodyModes(DM dm, int dim, bool axisymmetric, IS displacement,
                                          MatNullSpace *space)
{
  PetscSection s, csec;
  Vec coords, local, global;
  PetscInt pStart, pEnd, vStart, vEnd;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(PetscSectionGetChart(s, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  // Axisymmetric: only the axial translation is free of strain (a radial displacement strains
  // the hoop), but both translations are smooth, low-energy modes worth giving to AMG.
  const int count = axisymmetric ? 2 : dim == 2 ? 3 : 6;
  std::vector<Vec> modes(count);
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGetGlobalVector(dm, &global));
  // The nodes of this rank's local points once: their offsets and positions.
  std::vector<PetscInt> offsets;
  std::vector<double> positions;
  const PetscScalar *x;
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt pt = pStart; pt < pEnd; ++pt) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetFieldDof(s, pt, kDisplacementField, &dof));
    if (dof < dim) continue;
    PetscCall(PetscSectionGetFieldOffset(s, pt, kDisplacementField, &off));
    double p[3];
    PetscCall(displacementNodeLocation(dm, csec, x, pt, dim, p));
    offsets.push_back(off);
    positions.insert(positions.end(), p, p + 3);
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  for (int m = 0; m < count; ++m) {
    PetscScalar *u;
    PetscCall(VecSet(local, 0.0));
    PetscCall(VecGetArray(local, &u));
    for (size_t k = 0; k < offsets.size(); ++k) {
      const double *p = &positions[3 * k];
      double mode[3] = {0, 0, 0};
      if (m < dim)
        mode[m] = 1.0;
      else if (dim == 2)
        mode[0] = -p[1], mode[1] = p[0];
      else if (m == 3)
        mode[0] = -p[1], mode[1] = p[0];
      else if (m == 4)
        mode[1] = -p[2], mode[2] = p[1];
      else
        mode[0] = p[2], mode[2] = -p[0];
      for (int d = 0; d < dim; ++d)
        u[offsets[k] + d] = mode[d];
    }
    PetscCall(VecRestoreArray(local, &u));
    PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, global));
    Vec sub;
    PetscCall(VecGetSubVector(global, displacement, &sub));
    PetscCall(VecDuplicate(sub, &modes[m]));
    PetscCall(VecCopy(sub, modes[m]));
    PetscCall(VecRestoreSubVector(global, displacement, &sub));
  }
  PetscCall(DMRestoreGlobalVector(dm, &global));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscCall(orthonormalize(modes));
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)dm), PETSC_FALSE, count, modes.data(),
                               space));
  for (auto &v : modes)
    PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode orthonormalize(std::vector<Vec> &vectors)
{
  PetscFunctionBeginUser;
  for (size_t m = 0; m < vectors.size(); ++m) { // modified Gram-Schmidt
    for (size_t k = 0; k < m; ++k) {
      PetscScalar dot;
      PetscCall(VecDot(vectors[m], vectors[k], &dot));
      PetscCall(VecAXPY(vectors[m], -dot, vectors[k]));
    }
    PetscCall(VecNormalize(vectors[m], nullptr));
  }
  PetscFunctionReturn(0);
}

namespace {

/// Splits of the pressure split, in its own numbering: the bulk and the interface pressures.
struct InnerSplits {
  IS pressure = nullptr, interface_pressure = nullptr;
  bool done = false;
};

PetscErrorCode destroyInnerSplits(void *ctx)
{
  InnerSplits *inner = static_cast<InnerSplits *>(ctx);
  PetscFunctionBeginUser;
  PetscCall(ISDestroy(&inner->pressure));
  PetscCall(ISDestroy(&inner->interface_pressure));
  delete inner;
  PetscFunctionReturn(0);
}

/// Before the first solve: once the outer fieldsplit exists, give the solver of the
/// "pressures" split (the Schur complement) its own splits "pressure" and
/// "interface_pressure" when it is a fieldsplit itself (-fieldsplit_pressures_pc_type
/// fieldsplit). PETSc sets sub-solvers up at their first use, so this comes in time.
PetscErrorCode nameInnerSplits(KSP ksp, Vec, Vec, void *ctx)
{
  InnerSplits *inner = static_cast<InnerSplits *>(ctx);
  PetscFunctionBeginUser;
  if (inner->done) PetscFunctionReturn(0);
  inner->done = true;
  PC pc, schur_pc;
  PetscInt n;
  KSP *sub;
  PetscCall(KSPSetUp(ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCFieldSplitGetSubKSP(pc, &n, &sub));
  if (n == 2) {
    PetscBool fieldsplit;
    PetscCall(KSPGetPC(sub[1], &schur_pc));
    PetscCall(PetscObjectTypeCompare((PetscObject)schur_pc, PCFIELDSPLIT, &fieldsplit));
    if (fieldsplit) {
      PetscCall(PCFieldSplitSetIS(schur_pc, "pressure", inner->pressure));
      if (inner->interface_pressure)
        PetscCall(PCFieldSplitSetIS(schur_pc, "interface_pressure", inner->interface_pressure));
      else // one split: the inner fieldsplit just applies the pressure solver
        PetscCall(PCFieldSplitSetType(schur_pc, PC_COMPOSITE_ADDITIVE));
    }
  }
  PetscCall(PetscFree(sub));
  PetscFunctionReturn(0);
}

/// Young's modulus of each cell's region, from the problem's bulk cells (0 for the
/// interfaces' cohesive cells, which belong to no region), for the stiff bodies of
/// vertex_blocks.
PetscErrorCode cellModuli(DM dm, const Scene &scene, const Problem &problem,
                          std::vector<PetscReal> &modulus)
{
  PetscInt cStart, cEnd;
  std::vector<PetscInt> cells;
  std::vector<int> regions;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  modulus.assign(cEnd - cStart, 0.0);
  problem.cellRegions(cells, regions);
  for (size_t i = 0; i < cells.size(); ++i)
    modulus[cells[i] - cStart] = scene.regions[regions[i]].young;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode configureFieldSplit(TS ts, DM dm, const Scene &scene, const Problem &problem,
                                   Vec *jacobian_diagonal)
{
  SNES snes;
  KSP ksp;
  PC pc;
  PetscBool fieldsplit;
  PetscFunctionBeginUser;
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &fieldsplit));
  if (!fieldsplit) PetscFunctionReturn(0);
  PetscInt numFields;
  char **names;
  IS *fields;
  PetscCall(DMCreateFieldIS(dm, &numFields, &names, &fields));
  MatNullSpace modes;
  PetscCall(displacementRigidBodyModes(dm, scene.dim, scene.axisymmetric,
                                       fields[kDisplacementField], &modes));
  PetscCall(DMCreateGlobalVector(dm, jacobian_diagonal));
  std::vector<PetscReal> cell_modulus;
  PetscCall(cellModuli(dm, scene, problem, cell_modulus));
  PetscCall(attachVertexBlocks(dm, scene.dim, scene.axisymmetric, fields[kDisplacementField], modes,
                               ksp, *jacobian_diagonal, cell_modulus));
  PetscCall(PetscObjectCompose((PetscObject)fields[kDisplacementField], "nearnullspace",
                               (PetscObject)modes));
  PetscCall(MatNullSpaceDestroy(&modes));
  // Two splits, as a Schur complement needs: "displacement", and "pressures" holding the bulk
  // and the interface pressures together; inside it, "pressure" and "interface_pressure"
  // (nameInnerSplits).
  IS pressures;
  PetscCall(pressureRows(numFields, fields, &pressures));
  PetscCall(PCFieldSplitSetIS(pc, "displacement", fields[kDisplacementField]));
  if (pressures) {
    PetscInt size;
    PetscCall(ISGetSize(pressures, &size));
    if (size > 0) {
      PetscCall(PCFieldSplitSetIS(pc, "pressures", pressures));
      // The two kinds of pressure inside the pressures split, numbered as in that split
      // (with no interface pressure, the bulk pressure is all of it).
      const PetscInt *merged;
      PetscInt nlocal, first = 0, np;
      PetscCall(ISGetLocalSize(pressures, &nlocal));
      PetscCall(ISGetIndices(pressures, &merged));
      PetscCallMPI(
          MPI_Exscan(&nlocal, &first, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
      const PetscInt *pidx;
      PetscCall(ISGetLocalSize(fields[kPressureField], &np));
      PetscCall(ISGetIndices(fields[kPressureField], &pidx));
      const bool with_p3 = numFields > kInterfacePressureField;
      std::vector<PetscInt> inner_p, inner_p3;
      const std::unordered_set<PetscInt> bulk(pidx, pidx + np);
      for (PetscInt k = 0; k < nlocal; ++k)
        (bulk.count(merged[k]) ? inner_p : inner_p3).push_back(first + k);
      PetscCall(ISRestoreIndices(fields[kPressureField], &pidx));
      PetscCall(ISRestoreIndices(pressures, &merged));
      auto *inner = new InnerSplits;
      MPI_Comm comm = PetscObjectComm((PetscObject)dm);
      PetscCall(ISCreateGeneral(comm, (PetscInt)inner_p.size(), inner_p.data(), PETSC_COPY_VALUES,
                                &inner->pressure));
      if (with_p3)
        PetscCall(ISCreateGeneral(comm, (PetscInt)inner_p3.size(), inner_p3.data(),
                                  PETSC_COPY_VALUES, &inner->interface_pressure));
      PetscContainer owner;
      PetscCall(PetscContainerCreate(comm, &owner));
      PetscCall(PetscContainerSetPointer(owner, inner));
      PetscCall(PetscContainerSetUserDestroy(owner, destroyInnerSplits));
      PetscCall(PetscObjectCompose((PetscObject)ksp, "poroseam inner splits", (PetscObject)owner));
      PetscCall(PetscContainerDestroy(&owner));
      PetscCall(KSPSetPreSolve(ksp, nameInnerSplits, inner));
    }
    PetscCall(ISDestroy(&pressures));
  }
  for (PetscInt f = 0; f < numFields; ++f) {
    PetscCall(PetscFree(names[f]));
    PetscCall(ISDestroy(&fields[f]));
  }
  PetscCall(PetscFree(names));
  PetscCall(PetscFree(fields));
  PetscFunctionReturn(0);
}

} // namespace poroseam
