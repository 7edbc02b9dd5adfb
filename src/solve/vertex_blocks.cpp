#include "poroseam/vertex_blocks.hpp"

#include "order_coarsening.hpp"
#include "stiff_bodies.hpp"
#include "vertex_block_map.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/nullspace.hpp"

#include <algorithm>
#include <cstdio>
#include <petsc/private/pcimpl.h> // a new PC type sets pc->ops (PETSc's documented way)
#include <petscdmplex.h>
#include <petscksp.h>
#include <string>
#include <vector>

namespace poroseam {
namespace {

using namespace vertex_blocks_detail;

/// State of one vertex_blocks preconditioner.
struct VertexBlocksPC {
  const VertexBlockMap *map = nullptr;
  Mat ext = nullptr;  ///< the displacement block with whole vertex blocks
  PC inner = nullptr; ///< applied to ext
  Vec ext_rhs = nullptr, ext_sol = nullptr;
  std::vector<PetscInt> off_rows; ///< off-rank columns of the block (sorted) ...
  std::vector<PetscInt> off_ext;  ///< ... and their extended rows
  PetscInt setups = 0;            ///< set-ups so far (which one -..._dump_operator writes)
  /// -<prefix>vertex_blocks_coarse_lag N: the inner multigrid's coarse levels are rebuilt at
  /// set-ups 1, N+1, 2N+1, ...; in between only its finest level takes the new operator.
  PetscInt coarse_lag = 1;
  /// -<prefix>vertex_blocks_order_coarsening: at order 2, one geometric level from the
  /// order-2 to the order-1 field of the same mesh above the inner PC (order_coarsening.hpp).
  PetscBool order_coarsening = PETSC_TRUE;
  OrderCoarsening oc;
  /// -<prefix>vertex_blocks_stiff_ratio: the nodes of much stiffer bodies solved exactly after
  /// each cycle (stiff_bodies.hpp).
  StiffBodies stiff;
  bool coarsening() const { return map && map->quadratic() && order_coarsening; }
};

/// Off-rank columns of P and their extended rows, gathered once: the pattern of the Jacobian
/// is fixed by the DM.
PetscErrorCode mapOffRankColumns(Mat P, VertexBlocksPC &vb)
{
  PetscInt rstart, rend;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(P, &rstart, &rend));
  std::vector<PetscInt> off;
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt ncols;
    const PetscInt *cols;
    PetscCall(MatGetRow(P, r, &ncols, &cols, nullptr));
    for (PetscInt k = 0; k < ncols; ++k)
      if (cols[k] < rstart || cols[k] >= rend) off.push_back(cols[k]);
    PetscCall(MatRestoreRow(P, r, &ncols, &cols, nullptr));
  }
  std::sort(off.begin(), off.end());
  off.erase(std::unique(off.begin(), off.end()), off.end());
  IS from;
  Vec gathered;
  VecScatter scatter;
  PetscCall(
      ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)off.size(), off.data(), PETSC_USE_POINTER, &from));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)off.size(), &gathered));
  PetscCall(VecScatterCreate(vb.map->ext_of_free_global, from, gathered, nullptr, &scatter));
  PetscCall(VecScatterBegin(scatter, vb.map->ext_of_free_global, gathered, INSERT_VALUES,
                            SCATTER_FORWARD));
  PetscCall(
      VecScatterEnd(scatter, vb.map->ext_of_free_global, gathered, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *values;
  PetscCall(VecGetArrayRead(gathered, &values));
  vb.off_ext.resize(off.size());
  for (size_t k = 0; k < off.size(); ++k)
    vb.off_ext[k] = (PetscInt)PetscRealPart(values[k]);
  PetscCall(VecRestoreArrayRead(gathered, &values));
  PetscCall(VecScatterDestroy(&scatter));
  PetscCall(VecDestroy(&gathered));
  PetscCall(ISDestroy(&from));
  vb.off_rows = std::move(off);
  PetscFunctionReturn(0);
}

/// Copies P into the extended matrix (creating and preallocating it the first time) and puts
/// the vertex's largest free diagonal on each constrained component's row.
PetscErrorCode fillExtended(Mat P, VertexBlocksPC &vb)
{
  const VertexBlockMap &map = *vb.map;
  MPI_Comm comm = PetscObjectComm((PetscObject)P);
  PetscInt rstart, rend;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(P, &rstart, &rend));
  const PetscInt ext_start = map.ext_start;
  const PetscInt ext_end = ext_start + map.ext_local;
  auto extColumn = [&](PetscInt c, PetscInt *e) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (c >= rstart && c < rend) {
      *e = map.ext_of_free[c - rstart];
    } else {
      auto it = std::lower_bound(vb.off_rows.begin(), vb.off_rows.end(), c);
      PetscCheck(it != vb.off_rows.end() && *it == c, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "vertex_blocks: column %" PetscInt_FMT " outside the Jacobian's pattern", c);
      *e = vb.off_ext[it - vb.off_rows.begin()];
    }
    PetscFunctionReturn(0);
  };
  if (!vb.ext) {
    PetscCall(mapOffRankColumns(P, vb));
    std::vector<PetscInt> d_nnz(map.ext_local, 1), o_nnz(map.ext_local, 0);
    for (PetscInt r = rstart; r < rend; ++r) {
      PetscInt ncols;
      const PetscInt *cols;
      PetscCall(MatGetRow(P, r, &ncols, &cols, nullptr));
      const PetscInt row = map.ext_of_free[r - rstart] - ext_start;
      d_nnz[row] = o_nnz[row] = 0;
      for (PetscInt k = 0; k < ncols; ++k) {
        PetscInt e = -1;
        PetscCall(extColumn(cols[k], &e));
        ++((e >= ext_start && e < ext_end) ? d_nnz[row] : o_nnz[row]);
      }
      PetscCall(MatRestoreRow(P, r, &ncols, &cols, nullptr));
    }
    PetscCall(MatCreate(comm, &vb.ext));
    PetscCall(MatSetSizes(vb.ext, map.ext_local, map.ext_local, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetType(vb.ext, MATAIJ));
    PetscCall(MatSetBlockSize(vb.ext, map.dim));
    PetscCall(MatSeqAIJSetPreallocation(vb.ext, 0, d_nnz.data()));
    PetscCall(MatMPIAIJSetPreallocation(vb.ext, 0, d_nnz.data(), 0, o_nnz.data()));
    PetscCall(MatSetOption(vb.ext, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
    PetscCall(MatCreateVecs(vb.ext, &vb.ext_sol, &vb.ext_rhs));
  } else {
    PetscCall(MatZeroEntries(vb.ext));
  }
  // Diagonal per extended row; constrained rows keep 0 until filled below.
  std::vector<PetscScalar> diag(map.ext_local, 0.0);
  std::vector<PetscInt> ext_cols;
  for (PetscInt r = rstart; r < rend; ++r) {
    PetscInt ncols;
    const PetscInt *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(P, r, &ncols, &cols, &vals));
    const PetscInt row = map.ext_of_free[r - rstart];
    ext_cols.resize(ncols);
    for (PetscInt k = 0; k < ncols; ++k) {
      PetscCall(extColumn(cols[k], &ext_cols[k]));
      if (cols[k] == r) diag[row - ext_start] = vals[k];
    }
    PetscCall(MatSetValues(vb.ext, 1, &row, ncols, ext_cols.data(), vals, INSERT_VALUES));
    PetscCall(MatRestoreRow(P, r, &ncols, &cols, &vals));
  }
  const int dim = map.dim;
  for (PetscInt v = 0; v < map.ext_local / dim; ++v) {
    PetscReal largest = 0.0;
    for (int c = 0; c < dim; ++c)
      largest = std::max(largest, PetscAbsScalar(diag[v * dim + c]));
    if (largest == 0.0) largest = 1.0; // a fully constrained vertex: decoupled identity
    for (int c = 0; c < dim; ++c) {
      if (diag[v * dim + c] != 0.0) continue;
      const PetscInt row = ext_start + v * dim + c;
      const PetscScalar value = largest;
      PetscCall(MatSetValues(vb.ext, 1, &row, 1, &row, &value, INSERT_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(vb.ext, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(vb.ext, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/// The Jacobian's diagonal of the displacement block in the extended numbering (created like
/// vb.ext_rhs): the free components' entries, 0 on constrained ones.
PetscErrorCode extendedJacobianDiagonal(const VertexBlocksPC &vb, Vec *out)
{
  const VertexBlockMap &map = *vb.map;
  Vec diag;
  const PetscScalar *d;
  PetscScalar *e;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(vb.ext_rhs, out));
  PetscCall(VecSet(*out, 0.0));
  PetscCall(VecGetSubVector(map.jacobian_diagonal, map.displacement, &diag));
  PetscCall(VecGetArrayRead(diag, &d));
  PetscCall(VecGetArray(*out, &e));
  for (size_t i = 0; i < map.ext_of_free.size(); ++i)
    e[map.ext_of_free[i] - map.ext_start] = d[i];
  PetscCall(VecRestoreArray(*out, &e));
  PetscCall(VecRestoreArrayRead(diag, &d));
  PetscCall(VecRestoreSubVector(map.jacobian_diagonal, map.displacement, &diag));
  PetscFunctionReturn(0);
}

/// W = |diag|^1/2 of the operator the PC is given when the outer solver scales the system by
/// D^-1/2 (constrained rows: the vertex's largest), else null: the near null space is W times
/// the rigid-body modes, and the order coarsening scales its interpolation by it.
PetscErrorCode extendedWeight(const VertexBlocksPC &vb, Vec *weight)
{
  const VertexBlockMap &map = *vb.map;
  PetscBool scaled = PETSC_FALSE;
  PetscFunctionBeginUser;
  *weight = nullptr;
  if (map.outer) PetscCall(KSPGetDiagonalScale(map.outer, &scaled));
  if (!scaled) PetscFunctionReturn(0);
  PetscScalar *w;
  PetscCall(extendedJacobianDiagonal(vb, weight));
  PetscCall(VecSqrtAbs(*weight));
  PetscCall(VecGetArray(*weight, &w));
  for (PetscInt v = 0; v < map.ext_local / map.dim; ++v) {
    PetscReal largest = 0.0;
    for (int c = 0; c < map.dim; ++c)
      largest = std::max(largest, PetscRealPart(w[v * map.dim + c]));
    for (int c = 0; c < map.dim; ++c)
      if (w[v * map.dim + c] == 0.0) w[v * map.dim + c] = largest > 0.0 ? largest : 1.0;
  }
  PetscCall(VecRestoreArray(*weight, &w));
  PetscFunctionReturn(0);
}

/// The near null space of the operator the PC is given: the rigid-body modes, times W
/// (extendedWeight) when the outer solver scales the system.
PetscErrorCode attachModes(VertexBlocksPC &vb, Vec weight)
{
  const VertexBlockMap &map = *vb.map;
  PetscFunctionBeginUser;
  std::vector<Vec> modes(map.ext_modes.size());
  for (size_t m = 0; m < modes.size(); ++m) {
    PetscCall(VecDuplicate(map.ext_modes[m], &modes[m]));
    PetscCall(VecCopy(map.ext_modes[m], modes[m]));
    if (weight) PetscCall(VecPointwiseMult(modes[m], modes[m], weight));
  }
  PetscCall(orthonormalize(modes)); // as MatNullSpaceCreate expects
  MatNullSpace space;
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)vb.ext), PETSC_FALSE,
                               (PetscInt)modes.size(), modes.data(), &space));
  PetscCall(MatSetNearNullSpace(vb.ext, space));
  PetscCall(MatNullSpaceDestroy(&space));
  for (auto &v : modes)
    PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

/// -<prefix>vertex_blocks_dump_operator FILE (and _dump_operator_setup N, default 1): writes
/// the N-th set-up's operator to FILE in PETSc's binary format, for studying the displacement
/// block alone (bench/displacement_block.c): the extended matrix, its near-null-space vectors,
/// the unscaled Jacobian diagonal of each row (0 on constrained components) and the vertex
/// coordinates (dim per vertex), in that order.
PetscErrorCode dumpOperator(PC pc, const VertexBlocksPC &vb)
{
  const VertexBlockMap &map = *vb.map;
  char file[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  PetscInt which = 1;
  const char *prefix;
  PetscFunctionBeginUser;
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscOptionsGetString(nullptr, prefix, "-vertex_blocks_dump_operator", file,
                                  sizeof file, &set));
  PetscCall(
      PetscOptionsGetInt(nullptr, prefix, "-vertex_blocks_dump_operator_setup", &which, nullptr));
  MPI_Comm comm = PetscObjectComm((PetscObject)pc);
  if (set && vb.setups == 1) {
    // Checked on every rank together at the first set-up: a file only rank 0 cannot open
    // would fail there alone and leave the other ranks waiting.
    std::string error;
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (which < 1)
      error = "option -" + std::string(prefix ? prefix : "") +
              "vertex_blocks_dump_operator_setup " + std::to_string(which) +
              ": expected a set-up number >= 1";
    else if (rank == 0) {
      if (std::FILE *f = std::fopen(file, "wb"))
        std::fclose(f);
      else
        error = "option -" + std::string(prefix ? prefix : "") + "vertex_blocks_dump_operator " +
                file + ": cannot write that file";
    }
    PetscCall(checkOnAllRanks(comm, error));
  }
  if (!set || vb.setups != which) PetscFunctionReturn(0);
  PetscViewer viewer;
  MatNullSpace space;
  PetscInt n;
  const Vec *modes;
  Vec diagonal;
  PetscCall(PetscViewerBinaryOpen(comm, file, FILE_MODE_WRITE, &viewer));
  PetscCall(MatView(vb.ext, viewer));
  PetscCall(MatGetNearNullSpace(vb.ext, &space));
  PetscCall(MatNullSpaceGetVecs(space, nullptr, &n, &modes));
  for (PetscInt m = 0; m < n; ++m)
    PetscCall(VecView(modes[m], viewer));
  PetscCall(extendedJacobianDiagonal(vb, &diagonal));
  PetscCall(VecView(diagonal, viewer));
  PetscCall(VecDestroy(&diagonal));
  PetscCall(VecView(map.coordinates, viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)pc),
                        "poroseam: displacement block of set-up %" PetscInt_FMT " (%" PetscInt_FMT
                        " near-null vectors) written to %s\n",
                        which, n, file));
  PetscFunctionReturn(0);
}

PetscErrorCode setUp(PC pc)
{
  auto *vb = static_cast<VertexBlocksPC *>(pc->data);
  Mat P;
  PetscFunctionBeginUser;
  PetscCall(PCGetOperators(pc, nullptr, &P));
  if (!vb->map) PetscCall(findMap(P, &vb->map));
  PetscCall(fillExtended(P, *vb));
  Vec weight;
  PetscCall(extendedWeight(*vb, &weight));
  PetscCall(attachModes(*vb, weight));
  // At order 2 the inner PC works on the order-1 operator of the same mesh.
  Mat inner_operator = vb->ext;
  if (vb->coarsening()) {
    PetscCall(setUpOrderCoarsening(pc, *vb->map, vb->ext, weight, vb->oc));
    inner_operator = vb->oc.coarse;
  }
  PetscCall(VecDestroy(&weight));
  PetscCall(setUpStiffBodies(pc, *vb->map, vb->ext, vb->stiff));
  if (!vb->inner) {
    const char *prefix;
    PetscCall(PCCreate(PetscObjectComm((PetscObject)pc), &vb->inner));
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(PCSetOptionsPrefix(vb->inner, prefix));
    PetscCall(PCAppendOptionsPrefix(vb->inner, "vertex_blocks_"));
    PetscCall(PCSetType(vb->inner, PCGAMG));
    PetscCall(PCSetFromOptions(vb->inner));
  }
  PetscCall(PCSetOperators(vb->inner, inner_operator, inner_operator));
  // The lag applies to multigrid (GAMG, ML, PCMG); any other inner PC is rebuilt each time.
  PetscErrorCode (*mg_levels)(PC, PetscInt *) = nullptr;
  PetscCall(PetscObjectQueryFunction((PetscObject)vb->inner, "PCMGGetLevels_C", &mg_levels));
  const bool rebuild = !mg_levels || vb->setups % vb->coarse_lag == 0;
  ++vb->setups;
  PetscCall(dumpOperator(pc, *vb));
  // Coarse lag. A Newton iteration changes the Jacobian where interfaces stick, slip, open or
  // close and where the soil yields: local changes, which the finest level's smoother sees at
  // once. The coarse levels only have to represent the smooth, global error, and the last
  // ones still do: 3D caisson at 160k unknowns, first three steps, 2 ranks: 403 outer
  // iterations with coarse levels rebuilt at every Newton iteration, 406 with the first
  // set-up's kept for all 18, and set-up 25 s instead of 56 s (GAMG's Galerkin products
  // PtAP of every level, 1.8 s a set-up, skipped). PCGAMG has no option for this
  // (-pc_gamg_reuse_interpolation keeps the prolongators but redoes the products), so the
  // inner PC is told to reuse itself and the finest smoother is handed the new operator (the
  // same matrix object, refilled above: Jacobi and the Chebyshev estimate are redone; the
  // finest level's residual uses this matrix too).
  PetscCall(PCSetReusePreconditioner(vb->inner, rebuild ? PETSC_FALSE : PETSC_TRUE));
  if (!rebuild) {
    PetscInt levels;
    KSP finest;
    PetscCall(PCMGGetLevels(vb->inner, &levels));
    PetscCall(PCMGGetSmoother(vb->inner, levels - 1, &finest));
    PetscCall(KSPSetOperators(finest, inner_operator, inner_operator));
  }
  PetscCall(PCSetUp(vb->inner));
  PetscFunctionReturn(0);
}

/// y = R M^-1 R^T x: the free components into the extended vector (zero on constrained
/// components), the inner preconditioner, and back.
PetscErrorCode apply(PC pc, Vec x, Vec y)
{
  auto *vb = static_cast<VertexBlocksPC *>(pc->data);
  const VertexBlockMap &map = *vb->map;
  PetscFunctionBeginUser;
  const PetscInt ext_start = map.ext_start;
  const PetscScalar *in;
  PetscScalar *ext;
  PetscCall(VecSet(vb->ext_rhs, 0.0));
  PetscCall(VecGetArrayRead(x, &in));
  PetscCall(VecGetArray(vb->ext_rhs, &ext));
  for (size_t i = 0; i < map.ext_of_free.size(); ++i)
    ext[map.ext_of_free[i] - ext_start] = in[i];
  PetscCall(VecRestoreArray(vb->ext_rhs, &ext));
  PetscCall(VecRestoreArrayRead(x, &in));
  if (vb->coarsening())
    PetscCall(applyOrderCoarsening(vb->oc, vb->ext, vb->inner, vb->ext_rhs, vb->ext_sol));
  else
    PetscCall(PCApply(vb->inner, vb->ext_rhs, vb->ext_sol));
  PetscCall(correctStiffBodies(vb->stiff, vb->ext_rhs, vb->ext_sol));
  const PetscScalar *sol;
  PetscScalar *out;
  PetscCall(VecGetArrayRead(vb->ext_sol, &sol));
  PetscCall(VecGetArray(y, &out));
  for (size_t i = 0; i < map.ext_of_free.size(); ++i)
    out[i] = sol[map.ext_of_free[i] - ext_start];
  PetscCall(VecRestoreArray(y, &out));
  PetscCall(VecRestoreArrayRead(vb->ext_sol, &sol));
  PetscFunctionReturn(0);
}

PetscErrorCode reset(PC pc)
{
  auto *vb = static_cast<VertexBlocksPC *>(pc->data);
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&vb->ext));
  PetscCall(VecDestroy(&vb->ext_rhs));
  PetscCall(VecDestroy(&vb->ext_sol));
  PetscCall(PCDestroy(&vb->inner));
  PetscCall(destroyOrderCoarsening(vb->oc));
  PetscCall(destroyStiffBodies(vb->stiff));
  vb->map = nullptr;
  vb->off_rows.clear();
  vb->off_ext.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode destroy(PC pc)
{
  PetscFunctionBeginUser;
  PetscCall(reset(pc));
  delete static_cast<VertexBlocksPC *>(pc->data);
  pc->data = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode view(PC pc, PetscViewer viewer)
{
  auto *vb = static_cast<VertexBlocksPC *>(pc->data);
  PetscBool ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii && vb->inner) {
    PetscCall(PetscViewerASCIIPrintf(
        viewer, "  constrained components restored as decoupled rows; inner preconditioner:\n"));
    if (vb->coarse_lag > 1)
      PetscCall(PetscViewerASCIIPrintf(viewer,
                                       "  its coarse levels rebuilt every %" PetscInt_FMT
                                       " set-ups, the finest level at each\n",
                                       vb->coarse_lag));
    PetscCall(PetscViewerASCIIPushTab(viewer));
    if (vb->coarsening()) {
      PetscInt rows;
      PetscCall(MatGetSize(vb->oc.coarse, &rows, nullptr));
      PetscCall(PetscViewerASCIIPrintf(
          viewer,
          "order coarsening: smoother on the order-2 field, then the order-1 field (%" PetscInt_FMT
          " rows) with the inner preconditioner; smoother:\n",
          rows));
      PetscCall(KSPView(vb->oc.fine, viewer));
    }
    if (vb->stiff.block) {
      PetscCall(PetscViewerASCIIPrintf(viewer,
                                       "stiff bodies (E >= %g x the smallest): %" PetscInt_FMT
                                       " rows solved after each cycle by:\n",
                                       (double)vb->stiff.ratio, vb->stiff.total_rows));
      PetscCall(KSPView(vb->stiff.solver, viewer));
    }
    PetscCall(PCView(vb->inner, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode setFromOptions(PC pc, PetscOptionItems *PetscOptionsObject)
{
  auto *vb = static_cast<VertexBlocksPC *>(pc->data);
  PetscInt lag = vb->coarse_lag;
  PetscBool coarsen = vb->order_coarsening;
  PetscReal ratio = vb->stiff.ratio < 0.0 ? kDefaultStiffRatio : vb->stiff.ratio;
  const char *prefix;
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "vertex_blocks: the displacement block by vertices");
  PetscCall(PetscOptionsInt("-vertex_blocks_coarse_lag",
                            "rebuild the inner multigrid's coarse levels every N set-ups (1: at "
                            "each); the finest level takes every new operator",
                            "docs/scenes.md", lag, &lag, nullptr));
  PetscCall(PetscOptionsBool("-vertex_blocks_order_coarsening",
                             "at -displacement_order 2: smooth the order-2 field, and hand the "
                             "order-1 field of the same mesh to the inner PC",
                             "docs/scenes.md", coarsen, &coarsen, nullptr));
  PetscBool stiff_given = PETSC_FALSE;
  PetscCall(PetscOptionsReal("-vertex_blocks_stiff_ratio",
                             "solve the nodes of cells with E >= this x the smallest E exactly "
                             "after each cycle (0: off; default 100 at -displacement_order 2, "
                             "off at order 1)",
                             "docs/scenes.md", ratio, &ratio, &stiff_given));
  PetscOptionsHeadEnd();
  vb->order_coarsening = coarsen;
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCheck(!stiff_given || ratio == 0.0 || ratio >= 1.0, PetscObjectComm((PetscObject)pc),
             PETSC_ERR_USER_INPUT,
             "option -%svertex_blocks_stiff_ratio %g: expected 0 (off) or a ratio of Young's "
             "moduli >= 1",
             prefix ? prefix : "", (double)ratio);
  if (stiff_given) vb->stiff.ratio = ratio;
  PetscCheck(lag >= 1, PetscObjectComm((PetscObject)pc), PETSC_ERR_USER_INPUT,
             "option -%svertex_blocks_coarse_lag %" PetscInt_FMT
             ": expected a number of set-ups >= 1",
             prefix ? prefix : "", lag);
  vb->coarse_lag = lag;
  PetscFunctionReturn(0);
}

PetscErrorCode create(PC pc)
{
  PetscFunctionBeginUser;
  pc->data = new VertexBlocksPC;
  pc->ops->setup = setUp;
  pc->ops->apply = apply;
  pc->ops->reset = reset;
  pc->ops->destroy = destroy;
  pc->ops->view = view;
  pc->ops->setfromoptions = setFromOptions;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode registerVertexBlocksPC()
{
  PetscFunctionBeginUser;
  PetscCall(PCRegister("vertex_blocks", create));
  PetscFunctionReturn(0);
}

} // namespace poroseam
