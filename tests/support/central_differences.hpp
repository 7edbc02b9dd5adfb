// Central finite differences of an assembled residual, column by column, for the Jacobian
// tests: the one loop they share. Serial (each rank perturbs its own entries only).
#pragma once

#include <petscvec.h>

namespace poroseam::test_support {

/// For every local entry j of X: F(X +- h_j e_j) by `residual(X, F)`, then
/// visit(i, j, (F+_i - F-_i) / (2 h_j)) for every local row i. X is restored afterwards.
/// Fp and Fm are work vectors like X; step(j) gives h_j.
template <class Residual, class Step, class Visit>
PetscErrorCode centralDifferences(Vec X, Vec Fp, Vec Fm, Residual &&residual, Step &&step,
                                  Visit &&visit)
{
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(X, &n));
  auto shift = [&](PetscInt j, double by) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(VecSetValue(X, j, by, ADD_VALUES));
    PetscCall(VecAssemblyBegin(X));
    PetscCall(VecAssemblyEnd(X));
    PetscFunctionReturn(0);
  };
  for (PetscInt j = 0; j < n; ++j) {
    const double h = step(j);
    PetscCall(shift(j, h));
    PetscCall(residual(X, Fp));
    PetscCall(shift(j, -2.0 * h));
    PetscCall(residual(X, Fm));
    PetscCall(shift(j, h));
    const PetscScalar *fp, *fm;
    PetscCall(VecGetArrayRead(Fp, &fp));
    PetscCall(VecGetArrayRead(Fm, &fm));
    for (PetscInt i = 0; i < n; ++i)
      visit(i, j, (fp[i] - fm[i]) / (2.0 * h));
    PetscCall(VecRestoreArrayRead(Fp, &fp));
    PetscCall(VecRestoreArrayRead(Fm, &fm));
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam::test_support
