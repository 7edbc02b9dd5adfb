// Two boundaries that share vertices (a corner, an edge in 3D, or overlapping face groups)
// and prescribe the same unknown there: the rule for which one holds, and its report.
#pragma once

#include "poroseam/scene.hpp"

#include <petscdmplex.h>

namespace poroseam {

/// Collective. Where two boundaries prescribe the same unknown (a displacement component, the
/// pore pressure of a porous vertex, or p3 of an interface's lateral edge) at a shared point
/// with different values (magnitude or time function), the rule is: the boundary listed later
/// in -boundaries holds there (its value is the one applied, Problem::insertBoundaryValues).
/// That is legitimate (a drained top meeting a pressurised side) but never silent: one warning
/// line per such pair of conditions, naming both options, the number of shared points and the
/// first of them, and which one holds. Equal values are not reported. Needs the boundary
/// labels of markLayoutLabels (layout.hpp).
PetscErrorCode reportCornerConditions(DM dm, const Scene &scene);

} // namespace poroseam
