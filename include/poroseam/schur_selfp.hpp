// The Schur complement's preconditioning matrix, assembled once symbolically.
//
// The fieldsplit preset preconditions the Schur complement S = A11 - A10 A00^-1 A01 of the
// pressures by algebraic multigrid on the assembled approximation
//     S_p = A11 - A10 diag(A00)^-1 A01                       (PETSc's "selfp")
// PETSc 3.18 builds S_p from scratch at every preconditioner set-up: a symbolic and a numeric
// sparse product, then a sum with a new nonzero pattern (MatCreateSchurComplementPmat, whose
// comments say the reuse is a to-do). The Jacobian's pattern never changes during a run, so the
// PC "schur_selfp" keeps the product's pattern and redoes only its numeric part: on the 3D
// caisson at 160k unknowns the symbolic products were 6.4 s of 139 s of time steps.
//
// Use (the preset does):
//   -pc_fieldsplit_schur_precondition a11   (PETSc then builds nothing; S_p is built here)
//   -fieldsplit_pressures_pc_type schur_selfp
//   -fieldsplit_pressures_schur_selfp_pc_type hypre  (the PC applied to S_p; its options take
//                                                     the prefix
//                                                     -fieldsplit_pressures_schur_selfp_)
#pragma once

#include <petscksp.h>

namespace poroseam {

/// Registers the PC type "schur_selfp" with PETSc (before the solvers read their options).
PetscErrorCode registerSchurSelfpPC();

/// The assembled A11 - A10 diag(A00)^-1 A01 of a set-up PC schur_selfp (borrowed; NULL before
/// the first set-up), for tests and inspection.
PetscErrorCode schurSelfpMatrix(PC pc, Mat *selfp);

} // namespace poroseam
