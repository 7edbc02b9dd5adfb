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

// The history is checkpointed as the doubles it is made of (a field added to it is carried
// along without change here).
static_assert(std::is_trivially_copyable_v<physics::SkeletonHistory> &&
                  sizeof(physics::SkeletonHistory) % sizeof(double) == 0,
              "SkeletonHistory must be plain doubles to be checkpointed as numbers");

PetscErrorCode Problem::skeletonResponses(
    Vec local,
    const std::function<PetscErrorCode(size_t, const physics::SkeletonResponse *)> &visit) const
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
  PetscCall(skeletonResponses(local, [&](size_t i, const physics::SkeletonResponse *r) {
    const size_t first = cells_[i].history;
    for (int q = 0; q < elements_[cells_[i].element].num_quadrature; ++q)
      updated[first + q] = r[q].updated;
    return PetscErrorCode(0);
  }));
  skeleton_committed_.swap(updated);
  PetscFunctionReturn(0);
}

std::vector<double> Problem::committedSkeletonHistory() const
{
  std::vector<double> values(skeleton_committed_.size() * kSkeletonValues);
  if (!values.empty())
    std::memcpy(values.data(), static_cast<const void *>(skeleton_committed_.data()),
                values.size() * sizeof(double));
  return values;
}

PetscErrorCode Problem::restoreSkeletonHistory(const std::vector<double> &values)
{
  PetscFunctionBeginUser;
  PetscCheck(values.size() == skeletonHistoryValues(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "skeleton history of %zu values for %zu integration points", values.size(),
             skeleton_committed_.size());
  if (!values.empty())
    std::memcpy(static_cast<void *>(skeleton_committed_.data()), values.data(),
                values.size() * sizeof(double));
  PetscFunctionReturn(0);
}

PetscErrorCode
Problem::visitSkeletonCells(Vec local, const std::function<void(PetscInt, double, int)> &f) const
{
  PetscFunctionBeginUser;
  PetscCall(skeletonResponses(local, [&](size_t i, const physics::SkeletonResponse *r) {
    const int nq = elements_[cells_[i].element].num_quadrature;
    double eqps = 0.0;
    int state = 0;
    for (int q = 0; q < nq; ++q) {
      eqps += r[q].updated.equivalent_plastic_strain;
      state = std::max(state, (int)r[q].state);
    }
    f(cells_[i].cell, eqps / nq, state);
    return PetscErrorCode(0);
  }));
  PetscFunctionReturn(0);
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
          << (dim_ == 3 ? std::to_string(centroid[2]) : std::string())
          << "), where its diagonal is " << s0[0][0] << ", " << s0[1][1] << ", " << s0[2][2]
          << " Pa. The run would start out of equilibrium: choose -region_" << region.name
          << "_K0 between the active and passive earth pressure coefficients of its strength, "
             "or a larger cohesion (now "
          << region.k0_origin << ")";
      error = msg.str();
    }
    return PetscErrorCode(0);
  }));
  PetscCall(DMRestoreLocalVector(dm_, &zero));
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

} // namespace poroseam
