// Gmsh's element types: node counts, linear corners and names (msh_element_types.hpp).
// Apart from msh_check.cpp because they are facts of the format, not of checking a file.
#include "poroseam/msh_element_types.hpp"

namespace poroseam::msh {

/// Nodes per element for the Gmsh types poroseam computes with: linear elements, and the
/// complete second-order ones (gmsh -order 2; -mesh_geometry_order 2), whose first nodes are
/// the corners of the linear type (linearType).
int nodesOfType(long type, int *dim)
{
  switch (type) {
  case 8:
    *dim = 1;
    return 3; // 3-node line
  case 9:
    *dim = 2;
    return 6; // 6-node triangle
  case 10:
    *dim = 2;
    return 9; // 9-node quadrangle
  case 11:
    *dim = 3;
    return 10; // 10-node tetrahedron
  case 12:
    *dim = 3;
    return 27; // 27-node hexahedron
  case 15:
    *dim = 0;
    return 1; // point
  case 1:
    *dim = 1;
    return 2; // line
  case 2:
    *dim = 2;
    return 3; // triangle
  case 3:
    *dim = 2;
    return 4; // quadrangle
  case 4:
    *dim = 3;
    return 4; // tetrahedron
  case 5:
    *dim = 3;
    return 8; // hexahedron
  default:
    return -1;
  }
}

/// The linear type with the same corners (a second-order type's first nodes).
long linearType(long type)
{
  return type == 8 ? 1 : type == 9 ? 2 : type == 10 ? 3 : type == 11 ? 4 : type == 12 ? 5 : type;
}

const char *typeName(long type)
{
  switch (type) {
  case 6:
    return "prism";
  case 7:
    return "pyramid";
  case 8:
    return "3-node line";
  case 9:
    return "6-node triangle";
  case 10:
    return "9-node quadrangle";
  case 11:
    return "10-node tetrahedron";
  case 12:
    return "27-node hexahedron";
  case 16:
    return "8-node quadrangle";
  case 17:
    return "20-node hexahedron";
  default:
    return "unknown type";
  }
}
} // namespace poroseam::msh
