// Fieldsplit set-up: named splits from the solution section, with the rigid-body modes of the
// displacement block attached as its near null space (AMG needs them for elasticity).
#pragma once

#include "poroseam/mesh_points.hpp" // displacementNodeLocation
#include "poroseam/scene.hpp"
#include <petscts.h>
#include <vector>

namespace poroseam {

class Problem;

/// The rigid-body modes (3 in 2D, 6 in 3D; axisymmetric: the 2 translations) of the
/// displacement at every displacement node, restricted to the free dofs of the split
/// `displacement` (global indices) and orthonormalised: the near null space of the elastic
/// stiffness without supports, exactly at both orders (a field linear in x is in the P2 / Q2
/// space of a straight-sided cell, tests/unit/test_rigid_modes.cpp).
PetscErrorCode displacementRigidBodyModes(DM dm, int dim, bool axisymmetric, IS displacement,
                                          MatNullSpace *space);

/// Makes `vectors` orthonormal in place (modified Gram-Schmidt), as MatNullSpaceCreate expects.
PetscErrorCode orthonormalize(std::vector<Vec> &vectors);

/// If the PC of the TS's Newton solver is PCFIELDSPLIT, defines the splits "displacement"
/// (with the rigid-body modes at every displacement node, both orders, attached as its near
/// null space) and "pressure" (the bulk and
/// the interface pressures together: a Schur complement takes exactly two splits).
/// Call after TSSetFromOptions. With a fieldsplit, *jacobian_diagonal becomes a global vector
/// that the caller must fill with the Jacobian's diagonal at every assembly (the displacement
/// preconditioner vertex_blocks needs it); otherwise it stays null. `problem` (set up) gives
/// the region of each bulk cell, whose Young's modulus marks vertex_blocks' stiff bodies.
PetscErrorCode configureFieldSplit(TS ts, DM dm, const Scene &scene, const Problem &problem,
                                   Vec *jacobian_diagonal);

} // namespace poroseam
