#include "stiff_bodies.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace poroseam {
namespace vertex_blocks_detail {
namespace {

/// The extended rows of the nodes whose modulus reaches ratio x the smallest of the mesh.
PetscErrorCode selectStiffRows(const VertexBlockMap &map, MPI_Comm comm, PetscReal ratio,
                               std::vector<PetscInt> &rows)
{
  PetscFunctionBeginUser;
  PetscReal softest = std::numeric_limits<PetscReal>::max();
  for (PetscReal e : map.node_modulus)
    if (e > 0.0) softest = std::min(softest, e);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &softest, 1, MPIU_REAL, MPI_MIN, comm));
  for (size_t k = 0; k < map.node_modulus.size(); ++k)
    if (map.node_modulus[k] >= ratio * softest)
      for (int c = 0; c < map.dim; ++c)
        rows.push_back(map.ext_start + (PetscInt)k * map.dim + c);
  PetscFunctionReturn(0);
}

PetscErrorCode createSolver(PC pc, MPI_Comm comm, StiffBodies &sb)
{
  const char *prefix;
  PC lu;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(comm, &sb.solver));
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(KSPSetOptionsPrefix(sb.solver, prefix));
  PetscCall(KSPAppendOptionsPrefix(sb.solver, "vertex_blocks_stiff_"));
  PetscCall(KSPSetType(sb.solver, KSPPREONLY));
  PetscCall(KSPGetPC(sb.solver, &lu));
  PetscCall(PCSetType(lu, PCLU));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size > 1) PetscCall(PCFactorSetMatSolverType(lu, MATSOLVERMUMPS));
  PetscCall(KSPSetFromOptions(sb.solver));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode setUpStiffBodies(PC pc, const VertexBlockMap &map, Mat ext, StiffBodies &sb)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)ext);
  PetscFunctionBeginUser;
  if (sb.ratio < 0.0) sb.ratio = map.quadratic() ? kDefaultStiffRatio : 0.0; // not given
  if (sb.ratio == 0.0) PetscFunctionReturn(0);
  if (!sb.block) {
    if (sb.rows) PetscFunctionReturn(0); // selected before: none is stiff
    std::vector<PetscInt> rows;
    PetscCall(selectStiffRows(map, comm, sb.ratio, rows));
    PetscCall(
        ISCreateGeneral(comm, (PetscInt)rows.size(), rows.data(), PETSC_COPY_VALUES, &sb.rows));
    PetscCall(ISGetSize(sb.rows, &sb.total_rows));
    if (sb.total_rows == 0) PetscFunctionReturn(0);
    PetscCall(MatCreateSubMatrix(ext, sb.rows, sb.rows, MAT_INITIAL_MATRIX, &sb.block));
    PetscInt first, end; // all columns: each rank its own range, as MatCreateSubMatrix takes it
    PetscCall(MatGetOwnershipRangeColumn(ext, &first, &end));
    PetscCall(ISCreateStride(comm, end - first, first, 1, &sb.columns));
    PetscCall(MatCreateSubMatrix(ext, sb.rows, sb.columns, MAT_INITIAL_MATRIX, &sb.rows_op));
    PetscCall(MatCreateVecs(sb.block, &sb.correction, &sb.residual));
    PetscCall(createSolver(pc, comm, sb));
  } else {
    PetscCall(MatCreateSubMatrix(ext, sb.rows, sb.rows, MAT_REUSE_MATRIX, &sb.block));
    PetscCall(MatCreateSubMatrix(ext, sb.rows, sb.columns, MAT_REUSE_MATRIX, &sb.rows_op));
  }
  PetscCall(KSPSetOperators(sb.solver, sb.block, sb.block));
  PetscFunctionReturn(0);
}

PetscErrorCode correctStiffBodies(const StiffBodies &sb, Vec b, Vec x)
{
  Vec bs, xs;
  PetscFunctionBeginUser;
  if (!sb.block) PetscFunctionReturn(0);
  PetscCall(MatMult(sb.rows_op, x, sb.residual)); // (A x)_s
  PetscCall(VecGetSubVector(b, sb.rows, &bs));
  PetscCall(VecAYPX(sb.residual, -1.0, bs)); // (b - A x)_s
  PetscCall(VecRestoreSubVector(b, sb.rows, &bs));
  PetscCall(KSPSolve(sb.solver, sb.residual, sb.correction));
  PetscCall(VecGetSubVector(x, sb.rows, &xs));
  PetscCall(VecAXPY(xs, 1.0, sb.correction));
  PetscCall(VecRestoreSubVector(x, sb.rows, &xs));
  PetscFunctionReturn(0);
}

PetscErrorCode destroyStiffBodies(StiffBodies &sb)
{
  PetscFunctionBeginUser;
  PetscCall(ISDestroy(&sb.rows));
  PetscCall(MatDestroy(&sb.block));
  PetscCall(MatDestroy(&sb.rows_op));
  PetscCall(ISDestroy(&sb.columns));
  PetscCall(KSPDestroy(&sb.solver));
  PetscCall(VecDestroy(&sb.residual));
  PetscCall(VecDestroy(&sb.correction));
  sb.total_rows = 0;
  PetscFunctionReturn(0);
}

} // namespace vertex_blocks_detail
} // namespace poroseam
