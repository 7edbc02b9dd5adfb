#include "order_coarsening.hpp"

#include "poroseam/nullspace.hpp"

#include <petscmat.h>

namespace poroseam {
namespace vertex_blocks_detail {
namespace {

/// The scatter of W at the closure vertices of this rank's non-vertex nodes, and the vectors
/// and the pattern of P, made once: the mesh and its constraints do not change.
PetscErrorCode createProlongation(const VertexBlockMap &map, Mat ext, OrderCoarsening &oc)
{
  const auto &one = map.order_one;
  const int dim = map.dim;
  MPI_Comm comm = PetscObjectComm((PetscObject)ext);
  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(ext, nullptr, &oc.residual));
  const PetscInt n = (PetscInt)one.vertex_ext.size() * dim;
  std::vector<PetscInt> rows(n);
  for (size_t j = 0; j < one.vertex_ext.size(); ++j)
    for (int c = 0; c < dim; ++c)
      rows[j * dim + c] = one.vertex_ext[j] * dim + c;
  IS from;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, rows.data(), PETSC_COPY_VALUES, &from));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, n, &oc.gathered));
  PetscCall(VecScatterCreate(oc.residual, from, oc.gathered, nullptr, &oc.gather));
  PetscCall(ISDestroy(&from));

  // Entries per row: one at a vertex node, one per free closure vertex component otherwise.
  const PetscInt first = one.coarse_start, last = one.coarse_start + one.coarse_local;
  std::vector<PetscInt> d_nnz(map.ext_local, 0), o_nnz(map.ext_local, 0);
  for (size_t k = 0; k < one.coarse_of_node.size(); ++k)
    for (int c = 0; c < dim; ++c) {
      const size_t row = k * dim + c;
      if (one.coarse_of_node[k] >= 0) {
        d_nnz[row] = 1;
        continue;
      }
      for (PetscInt j = one.node_vertex_start[k]; j < one.node_vertex_start[k + 1]; ++j) {
        const PetscInt col = one.vertex_coarse[j] * dim + c;
        ++((col >= first && col < last) ? d_nnz[row] : o_nnz[row]);
      }
    }
  PetscCall(MatCreate(comm, &oc.prolongation));
  PetscCall(MatSetSizes(oc.prolongation, map.ext_local, one.coarse_local, PETSC_DETERMINE,
                        PETSC_DETERMINE));
  PetscCall(MatSetType(oc.prolongation, MATAIJ));
  PetscCall(MatSetBlockSizes(oc.prolongation, dim, dim));
  PetscCall(MatSeqAIJSetPreallocation(oc.prolongation, 0, d_nnz.data()));
  PetscCall(MatMPIAIJSetPreallocation(oc.prolongation, 0, d_nnz.data(), 0, o_nnz.data()));
  PetscCall(MatCreateVecs(oc.prolongation, &oc.coarse_sol, nullptr));
  PetscCall(VecDuplicate(oc.coarse_sol, &oc.coarse_rhs));
  PetscFunctionReturn(0);
}

/// P's values for the current W (see order_coarsening.hpp).
PetscErrorCode fillProlongation(const VertexBlockMap &map, Vec weight, OrderCoarsening &oc)
{
  const auto &one = map.order_one;
  const int dim = map.dim;
  const PetscScalar *w = nullptr, *wv = nullptr;
  PetscBool filled;
  PetscFunctionBeginUser;
  // Unscaled, P is the plain interpolation: the same values at every set-up.
  PetscCall(MatAssembled(oc.prolongation, &filled));
  if (!weight && filled) PetscFunctionReturn(0);
  if (weight) {
    PetscCall(VecScatterBegin(oc.gather, weight, oc.gathered, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(oc.gather, weight, oc.gathered, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(weight, &w));
    PetscCall(VecGetArrayRead(oc.gathered, &wv));
  }
  for (size_t k = 0; k < one.coarse_of_node.size(); ++k)
    for (int c = 0; c < dim; ++c) {
      const PetscInt row = map.ext_start + (PetscInt)(k * dim + c);
      if (one.coarse_of_node[k] >= 0) { // a vertex: W P W_c^-1 = 1 there
        const PetscInt col = one.coarse_of_node[k] * dim + c;
        const PetscScalar one_value = 1.0;
        PetscCall(MatSetValues(oc.prolongation, 1, &row, 1, &col, &one_value, INSERT_VALUES));
        continue;
      }
      const unsigned char bit = (unsigned char)(1u << c);
      if (!(one.node_free[k] & bit)) continue; // a decoupled row: no correction
      const PetscInt begin = one.node_vertex_start[k], end = one.node_vertex_start[k + 1];
      const PetscReal mean = 1.0 / (PetscReal)(end - begin);
      for (PetscInt j = begin; j < end; ++j) {
        if (!(one.vertex_free[j] & bit)) continue; // a constrained vertex value stays put
        const PetscInt col = one.vertex_coarse[j] * dim + c;
        PetscScalar value = mean;
        if (weight) value *= w[k * dim + c] / wv[j * dim + c];
        PetscCall(MatSetValues(oc.prolongation, 1, &row, 1, &col, &value, INSERT_VALUES));
      }
    }
  if (weight) {
    PetscCall(VecRestoreArrayRead(oc.gathered, &wv));
    PetscCall(VecRestoreArrayRead(weight, &w));
  }
  PetscCall(MatAssemblyBegin(oc.prolongation, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(oc.prolongation, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/// The coarse near null space: the fine one's vectors (already scaled like the operator) at
/// the vertices, which P carries back to the fine ones where the cells are straight.
PetscErrorCode attachCoarseModes(const VertexBlockMap &map, Mat ext, OrderCoarsening &oc)
{
  const auto &one = map.order_one;
  const int dim = map.dim;
  MatNullSpace fine_space;
  PetscInt n;
  const Vec *fine_modes;
  PetscFunctionBeginUser;
  PetscCall(MatGetNearNullSpace(ext, &fine_space));
  if (!fine_space) PetscFunctionReturn(0);
  PetscCall(MatNullSpaceGetVecs(fine_space, nullptr, &n, &fine_modes));
  std::vector<Vec> modes(n);
  for (PetscInt m = 0; m < n; ++m) {
    const PetscScalar *f;
    PetscScalar *v;
    PetscCall(VecDuplicate(oc.coarse_sol, &modes[m]));
    PetscCall(VecGetArrayRead(fine_modes[m], &f));
    PetscCall(VecGetArray(modes[m], &v));
    for (size_t k = 0; k < one.coarse_of_node.size(); ++k) {
      if (one.coarse_of_node[k] < 0) continue;
      for (int c = 0; c < dim; ++c)
        v[one.coarse_of_node[k] * dim + c - one.coarse_start] = f[k * dim + c];
    }
    PetscCall(VecRestoreArray(modes[m], &v));
    PetscCall(VecRestoreArrayRead(fine_modes[m], &f));
  }
  PetscCall(orthonormalize(modes));
  MatNullSpace space;
  PetscCall(
      MatNullSpaceCreate(PetscObjectComm((PetscObject)ext), PETSC_FALSE, n, modes.data(), &space));
  PetscCall(MatSetNearNullSpace(oc.coarse, space));
  PetscCall(MatNullSpaceDestroy(&space));
  for (auto &v : modes)
    PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

/// The smoother on the order-2 operator. Chebyshev with point-block Jacobi (the dim x dim
/// node blocks; the constrained components are decoupled rows, so no block is singular), two
/// steps, on [0.1, 1.1] x the estimated largest eigenvalue: PCMG's defaults for its levels
/// with the node blocks as the point blocks.
PetscErrorCode createFineSmoother(PC pc, Mat ext, OrderCoarsening &oc)
{
  const char *prefix;
  PC jacobi;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)ext), &oc.fine));
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(KSPSetOptionsPrefix(oc.fine, prefix));
  PetscCall(KSPAppendOptionsPrefix(oc.fine, "vertex_blocks_fine_"));
  PetscCall(KSPSetType(oc.fine, KSPCHEBYSHEV));
  PetscCall(KSPGetPC(oc.fine, &jacobi));
  PetscCall(PCSetType(jacobi, PCPBJACOBI));
  PetscCall(KSPChebyshevEstEigSet(oc.fine, 0.0, 0.1, 0.0, 1.1));
  PetscCall(KSPSetTolerances(oc.fine, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2));
  PetscCall(KSPSetNormType(oc.fine, KSP_NORM_NONE));
  PetscCall(KSPSetConvergenceTest(oc.fine, KSPConvergedSkip, nullptr, nullptr));
  PetscCall(KSPSetFromOptions(oc.fine));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode setUpOrderCoarsening(PC pc, const VertexBlockMap &map, Mat ext, Vec weight,
                                    OrderCoarsening &oc)
{
  PetscFunctionBeginUser;
  if (!oc.prolongation) PetscCall(createProlongation(map, ext, oc));
  PetscCall(fillProlongation(map, weight, oc));
  if (!oc.coarse) {
    PetscCall(MatPtAP(ext, oc.prolongation, MAT_INITIAL_MATRIX, 2.0, &oc.coarse));
    PetscInt bs;
    PetscCall(MatGetBlockSize(oc.coarse, &bs));
    if (bs != map.dim) PetscCall(MatSetBlockSize(oc.coarse, map.dim));
  } else {
    PetscCall(MatPtAP(ext, oc.prolongation, MAT_REUSE_MATRIX, 2.0, &oc.coarse));
  }
  PetscCall(attachCoarseModes(map, ext, oc));
  if (!oc.fine) PetscCall(createFineSmoother(pc, ext, oc));
  PetscCall(KSPSetOperators(oc.fine, ext, ext));
  PetscFunctionReturn(0);
}

PetscErrorCode applyOrderCoarsening(const OrderCoarsening &oc, Mat ext, PC inner, Vec b, Vec x)
{
  PetscFunctionBeginUser;
  PetscCall(KSPSetInitialGuessNonzero(oc.fine, PETSC_FALSE));
  PetscCall(KSPSolve(oc.fine, b, x));
  PetscCall(MatResidual(ext, b, x, oc.residual));
  PetscCall(MatMultTranspose(oc.prolongation, oc.residual, oc.coarse_rhs));
  PetscCall(PCApply(inner, oc.coarse_rhs, oc.coarse_sol));
  PetscCall(MatMultAdd(oc.prolongation, oc.coarse_sol, x, x));
  PetscCall(KSPSetInitialGuessNonzero(oc.fine, PETSC_TRUE));
  PetscCall(KSPSolve(oc.fine, b, x));
  PetscFunctionReturn(0);
}

PetscErrorCode destroyOrderCoarsening(OrderCoarsening &oc)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&oc.prolongation));
  PetscCall(MatDestroy(&oc.coarse));
  PetscCall(KSPDestroy(&oc.fine));
  PetscCall(VecScatterDestroy(&oc.gather));
  PetscCall(VecDestroy(&oc.gathered));
  PetscCall(VecDestroy(&oc.residual));
  PetscCall(VecDestroy(&oc.coarse_rhs));
  PetscCall(VecDestroy(&oc.coarse_sol));
  PetscFunctionReturn(0);
}

} // namespace vertex_blocks_detail
} // namespace poroseam
