// The Gmsh element types poroseam knows (numbers of the MSH format): their node counts and
// dimensions, the linear type with the same corners, and a name for messages. Apart from
// msh_check.cpp because they are facts of the format, not of checking a file.
#pragma once

namespace poroseam::msh {

/// Nodes per element for the Gmsh types poroseam computes with: linear elements, and the
/// complete second-order ones (gmsh -order 2; -mesh_geometry_order 2), whose first nodes are
/// the corners of the linear type (linearType). Sets *dim; -1 for any other type.
int nodesOfType(long type, int *dim);

/// The linear type with the same corners (a second-order type's first nodes).
long linearType(long type);

/// A name for messages of the types poroseam refuses and of the second-order ones.
const char *typeName(long type);

} // namespace poroseam::msh
