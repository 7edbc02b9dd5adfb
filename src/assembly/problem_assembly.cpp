// The problem's assembly: residual and Jacobian of the bulk cells through the closure cache
// (the cell kernel, cell_kernel.hpp), the interfaces, and the natural conditions on loaded
// faces. Part of Problem (problem.hpp); set-up in problem.cpp.
#include "poroseam/problem.hpp"

#include "cell_kernel.hpp"

#include "poroseam/closure_cache.hpp"
#include "poroseam/layout.hpp"

#include <cmath>

namespace poroseam {

PetscErrorCode Problem::residual(double t, Vec local, Vec local_rate, const ResidualMode &mode,
                                 Vec f) const
{
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(events_.residual));
  PetscCall(assembleResidual(t, local, local_rate, mode, f));
  PetscCall(endLogEvent(events_.residual));
  PetscFunctionReturn(0);
}

bool Problem::cellGeometry(size_t i, const PetscScalar *coords, std::vector<double> &xc) const
{
  if (node_places_.empty()) {
    const int nc = closures_.coordinateSize(i);
    xc.resize(nc);
    gatherClosure(coords, closures_.coordinates(i), nc, xc.data());
    return false;
  }
  // The closure's first values are the displacement nodes, in the element's node order.
  const int ng = elements_[cells_[i].element].num_nodes * dim_;
  xc.resize(ng);
  gatherClosure(node_places_.data(), closures_.local(i), ng, xc.data());
  return true;
}

void Problem::cellTerms(size_t i, const PetscScalar *u, const PetscScalar *u_t,
                        const PetscScalar *coords, double mass_scale, double shift,
                        bool with_jacobian, CellWork &w, physics::SkeletonResponse *responses) const
{
  const BulkCell &cell = cells_[i];
  CellMaterial m = materialOf(*scene_, scene_->regions[cell.region], cell.size);
  const bool history = cell.history != kNoHistory;
  if (history) m.law = &laws_[cell.region];
  const int n = closures_.closureSize(i);
  w.x.resize(n), w.xdot.resize(n);
  gatherClosure(u, closures_.local(i), n, w.x.data());
  gatherClosure(u_t, closures_.local(i), n, w.xdot.data());
  const bool curved = cellGeometry(i, coords, w.xc);
  w.F.assign(n, 0.0);
  if (with_jacobian) w.K.assign((size_t)n * n, 0.0);
  CellKernel kernel{
      elements_[cell.element], dim_, m, scene_->hasPressure() && m.porous, mass_scale, {0, 0, 0},
      scene_->axisymmetric};
  for (int d = 0; d < dim_; ++d)
    kernel.gravity[d] = gravityVector(d);
  kernel.work = &w.kernel;
  kernel.curved = curved;
  if (history) {
    kernel.history = &skeleton_committed_[cell.history];
    kernel.responses = responses;
  }
  kernel(
      w.xc.data(), w.x.data(), w.xdot.data(), n,
      [&](const double *p, double s0[3][3]) { initialStress(p, cell.region, s0); },
      [&](const double *p) { return initialPressure(p); }, w.F.data(), shift,
      with_jacobian ? w.K.data() : nullptr);
}

PetscErrorCode Problem::assembleResidual(double t, Vec local, Vec local_rate,
                                         const ResidualMode &mode, Vec f) const
{
  PetscSection s, csec;
  Vec coords;
  PetscFunctionBeginUser;
  PetscCall(VecSet(f, 0.0));
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  CellWork work;
  {
    // Closures through the cache (closure_cache.hpp), read from and added to the local arrays:
    // the same values and additions, in the same order, as DMPlexVec{Get,Set}Closure.
    const PetscScalar *ua, *ra, *ca;
    PetscScalar *fa;
    PetscCall(VecGetArrayRead(local, &ua));
    PetscCall(VecGetArrayRead(local_rate, &ra));
    PetscCall(VecGetArrayRead(coords, &ca));
    PetscCall(VecGetArray(f, &fa));
    for (size_t i = 0; i < cells_.size(); ++i) {
      cellTerms(i, ua, ra, ca, mode.mass_scale, 0.0, false, work);
      // All entries, constrained dofs included: they are the reactions (ADD_ALL_VALUES).
      addClosure(work.F.data(), closures_.local(i), closures_.closureSize(i), fa);
    }
    PetscCall(VecRestoreArray(f, &fa));
    PetscCall(VecRestoreArrayRead(coords, &ca));
    PetscCall(VecRestoreArrayRead(local_rate, &ra));
    PetscCall(VecRestoreArrayRead(local, &ua));
  }
  PetscCall(beginLogEvent(events_.interface_residual));
  PetscCall(interfaces_.residual(local, InterfaceRates{local_rate, mode.dt}, mode.mass_scale, f));
  PetscCall(endLogEvent(events_.interface_residual));
  if (!mode.include_loads) PetscFunctionReturn(0);
  PetscCall(addLoads(t, mode.mass_scale, f, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::jacobian(double t, double shift, Vec local, Vec local_rate,
                                 const ResidualMode &mode, Mat J) const
{
  const double mass_scale = mode.mass_scale;
  Vec coords;
  const PetscScalar *ua, *ra, *ca;
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(events_.jacobian));
  // The cells without history (linear elasticity, Biot) have a Jacobian that depends on the
  // shift and the mass scale only, not on the state: it is assembled once and copied while
  // those stay the same (fixed time steps). Measured on the 3D caisson, 160k unknowns, 2
  // ranks: the bulk loop took 0.96 s per Jacobian, 14 % of the time steps.
  const bool reuse = linear_cells_jacobian_ && shift == linear_cells_shift_ &&
                     mass_scale == linear_cells_mass_scale_;
  if (reuse)
    PetscCall(MatCopy(linear_cells_jacobian_, J, SAME_NONZERO_PATTERN));
  else
    PetscCall(MatZeroEntries(J));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  CellWork work;
  std::vector<PetscInt> rows;
  // Closures and matrix indices through the cache (closure_cache.hpp); one MatSetValues per
  // cell with the indices DMPlexMatSetClosure would compute (constrained dofs negative).
  PetscCall(VecGetArrayRead(local, &ua));
  PetscCall(VecGetArrayRead(local_rate, &ra));
  PetscCall(VecGetArrayRead(coords, &ca));
  auto addCells = [&](bool with_history) -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (size_t i = 0; i < cells_.size(); ++i) {
      if ((cells_[i].history != kNoHistory) != with_history) continue;
      cellTerms(i, ua, ra, ca, mass_scale, shift, true, work);
      const int n = closures_.closureSize(i);
      rows.resize(n);
      closures_.globalIndices(i, rows.data());
      PetscCall(MatSetValues(J, n, rows.data(), n, rows.data(), work.K.data(), ADD_VALUES));
    }
    PetscFunctionReturn(0);
  };
  if (!reuse) {
    PetscCall(addCells(false));
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
    if (linear_cells_jacobian_)
      PetscCall(MatCopy(J, linear_cells_jacobian_, SAME_NONZERO_PATTERN));
    else
      PetscCall(MatDuplicate(J, MAT_COPY_VALUES, &linear_cells_jacobian_));
    linear_cells_shift_ = shift;
    linear_cells_mass_scale_ = mass_scale;
  }
  if (any_skeleton_history_) PetscCall(addCells(true));
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(VecRestoreArrayRead(local_rate, &ra));
  PetscCall(VecRestoreArrayRead(local, &ua));
  PetscCall(beginLogEvent(events_.interface_jacobian));
  PetscCall(interfaces_.jacobian(local, InterfaceRates{local_rate, mode.dt}, shift, mass_scale, J));
  PetscCall(endLogEvent(events_.interface_jacobian));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  // Without interfaces and history J is the copy made or taken above: when taken, it is the
  // very matrix of the last call (state-dependent terms would make it differ). Decided from
  // the scene, not this rank's cells, so that every rank agrees.
  jacobian_repeated_ = reuse && !any_skeleton_history_ && scene_->interfaces.empty();
  PetscCall(endLogEvent(events_.jacobian));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::release()
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&linear_cells_jacobian_));
  PetscFunctionReturn(0);
}

} // namespace poroseam
