// The node map of the PC vertex_blocks (internal to src/solve): where each free displacement
// component of this rank sits in the whole-node ("extended") numbering, the rigid-body modes
// and coordinates in that numbering, built by attachVertexBlocks (vertex_blocks.hpp) and found
// by the PC through the near null space of its matrix. Split from vertex_blocks.cpp.
#pragma once

#include <petscksp.h>
#include <vector>

namespace poroseam {
namespace vertex_blocks_detail {

/// Where the free displacement components of this rank go in the whole-node numbering
/// ("extended": dim rows per owned displacement node, numbered node by node, ranks in order).
struct VertexBlockMap {
  int dim = 0;
  std::vector<PetscInt> ext_of_free; ///< per local free component: its extended row
  PetscInt ext_local = 0;            ///< extended rows on this rank (dim x owned vertices)
  PetscInt ext_start = 0;            ///< first extended row of this rank
  std::vector<Vec> ext_modes;        ///< rigid-body modes in the extended numbering
  Vec ext_of_free_global = nullptr;  ///< ext_of_free as a vector of the displacement block
  /// -ksp_diagonal_scale: the outer solver (borrowed) may hand the PC D^-1/2 A D^-1/2 with
  /// D = diag(A); the near null space of that operator is D^1/2 times the rigid-body modes.
  /// Measured on the coarse 3D caisson: unscaled modes on the scaled operator took GAMG 71
  /// iterations per displacement solve instead of 26.
  KSP outer = nullptr;
  Vec jacobian_diagonal = nullptr; ///< diag of the whole Jacobian, filled at each assembly
  Vec coordinates = nullptr;       ///< vertex coordinates in the extended numbering (dumps)
  IS displacement = nullptr;       ///< the displacement split in the whole system
  /// Per owned node (extended numbering order): the largest Young's modulus [Pa] of the
  /// cells around it, on every rank's cells (stiff_bodies.hpp).
  std::vector<PetscReal> node_modulus;
  /// At -displacement_order 2: the same field at order 1 (vertices only), the coarse level of
  /// the order coarsening (order_coarsening.hpp). Empty at order 1.
  struct OrderOneLevel {
    PetscInt coarse_local = 0; ///< coarse rows on this rank (dim x owned vertices)
    PetscInt coarse_start = 0; ///< first coarse row of this rank
    /// Per owned node (extended numbering order): its coarse node (a vertex), or -1.
    std::vector<PetscInt> coarse_of_node;
    /// Per owned node that is not a vertex: the vertices of its point's closure, as
    /// [first, next) ranges into the two arrays below (first = node_vertex_start[k]).
    std::vector<PetscInt> node_vertex_start;
    std::vector<PetscInt> vertex_coarse; ///< that vertex's coarse node (global)
    std::vector<PetscInt> vertex_ext;    ///< that vertex's node in the extended numbering
    /// Free components of each such vertex, bit c set when component c is an unknown.
    std::vector<unsigned char> vertex_free;
    std::vector<unsigned char> node_free; ///< per owned node: its free components, as above
  } order_one;
  bool quadratic() const { return !order_one.coarse_of_node.empty(); }
};

/// The map attached to the near null space of P (the displacement split's matrix); a clear
/// error when P is not poroseam's displacement split.
PetscErrorCode findMap(Mat P, const VertexBlockMap **map);

} // namespace vertex_blocks_detail
} // namespace poroseam
