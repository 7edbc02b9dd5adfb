// Which unknowns exist where: the PetscSection of the solution, built from the scene.
// Field 0 "displacement" (dim components) lives on every vertex, and with
// -displacement_order 2 on every edge and every quadrilateral and hexahedron too (one node
// per point: P2 / Lagrange Q2, docs/elements.md); field 1 "pressure" (linear) only on
// vertices of porous regions, and only when the scene is not drained; field 2
// "interface_pressure" only on the lateral edges of cohesive cells of interfaces with flow.
// Dirichlet conditions are section constraints, so constrained values never enter the global
// vector.
#pragma once

#include "poroseam/scene.hpp"
#include <petscdmplex.h>
#include <string>
#include <vector>

namespace poroseam {

constexpr int kDisplacementField = 0;
constexpr int kPressureField = 1;          ///< present when there is any pressure at all
constexpr int kInterfacePressureField = 2; ///< present when an interface has flow

/// Label names set on the serial mesh before distribution, so that every rank agrees on the
/// layout of shared points.
constexpr const char *kPorousLabel = "porous closure";
/// Lateral edges (one per split vertex pair) of cohesive cells of interfaces with flow: the
/// home of the interface pressure p3, the paper's middle nodes.
constexpr const char *kInterfacePressureLabel = "interface pressure";
std::string boundaryLabelName(const std::string &boundary);

/// The lateral edges (interface pressure p3) of interfaces with flow that end on the named
/// boundary: those whose vertex lies in the boundary's label. The one rule for where -bc_<b>_p3
/// applies, shared by the section constraints, the boundary values and the reported outflows.
PetscErrorCode lateralEdgesOnBoundary(DM dm, const std::string &boundary,
                                      std::vector<PetscInt> &edges);

/// The points whose unknowns the Dirichlet condition `bc` prescribes on this rank: the lateral
/// edges of -bc_<b>_p3 (lateralEdgesOnBoundary), else the points of the boundary's label. The
/// one rule shared by the section's constraints and the prescribed values.
PetscErrorCode dirichletPoints(DM dm, const BoundaryCondition &bc, std::vector<PetscInt> &points);

/// Before distribution: marks the closure of porous cells and of every scene boundary.
PetscErrorCode markLayoutLabels(DM dm, const Scene &scene);

/// After distribution: builds the local section (fields and constraints) and sets it on dm.
PetscErrorCode createSolutionSection(DM dm, const Scene &scene);

/// The rows of the water unknowns, bulk and interface pressure together (global indices,
/// sorted), from the field index sets of DMCreateFieldIS; null when the scene has none.
PetscErrorCode pressureRows(PetscInt num_fields, const IS fields[], IS *rows);

} // namespace poroseam
