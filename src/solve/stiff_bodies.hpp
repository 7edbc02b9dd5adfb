// Stiff bodies in the PC vertex_blocks: the nodes of bodies much stiffer than the rest (the
// caisson's steel in the soil) solved together, exactly, after each cycle of the inner PC.
//
// Why: a thin stiff body bends. Its bending is a low-energy mode of the whole operator, but
// neither a point smoother nor the coarse spaces see it: GAMG aggregates across the skirt's
// two cells of thickness, and the order-1 level of the order coarsening locks in bending
// (order-1 hexahedra through a thin plate). The preset's outer FGMRES then spends most of its
// iterations on that one body. Measured on the 3D quarter caisson at order 2 (mesh factor 2,
// 30k unknowns, step 1, 2 ranks): 80 outer iterations per Newton iteration without, 35 with
// the steel's rows solved by LU after each cycle. (A first trial, which picked the rows by
// their diagonal, put the correction after the pre-smoothing, after the coarse correction or
// after the whole cycle: 33 each; it sits after the cycle, where it serves any inner PC.)
//
// Which nodes: those of cells whose region's Young's modulus is at least `ratio` times the
// smallest of the mesh (-<prefix>vertex_blocks_stiff_ratio; 0 turns it off). Soil layers
// differ by less, steel and soil by 1000. Default 100 at -displacement_order 2, off at
// order 1: there GAMG on the order-1 field already sees the skirt (3D caisson, 37k unknowns,
// whole run: 1249 instead of 1330 outer iterations, 58 instead of 61 Newton, but 51.6-51.9 s
// instead of 48.8-49.4 s: the LU and its solves cost more than the 6 % they save).
// The block is the extended operator restricted to those nodes (its decoupled constrained
// rows included), factorised by LU (MUMPS on more than one rank) at every set-up; its solver
// takes the prefix -<prefix>vertex_blocks_stiff_.
//
// One correction: x += A_ss^-1 (b - A x)_s on the stiff rows s, a multiplicative block
// Gauss-Seidel step after the inner PC's cycle. The residual is computed on those rows only.
#pragma once

#include "vertex_block_map.hpp"

#include <petscksp.h>

namespace poroseam {
namespace vertex_blocks_detail {

/// The ratio when -<prefix>vertex_blocks_stiff_ratio is not given, at order 2 (see above).
constexpr PetscReal kDefaultStiffRatio = 100.0;

struct StiffBodies {
  /// Stiff: E >= ratio x the smallest E of the mesh; 0: off. Unset, 100 at order 2 and off at
  /// order 1 (kDefaultStiffRatio).
  PetscReal ratio = -1.0;
  IS rows = nullptr;       ///< extended rows of the stiff nodes (null: none)
  PetscInt total_rows = 0; ///< over all ranks
  Mat block = nullptr;     ///< the extended operator on those rows
  /// Those rows of the extended operator, all columns: the residual on the stiff rows alone
  /// costs their share of a product with the whole operator, not the whole one (order 1, 37k
  /// caisson: the whole product made each outer iteration about 13 % dearer).
  Mat rows_op = nullptr;
  IS columns = nullptr;                         ///< all columns, as MatCreateSubMatrix takes them
  KSP solver = nullptr;                         ///< LU of `block`
  Vec residual = nullptr, correction = nullptr; ///< on the stiff rows
};

/// Selects the stiff nodes (first call) and hands the current operator's block to the solver.
PetscErrorCode setUpStiffBodies(PC pc, const VertexBlockMap &map, Mat ext, StiffBodies &sb);

/// x += A_ss^-1 (b - A x)_s; nothing when no node is stiff.
PetscErrorCode correctStiffBodies(const StiffBodies &sb, Vec b, Vec x);

PetscErrorCode destroyStiffBodies(StiffBodies &sb);

} // namespace vertex_blocks_detail
} // namespace poroseam
