// Which unknowns exist where: the PetscSection of the solution, built from the scene.
// Field 0 "displacement" (dim components) lives on every vertex; field 1 "pressure" only on
// vertices of porous regions, and only when the scene is not drained. Dirichlet conditions are
// section constraints, so constrained values never enter the global vector.
#pragma once

#include "poroseam/scene.hpp"
#include <petscdmplex.h>

namespace poroseam {

constexpr int kDisplacementField = 0;
constexpr int kPressureField = 1;

/// Label names set on the serial mesh before distribution, so that every rank agrees on the
/// layout of shared points.
constexpr const char *kPorousLabel = "porous closure";
std::string boundaryLabelName(const std::string &boundary);

/// Before distribution: marks the closure of porous cells and of every scene boundary.
PetscErrorCode markLayoutLabels(DM dm, const Scene &scene);

/// After distribution: builds the local section (fields and constraints) and sets it on dm.
PetscErrorCode createSolutionSection(DM dm, const Scene &scene);

} // namespace poroseam
