// PC schur_selfp (src/solve/schur_selfp.cpp) against PETSc's own selfp: on a small
// displacement-pressure system, the matrix A11 - A10 diag(A00)^-1 A01 it assembles must equal
// the one PETSc's -pc_fieldsplit_schur_precondition selfp builds, at the first set-up and at a
// second one with new values in the same pattern (where only the numeric product is redone).
#include "poroseam/schur_selfp.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace {

constexpr PetscInt kNodes = 40; // each node: two "displacement" rows, one "pressure" row

/// A nonsymmetric block system [A B^T'; B -C] on a chain of nodes; `shift` changes the values,
/// not the pattern.
PetscErrorCode assemble(Mat J, PetscReal shift)
{
  PetscFunctionBeginUser;
  PetscCall(MatZeroEntries(J));
  for (PetscInt i = 0; i < kNodes; ++i) {
    const PetscInt u0 = 3 * i, u1 = 3 * i + 1, p = 3 * i + 2;
    const PetscReal w = 1.0 + 0.1 * i + shift * (i % 3);
    PetscCall(MatSetValue(J, u0, u0, 4.0 * w, ADD_VALUES));
    PetscCall(MatSetValue(J, u1, u1, 3.0 + w, ADD_VALUES));
    PetscCall(MatSetValue(J, u0, u1, 0.5, ADD_VALUES));
    PetscCall(MatSetValue(J, u1, u0, 0.25 * w, ADD_VALUES));
    PetscCall(MatSetValue(J, p, p, -0.01 * w, ADD_VALUES));
    PetscCall(MatSetValue(J, u0, p, 1.0, ADD_VALUES)); // B^T-like, not B^T
    PetscCall(MatSetValue(J, p, u1, 0.7 * w, ADD_VALUES));
    if (i + 1 < kNodes) {
      const PetscInt v0 = u0 + 3, v1 = u1 + 3, q = p + 3;
      PetscCall(MatSetValue(J, u0, v0, -1.0, ADD_VALUES));
      PetscCall(MatSetValue(J, v0, u0, -1.0 - shift, ADD_VALUES));
      PetscCall(MatSetValue(J, u1, v1, -0.8, ADD_VALUES));
      PetscCall(MatSetValue(J, v1, u1, -0.8, ADD_VALUES));
      PetscCall(MatSetValue(J, p, q, 0.002, ADD_VALUES));
      PetscCall(MatSetValue(J, v1, p, -0.3, ADD_VALUES));
      PetscCall(MatSetValue(J, q, u0, 0.4 + shift, ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/// A Schur fieldsplit of J with splits u, p under `prefix`; the preconditioning matrix of its
/// Schur complement after set-up (PETSc's selfp, or the one PC schur_selfp assembled).
PetscErrorCode schurPmat(KSP ksp, bool ours, Mat *Sp)
{
  PC pc, schur_pc;
  KSP *sub;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(KSPSetUp(ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCFieldSplitGetSubKSP(pc, &n, &sub));
  PetscCall(KSPSetUp(sub[1]));
  PetscCall(KSPGetPC(sub[1], &schur_pc));
  PetscCall(PCSetUp(schur_pc));
  if (ours)
    PetscCall(poroseam::schurSelfpMatrix(schur_pc, Sp));
  else
    PetscCall(KSPGetOperators(sub[1], nullptr, Sp));
  PetscCall(PetscFree(sub));
  PetscFunctionReturn(0);
}

PetscErrorCode makeSolver(Mat J, const char *prefix, KSP *ksp)
{
  std::vector<PetscInt> u, p;
  for (PetscInt i = 0; i < kNodes; ++i) {
    u.push_back(3 * i);
    u.push_back(3 * i + 1);
    p.push_back(3 * i + 2);
  }
  IS isu, isp;
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PETSC_COMM_SELF, ksp));
  PetscCall(KSPSetOptionsPrefix(*ksp, prefix));
  PetscCall(KSPSetOperators(*ksp, J, J));
  PetscCall(KSPGetPC(*ksp, &pc));
  PetscCall(PCSetType(pc, PCFIELDSPLIT));
  PetscCall(
      ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)u.size(), u.data(), PETSC_COPY_VALUES, &isu));
  PetscCall(
      ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)p.size(), p.data(), PETSC_COPY_VALUES, &isp));
  PetscCall(PCFieldSplitSetIS(pc, "u", isu));
  PetscCall(PCFieldSplitSetIS(pc, "p", isp));
  PetscCall(ISDestroy(&isu));
  PetscCall(ISDestroy(&isp));
  PetscCall(KSPSetFromOptions(*ksp));
  PetscFunctionReturn(0);
}

/// ||X - Y||_F / ||Y||_F
PetscReal relativeDifference(Mat X, Mat Y)
{
  Mat D;
  PetscReal d, y;
  PetscCallAbort(PETSC_COMM_SELF, MatDuplicate(X, MAT_COPY_VALUES, &D));
  PetscCallAbort(PETSC_COMM_SELF, MatAXPY(D, -1.0, Y, DIFFERENT_NONZERO_PATTERN));
  PetscCallAbort(PETSC_COMM_SELF, MatNorm(D, NORM_FROBENIUS, &d));
  PetscCallAbort(PETSC_COMM_SELF, MatNorm(Y, NORM_FROBENIUS, &y));
  PetscCallAbort(PETSC_COMM_SELF, MatDestroy(&D));
  return d / y;
}

TEST(SchurSelfp, EqualsPetscSelfpAtEachSetUp)
{
  ASSERT_EQ(poroseam::registerSchurSelfpPC(), 0);
  const char *options =
      "-petsc_pc_fieldsplit_type schur -petsc_pc_fieldsplit_schur_precondition selfp "
      "-ours_pc_fieldsplit_type schur -ours_pc_fieldsplit_schur_precondition a11 "
      "-ours_fieldsplit_p_pc_type schur_selfp "
      "-ours_fieldsplit_p_schur_selfp_pc_type jacobi";
  ASSERT_EQ(PetscOptionsInsertString(nullptr, options), 0);
  Mat J;
  ASSERT_EQ(MatCreateSeqAIJ(PETSC_COMM_SELF, 3 * kNodes, 3 * kNodes, 9, nullptr, &J), 0);
  ASSERT_EQ(assemble(J, 0.0), 0);
  KSP petsc, ours;
  ASSERT_EQ(makeSolver(J, "petsc_", &petsc), 0);
  ASSERT_EQ(makeSolver(J, "ours_", &ours), 0);
  for (PetscReal shift : {0.0, 0.37}) {
    if (shift != 0.0) { // new values, same pattern: both solvers set up again
      ASSERT_EQ(assemble(J, shift), 0);
      ASSERT_EQ(KSPSetOperators(petsc, J, J), 0);
      ASSERT_EQ(KSPSetOperators(ours, J, J), 0);
    }
    Mat expected, assembled;
    ASSERT_EQ(schurPmat(petsc, false, &expected), 0);
    ASSERT_EQ(schurPmat(ours, true, &assembled), 0);
    ASSERT_NE(assembled, nullptr);
    EXPECT_LT(relativeDifference(assembled, expected), 1e-14) << "shift " << shift;
  }
  ASSERT_EQ(KSPDestroy(&petsc), 0);
  ASSERT_EQ(KSPDestroy(&ours), 0);
  ASSERT_EQ(MatDestroy(&J), 0);
}

} // namespace
