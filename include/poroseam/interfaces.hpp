// Splitting the mesh along interfaces into cohesive cells (before distribution), and the
// labels that tell each cohesive cell which interface it belongs to and where side 1 is.
#pragma once

#include "poroseam/scene.hpp"
#include <petscdmplex.h>

namespace poroseam {

/// Cohesive cell -> interface index + 1.
constexpr const char *kInterfaceLabel = "interface";
/// Cohesive cell -> index + 1 of its surface (named part) in Interface::surfaces.
constexpr const char *kInterfaceSurfaceLabel = "interface surface";
/// Cohesive cell -> 1 when cone[0] is the face of side 1, 2 when cone[1] is.
constexpr const char *kInterfaceSideLabel = "interface side";
/// Cohesive cell -> 1 when the natural normal of cone[0] (from its closure order) points
/// from side 1 to side 2, 2 when it points the other way. Cones survive distribution, so
/// the frame can be rebuilt on any rank without the bulk neighbours.
constexpr const char *kInterfaceNormalLabel = "interface normal";

bool isCohesive(DMPolytopeType type);

/// The bulk cell on the other side of `face` from the cohesive cell, or -1 when this rank does
/// not hold it.
PetscErrorCode bulkNeighbour(DM dm, PetscInt face, PetscInt *cell);

/// Splits the serial mesh along all interfaces of the scene (no-op without interfaces) and
/// sets the labels above. Interfaces that end inside the mesh are handled (buried tips).
PetscErrorCode splitInterfaces(DM *dm, const Scene &scene);

} // namespace poroseam
