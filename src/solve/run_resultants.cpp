// Forces and flows of a run through its boundaries and interfaces (split from simulation.cpp).

#include "run.hpp"

#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"

#include <cmath>
#include <vector>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode collectBoundaryDofs(Run &run)
{
  PetscSection s;
  PetscInt numFields, vStart, vEnd;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(run.dm, &s));
  PetscCall(PetscSectionGetNumFields(s, &numFields));
  PetscCall(DMPlexGetDepthStratum(run.dm, 0, &vStart, &vEnd));
  run.boundary_dofs.assign(run.scene.boundaries.size(), BoundaryDofs());
  for (size_t b = 0; b < run.scene.boundaries.size(); ++b) {
    DMLabel label;
    PetscCall(DMGetLabel(run.dm, boundaryLabelName(run.scene.boundaries[b].name).c_str(), &label));
    IS points = nullptr;
    PetscCall(DMLabelGetStratumIS(label, 1, &points));
    if (!points) continue;
    const PetscInt *idx;
    PetscInt n;
    PetscCall(ISGetLocalSize(points, &n));
    PetscCall(ISGetIndices(points, &idx));
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt v = idx[i];
      // Every point with displacement unknowns (vertices; edges and faces at order 2): a
      // reaction summed over vertices only would drop the edge unknowns' share.
      PetscInt off, dof = 0, udof = 0;
      PetscCall(PetscSectionGetFieldDof(s, v, kDisplacementField, &udof));
      if (!udof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, v, kDisplacementField, &off));
      run.boundary_dofs[b].displacement.push_back(off);
      if (numFields > kPressureField && v >= vStart && v < vEnd)
        PetscCall(PetscSectionGetFieldDof(s, v, kPressureField, &dof));
      if (dof) {
        PetscCall(PetscSectionGetFieldOffset(s, v, kPressureField, &off));
        run.boundary_dofs[b].pressure.push_back(off);
      }
    }
    PetscCall(ISRestoreIndices(points, &idx));
    PetscCall(ISDestroy(&points));
  }
  // Prescribed interface pressures per boundary (the rule of the section constraints)...
  for (size_t b = 0; b < run.scene.boundaries.size(); ++b) {
    std::vector<PetscInt> edges;
    PetscCall(lateralEdgesOnBoundary(run.dm, run.scene.boundaries[b].name, edges));
    for (PetscInt e : edges) {
      PetscInt cdof = 0, off;
      if (numFields > kInterfacePressureField)
        PetscCall(PetscSectionGetFieldConstraintDof(s, e, kInterfacePressureField, &cdof));
      if (!cdof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, e, kInterfacePressureField, &off));
      run.boundary_dofs[b].interface_pressure.push_back(off);
    }
  }
  // ... and per interface (lateral edges, found from their star).
  run.interface_end_dofs.assign(run.scene.interfaces.size(), {});
  DMLabel lateral, iface;
  PetscCall(DMGetLabel(run.dm, kInterfacePressureLabel, &lateral));
  PetscCall(DMGetLabel(run.dm, kInterfaceLabel, &iface));
  IS edges = nullptr;
  if (lateral && iface) PetscCall(DMLabelGetStratumIS(lateral, 1, &edges));
  if (edges) {
    const PetscInt *idx;
    PetscInt n;
    PetscCall(ISGetLocalSize(edges, &n));
    PetscCall(ISGetIndices(edges, &idx));
    for (PetscInt k = 0; k < n; ++k) {
      PetscInt cdof = 0, off;
      PetscCall(PetscSectionGetFieldConstraintDof(s, idx[k], kInterfacePressureField, &cdof));
      if (!cdof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, idx[k], kInterfacePressureField, &off));
      PetscInt nstar, *star = nullptr, which = -1;
      PetscCall(DMPlexGetTransitiveClosure(run.dm, idx[k], PETSC_FALSE, &nstar, &star));
      for (PetscInt m = 0; m < nstar && which < 1; ++m)
        PetscCall(DMLabelGetValue(iface, star[2 * m], &which));
      PetscCall(DMPlexRestoreTransitiveClosure(run.dm, idx[k], PETSC_FALSE, &nstar, &star));
      if (which >= 1) run.interface_end_dofs[which - 1].push_back(off);
    }
    PetscCall(ISRestoreIndices(edges, &idx));
    PetscCall(ISDestroy(&edges));
  }
  PetscFunctionReturn(0);
}

/// Per boundary: force [N], water outflow from the bulk [m3/s] and, with interface flow,
/// water leaving along interfaces that end there [m3/s]; then the longitudinal outflow
/// [m3/s] of every interface (0 without flow or prescribed ends). From the residual without
/// loads.
PetscErrorCode boundaryResultants(Run &run, double t, double dt, Vec local, Vec rate,
                                  std::vector<double> &out)
{
  const int dim = run.scene.dim, per = dim + 1 + (run.scene.hasInterfacePressure() ? 1 : 0);
  Vec f;
  const PetscScalar *r;
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(run.dm, &f));
  PetscCall(run.problem.residual(t, local, rate, ResidualMode{1.0, false, dt}, f));
  PetscCall(VecGetArrayRead(f, &r));
  std::vector<double> mine(run.boundary_dofs.size() * per, 0.0);
  for (size_t b = 0; b < run.boundary_dofs.size(); ++b) {
    // Each rank holds only its own cells' contributions, so the sum over ranks counts each once.
    for (PetscInt off : run.boundary_dofs[b].displacement)
      for (int d = 0; d < dim; ++d)
        mine[b * per + d] += r[off + d];
    for (PetscInt off : run.boundary_dofs[b].pressure)
      mine[b * per + dim] -= r[off];
    for (PetscInt off : run.boundary_dofs[b].interface_pressure)
      mine[b * per + dim + 1] -= r[off];
  }
  // Longitudinal outflow of each interface through its ends with prescribed p3.
  for (const auto &dofs : run.interface_end_dofs) {
    double outflow = 0.0;
    for (PetscInt off : dofs)
      outflow -= r[off];
    mine.push_back(outflow);
  }
  PetscCall(VecRestoreArrayRead(f, &r));
  PetscCall(DMRestoreLocalVector(run.dm, &f));
  out.assign(mine.size(), 0.0);
  PetscCallMPI(MPI_Allreduce(mine.data(), out.data(), (int)mine.size(), MPI_DOUBLE, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

/// Per interface, then per part when it has several: the force on side 1 from side 2
/// [N, per m in 2D] and, with flow, the water from side 1 into the gap, from the gap into
/// side 2 [m3/s], the water stored in the gap [m3] and its rate [m3/s], and the integral of p3
/// over the interface [N]: the normal force the water in the gap exerts.
int interfaceBlock(const Scene &scene, const Interface &i)
{
  return scene.dim + (i.flow ? 5 : 0);
}

PetscErrorCode interfaceResultants(Run &run, Vec local, const InterfaceRates &rates,
                                   std::vector<double> &out)
{
  const Scene &scene = run.scene;
  std::vector<size_t> first;
  size_t count = 0;
  for (const auto &i : scene.interfaces) {
    first.push_back(count);
    count += interfaceBlock(scene, i) * (1 + (i.surfaces.size() > 1 ? i.surfaces.size() : 0));
  }
  std::vector<double> mine(count, 0.0);
  PetscFunctionBeginUser;
  PetscCall(run.problem.interfaces().visit(
      local, rates, [&](int iface, int surface, PetscInt, const InterfacePointState &st) {
        const Interface &in = scene.interfaces[iface];
        const int block = interfaceBlock(scene, in);
        auto add = [&](size_t base) {
          for (int d = 0; d < scene.dim; ++d)
            mine[base + d] += st.weight * st.traction[d];
          if (!in.flow) return;
          mine[base + scene.dim + 0] += st.weight * st.transversal_flux1;
          mine[base + scene.dim + 1] += st.weight * st.transversal_flux2;
          mine[base + scene.dim + 2] += st.weight * st.aperture;
          mine[base + scene.dim + 3] += st.weight * st.aperture_rate;
          mine[base + scene.dim + 4] += st.weight * st.interface_pressure;
        };
        add(first[iface]);
        if (in.surfaces.size() > 1) add(first[iface] + block * (1 + surface));
      }));
  out.assign(count, 0.0);
  PetscCallMPI(MPI_Allreduce(mine.data(), out.data(), (int)count, MPI_DOUBLE, MPI_SUM,
                             PetscObjectComm((PetscObject)run.dm)));
  PetscFunctionReturn(0);
}

/// Force level of the iterate X: the sum of the magnitudes of the forces through every
/// boundary (reactions and applied loads) and interface.
PetscErrorCode forceLevel(Run &run, Vec X, double *level)
{
  Vec local, zero;
  std::vector<double> resultants, interface;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(run.dm, &local));
  PetscCall(DMGetLocalVector(run.dm, &zero));
  PetscCall(VecSet(zero, 0.0));
  PetscCall(DMGlobalToLocal(run.dm, X, INSERT_VALUES, local));
  PetscCall(run.problem.insertBoundaryValues(run.stage_time, local));
  PetscCall(boundaryResultants(run, run.stage_time, run.attempted_dt, local, zero, resultants));
  PetscCall(interfaceResultants(run, local, InterfaceRates{zero, run.attempted_dt}, interface));
  PetscCall(DMRestoreLocalVector(run.dm, &zero));
  PetscCall(DMRestoreLocalVector(run.dm, &local));
  const int dim = run.scene.dim;
  double sum = 0.0;
  const int per = dim + 1 + (run.scene.hasInterfacePressure() ? 1 : 0);
  for (size_t b = 0; b < run.scene.boundaries.size(); ++b)
    for (int d = 0; d < dim; ++d)
      sum += std::fabs(resultants[b * per + d]);
  size_t k = 0; // forces of each whole interface (its parts repeat them)
  for (const auto &in : run.scene.interfaces) {
    for (int d = 0; d < dim; ++d)
      sum += std::fabs(interface[k + d]);
    k += interfaceBlock(run.scene, in) * (1 + (in.surfaces.size() > 1 ? in.surfaces.size() : 0));
  }
  *level = sum;
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
