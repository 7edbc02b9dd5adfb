// The displacement block with whole node blocks, for algebraic multigrid. A node is a point
// that carries displacement unknowns: every vertex, and at -displacement_order 2 every edge,
// quadrilateral and hexahedron too (one node each, layout.hpp); "vertex" below means node.
//
// Dirichlet conditions are section constraints, so a constrained displacement component is not
// an unknown at all: the displacement block has 1, 2 or 3 rows per vertex and no block size.
// Smoothed-aggregation AMG then aggregates single components (x of one vertex with y of
// another), which elasticity punishes: measured on the 3D quarter caisson, GAMG on that block
// stopped at its 15-iteration cap in every solve. The preconditioner "vertex_blocks" puts the
// constrained components back as decoupled rows (value: the vertex's largest free diagonal), so
// the operator has dim x dim blocks at every vertex, attaches the rigid-body modes from the
// coordinates, and applies an inner preconditioner (GAMG by default) to that operator. The
// constrained rows are decoupled, so the inner operator restricted to the free components is
// the displacement block itself.
//
// Use: -fieldsplit_displacement_pc_type vertex_blocks
//      -fieldsplit_displacement_vertex_blocks_pc_type gamg (or hypre, ...; its options take the
//      prefix -fieldsplit_displacement_vertex_blocks_)
#pragma once

#include <petscdm.h>
#include <petscksp.h>
#include <vector>

namespace poroseam {

/// Registers the PC type "vertex_blocks" with PETSc (before the solvers read their options).
PetscErrorCode registerVertexBlocksPC();

/// Attaches to `modes` (the near null space that the displacement split hands to its matrix)
/// what vertex_blocks needs: where each free displacement component of this rank sits in the
/// whole-vertex numbering, and the coordinates. `displacement` is the displacement split's IS
/// (global indices of the full system, sorted). `outer` is the Newton solver's KSP (when it
/// scales the system, -ksp_diagonal_scale, the modes are scaled alike) and
/// `jacobian_diagonal` the diagonal of the whole Jacobian, which the caller fills at every
/// assembly (the outer KSP scales the matrix in place before the PC sees it).
/// `cell_modulus` is Young's modulus [Pa] of each cell of the DM's cell stratum (0 where a
/// cell has none, the interfaces' cohesive cells): it tells the PC which nodes belong to
/// bodies much stiffer than the rest (stiff_bodies.hpp).
PetscErrorCode attachVertexBlocks(DM dm, int dim, bool axisymmetric, IS displacement,
                                  MatNullSpace modes, KSP outer, Vec jacobian_diagonal,
                                  const std::vector<PetscReal> &cell_modulus);

} // namespace poroseam
