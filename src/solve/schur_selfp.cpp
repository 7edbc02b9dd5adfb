#include "poroseam/schur_selfp.hpp"

#include <petsc/private/pcimpl.h> // a new PC type sets pc->ops (PETSc's documented way)

namespace poroseam {
namespace {

struct SchurSelfpPC {
  PC inner = nullptr;     ///< applied to selfp
  Mat scaled_B = nullptr; ///< diag(A00)^-1 A01, the product's right factor (its pattern kept)
  Mat product = nullptr;  ///< A10 diag(A00)^-1 A01 (symbolic part kept)
  Mat selfp = nullptr;    ///< A11 - product
  Vec inverse_diagonal = nullptr;
  PetscObjectState pattern_A01 = -1, pattern_A10 = -1; ///< nonzero states the product is for
};

/// The blocks of the Schur complement this PC is given as its operator.
PetscErrorCode schurBlocks(PC pc, Mat *A00, Mat *A01, Mat *A10, Mat *A11)
{
  Mat S;
  PetscBool schur;
  PetscFunctionBeginUser;
  PetscCall(PCGetOperators(pc, &S, nullptr));
  PetscCall(PetscObjectTypeCompare((PetscObject)S, MATSCHURCOMPLEMENT, &schur));
  PetscCheck(schur, PetscObjectComm((PetscObject)pc), PETSC_ERR_USER_INPUT,
             "-pc_type schur_selfp works only on the Schur complement of -pc_fieldsplit_type "
             "schur (-fieldsplit_pressures_pc_type schur_selfp)");
  PetscCall(MatSchurComplementGetSubMatrices(S, A00, nullptr, A01, A10, A11));
  PetscFunctionReturn(0);
}

PetscErrorCode setUp(PC pc)
{
  auto *sp = static_cast<SchurSelfpPC *>(pc->data);
  Mat A00, A01, A10, A11;
  PetscObjectState state01, state10;
  PetscFunctionBeginUser;
  PetscCall(schurBlocks(pc, &A00, &A01, &A10, &A11));
  PetscCall(MatGetNonzeroState(A01, &state01));
  PetscCall(MatGetNonzeroState(A10, &state10));
  const bool same_pattern = sp->product && state01 == sp->pattern_A01 && state10 == sp->pattern_A10;
  if (!sp->inverse_diagonal) PetscCall(MatCreateVecs(A00, &sp->inverse_diagonal, nullptr));
  PetscCall(MatGetDiagonal(A00, sp->inverse_diagonal));
  PetscCall(VecReciprocal(sp->inverse_diagonal));
  if (same_pattern) {
    PetscCall(MatCopy(A01, sp->scaled_B, SAME_NONZERO_PATTERN));
  } else {
    PetscCall(MatDestroy(&sp->product));
    PetscCall(MatDestroy(&sp->scaled_B));
    PetscCall(MatDuplicate(A01, MAT_COPY_VALUES, &sp->scaled_B));
    sp->pattern_A01 = state01;
    sp->pattern_A10 = state10;
  }
  PetscCall(MatDiagonalScale(sp->scaled_B, sp->inverse_diagonal, nullptr));
  PetscCall(MatMatMult(A10, sp->scaled_B, same_pattern ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX,
                       PETSC_DEFAULT, &sp->product));
  // A11 - product. The sum's pattern is the union of two patterns, and MatAYPX replaces the
  // matrix it works on, so it gets a copy of the product (whose symbolic part is what we keep).
  PetscCall(MatDestroy(&sp->selfp));
  PetscCall(MatDuplicate(sp->product, MAT_COPY_VALUES, &sp->selfp));
  PetscCall(MatAYPX(sp->selfp, -1.0, A11, DIFFERENT_NONZERO_PATTERN));
  if (!sp->inner) {
    const char *prefix;
    PetscCall(PCCreate(PetscObjectComm((PetscObject)pc), &sp->inner));
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(PCSetOptionsPrefix(sp->inner, prefix));
    PetscCall(PCAppendOptionsPrefix(sp->inner, "schur_selfp_"));
    PetscCall(PCSetType(sp->inner, PCHYPRE));
    PetscCall(PCSetFromOptions(sp->inner));
  }
  PetscCall(PCSetOperators(sp->inner, sp->selfp, sp->selfp));
  PetscCall(PCSetUp(sp->inner));
  PetscFunctionReturn(0);
}

PetscErrorCode apply(PC pc, Vec x, Vec y)
{
  auto *sp = static_cast<SchurSelfpPC *>(pc->data);
  PetscFunctionBeginUser;
  PetscCall(PCApply(sp->inner, x, y));
  PetscFunctionReturn(0);
}

PetscErrorCode reset(PC pc)
{
  auto *sp = static_cast<SchurSelfpPC *>(pc->data);
  PetscFunctionBeginUser;
  PetscCall(PCDestroy(&sp->inner));
  PetscCall(MatDestroy(&sp->scaled_B));
  PetscCall(MatDestroy(&sp->product));
  PetscCall(MatDestroy(&sp->selfp));
  PetscCall(VecDestroy(&sp->inverse_diagonal));
  sp->pattern_A01 = sp->pattern_A10 = -1;
  PetscFunctionReturn(0);
}

PetscErrorCode destroy(PC pc)
{
  PetscFunctionBeginUser;
  PetscCall(reset(pc));
  delete static_cast<SchurSelfpPC *>(pc->data);
  pc->data = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode view(PC pc, PetscViewer viewer)
{
  auto *sp = static_cast<SchurSelfpPC *>(pc->data);
  PetscBool ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii && sp->inner) {
    PetscCall(PetscViewerASCIIPrintf(
        viewer, "  on A11 - A10 diag(A00)^-1 A01 (product pattern kept); inner preconditioner:\n"));
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(PCView(sp->inner, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode create(PC pc)
{
  PetscFunctionBeginUser;
  pc->data = new SchurSelfpPC;
  pc->ops->setup = setUp;
  pc->ops->apply = apply;
  pc->ops->reset = reset;
  pc->ops->destroy = destroy;
  pc->ops->view = view;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode registerSchurSelfpPC()
{
  PetscFunctionBeginUser;
  PetscCall(PCRegister("schur_selfp", create));
  PetscFunctionReturn(0);
}

PetscErrorCode schurSelfpMatrix(PC pc, Mat *selfp)
{
  PetscBool ours;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, "schur_selfp", &ours));
  PetscCheck(ours, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG,
             "schurSelfpMatrix: the PC is not of type schur_selfp");
  *selfp = static_cast<SchurSelfpPC *>(pc->data)->selfp;
  PetscFunctionReturn(0);
}

} // namespace poroseam
