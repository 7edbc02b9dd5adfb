// Order coarsening (p-multigrid) for the PC vertex_blocks at -displacement_order 2.
//
// Why: smoothed-aggregation AMG coarsens the Q2/P2 displacement block badly. A 27-node
// hexahedron couples each node with up to 125 nodes; GAMG's squared graph then makes
// aggregates of about 40 nodes at its first level (20x fewer rows), too coarse for a
// Chebyshev-Jacobi smoother, and the 3D quarter caisson's displacement block took 224 GMRES
// iterations against 50 at order 1 (docs/performance.md). On the order-1 field of the same
// mesh GAMG does what it does at order 1. So the V-cycle gets one more, geometric, level on
// top: the order-2 operator A, smoothed on its own nodes, and the order-1 operator of the same
// mesh, P^T A P, handed to the inner PC (GAMG with the preset's options, unchanged).
//
// P interpolates an order-1 field to the order-2 nodes: identity at vertices, the mean of the
// closure's vertices at an edge, quadrilateral or hexahedron node (where the bilinear map puts
// the point's centre). Constrained components are decoupled rows of A (vertex_blocks.cpp), so
// P does not carry a value from a constrained vertex component into a free one. When the
// outer solver scales the system (-ksp_diagonal_scale, the operator is W^-1 A W^-1 with
// W = diag(A)^1/2) P is scaled too, W P W_c^-1 with W_c the vertices' W: the coarse operator
// is then the scaled order-1 operator and its near null space the scaled rigid-body modes at
// the vertices.
//
// One cycle: pre-smooth (the fine KSP from a zero guess), coarse correction, post-smooth.
// Options, with the vertex_blocks PC's prefix:
//   -<prefix>vertex_blocks_order_coarsening <bool>   (default true at order 2)
//   -<prefix>vertex_blocks_fine_ksp_type, _fine_pc_type, ... the fine smoother (chebyshev with
//    point-block Jacobi, 2 steps by default)
#pragma once

#include "vertex_block_map.hpp"

#include <petscksp.h>
#include <vector>

namespace poroseam {
namespace vertex_blocks_detail {

struct OrderCoarsening {
  Mat prolongation = nullptr;  ///< P, extended rows x coarse rows
  Mat coarse = nullptr;        ///< P^T A P, the inner PC's operator
  KSP fine = nullptr;          ///< the smoother on A
  VecScatter gather = nullptr; ///< the weights at the vertices of non-vertex nodes ...
  Vec gathered = nullptr;      ///< ... (one per entry of order_one.vertex_ext x dim)
  Vec residual = nullptr, coarse_rhs = nullptr, coarse_sol = nullptr;
};

/// Builds (first call) or refills P, the coarse operator P^T A P with its near null space
/// (the fine one's vectors at the vertices), and hands A to the fine smoother. `weight` is W
/// (see above) in the extended numbering, or null when the outer solver does not scale.
PetscErrorCode setUpOrderCoarsening(PC pc, const VertexBlockMap &map, Mat ext, Vec weight,
                                    OrderCoarsening &oc);

/// x = one two-level cycle on b, with `inner` on the coarse level.
PetscErrorCode applyOrderCoarsening(const OrderCoarsening &oc, Mat ext, PC inner, Vec b, Vec x);

PetscErrorCode destroyOrderCoarsening(OrderCoarsening &oc);

} // namespace vertex_blocks_detail
} // namespace poroseam
