// Integration-point history of the bulk cells whose skeleton law has one (Problem's part that
// mirrors the interfaces' history, interface_assembly.cpp): the law is evaluated from the
// committed history at every residual and Jacobian (the trial state is never stored), and the
// history moves on only in commit(), which the time loop calls after an accepted step. A
// failed or cut step therefore leaves nothing to roll back. Checkpoints carry the committed
// history; the initial stress is checked against the yield surface at setup.
#include "poroseam/problem.hpp"

#include "cell_kernel.hpp"

#include "poroseam/collective_check.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cstring>
#include <sstream>
#include <type_traits>

namespace poroseam {

static_assert(std::is_trivially_copyable_v<physics::SkeletonHistory> &&
                  sizeof(physics::SkeletonHistory) % sizeof(double) == 0,
              "SkeletonHistory must be plain doubles to be checkpointed as numbers");

PetscErrorCode Problem::skeletonResponses(
    Vec local, const std::function<PetscErrorCode(size_t, const physics::SkeletonResponse *)> &visit)
    const
{
  Vec coords;
  const PetscScalar *ua, *ca;
  CellWork work;
  std::vector<physics::SkeletonResponse> responses;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(VecGetArrayRead(local, &ua));
  PetscCall(VecGetArrayRead(coords, &ca));
  for (size_t i = 0; i < cells_.size(); ++i) {
    if (cells_[i].history == kNoHistory) continue;
    responses.resize(elements_[cells_[i].element].num_quadrature);
    // The rate only enters the mass balance, which is not looked at: the state stands for it.
    cellTerms(i, ua, ua, ca, 1.0, 0.0, false, work, responses.data());
    PetscCall(visit(i, responses.data()));
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(VecRestoreArrayRead(local, &ua));
  PetscFunctionReturn(0);
}

PetscErrorCode Problem::commit(Vec local)
{
  PetscFunctionBeginUser;
  PetscCall(interfaces_.commit(local));
  if (skeleton_committed_.empty()) PetscFunctionReturn(0);
  // Every point's update from the committed history, then all at once.
  std::vector<physics::SkeletonHistory> updated = skeleton_committed_;
  std::vector<physics::YieldState> state = skeleton_state_;
  PetscCall(skeletonResponses(local, [&](size_t i, const physics::SkeletonResponse *r) {
    const size_t first = cells_[i].history;
    for (int q = 0; q < elements_[cells_[i].element].num_quadrature; ++q) {
      updated[first + q] = r[q].updated;
      state[first + q] = r[q].state;
    }
    return PetscErrorCode(0);
  }));
  skeleton_committed_.swap(updated);
  skeleton_state_.swap(state);
  PetscFunctionReturn(0);
}

std::vector<double> Problem::committedSkeletonHistory() const
{
  constexpr size_t n = kSkeletonValues - 1;
  std::vector<double> values(skeleton_committed_.size() * kSkeletonValues);
  for (size_t p = 0; p < skeleton_committed_.size(); ++p) {
    std::memcpy(&values[p * kSkeletonValues], &skeleton_committed_[p], n * sizeof(double));
    values[p * kSkeletonValues + n] = (double)skeleton_state_[p];
  }
  return values;
}

PetscErrorCode Problem::restoreSkeletonHistory(const std::vector<double> &values)
{
  constexpr size_t n = kSkeletonValues - 1;
  PetscFunctionBeginUser;
  PetscCheck(values.size() == skeletonHistoryValues(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "skeleton history of %zu values for %zu integration points", values.size(),
             skeleton_committed_.size());
  for (size_t p = 0; p < skeleton_committed_.size(); ++p) {
    std::memcpy(static_cast<void *>(&skeleton_committed_[p]), &values[p * kSkeletonValues], n * sizeof(double));
    skeleton_state_[p] = (physics::YieldState)(int)values[p * kSkeletonValues + n];
  }
  PetscFunctionReturn(0);
}

void Problem::visitSkeletonCells(
    const std::function<void(PetscInt, double, int)> &f) const
{
  for (const BulkCell &cell : cells_) {
    if (cell.history == kNoHistory) continue;
    const int nq = elements_[cell.element].num_quadrature;
    double eqps = 0.0;
    int state = 0;
    for (int q = 0; q < nq; ++q) {
      eqps += skeleton_committed_[cell.history + q].equivalent_plastic_strain;
      state = std::max(state, (int)skeleton_state_[cell.history + q]);
    }
    f(cell.cell, eqps / nq, state);
  }
}

PetscErrorCode Problem::checkInitialYield(MPI_Comm comm)
{
  Vec zero;
  std::string error;
  PetscFunctionBeginUser;
  // Zero displacement: the law sees its initial stress alone.
  PetscCall(DMGetLocalVector(dm_, &zero));
  PetscCall(VecSet(zero, 0.0));
  PetscCall(skeletonResponses(zero, [&](size_t i, const physics::SkeletonResponse *r) {
    const int nq = elements_[cells_[i].element].num_quadrature;
    for (int q = 0; q < nq && error.empty(); ++q) {
      if (r[q].state == physics::YieldState::elastic) continue;
      const Region &region = scene_->regions[cells_[i].region];
      PetscReal volume, centroid[3] = {0, 0, 0};
      PetscCall(DMPlexComputeCellGeometryFVM(dm_, cells_[i].cell, &volume, centroid, nullptr));
      double s0[3][3];
      initialStress(centroid, cells_[i].region, s0);
      std::ostringstream msg;
      msg << "region '" << region.name << "': the initial effective stress lies outside the "
          << "yield surface of its material (yield state " << (int)r[q].state << ") near ("
          << centroid[0] << ", " << centroid[1] << (dim_ == 3 ? ", " : "")
          << (dim_ == 3 ? std::to_string(centroid[2]) : std::string()) << "), where its diagonal is "
          << s0[0][0] << ", " << s0[1][1] << ", " << s0[2][2]
          << " Pa. The run would start out of equilibrium: choose -region_" << region.name
          << "_K0 between the active and passive earth pressure coefficients of its strength, "
             "or a larger cohesion";
      error = msg.str();
    }
    return PetscErrorCode(0);
  }));
  PetscCall(DMRestoreLocalVector(dm_, &zero));
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

} // namespace poroseam
