// Validation of a Gmsh .msh file before PETSc reads it: PETSc 3.18's reader trusts the file
// (an element naming a node that does not exist crashes it with SIGSEGV; a truncated file or
// a wrong count gives a traceback without the file's name). Every structural error is found
// here and reported in one line that names the file and says what is expected.
#pragma once

#include "poroseam/scene.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace poroseam {

struct MshSummary {
  int version = 0;     // 22 or 41
  bool binary = false; // file-type 1
  int dim = 0;         // largest dimension of an element
  long nodes = 0;
  long cells = 0; // elements of dimension `dim`
  int order = 0;  // 1 linear elements, 2 second-order (gmsh -order 2); 0 none
  /// Each point element of a physical point group: (physical tag, coordinates). PETSc 3.18's
  /// reader keeps no label of them (loadGmshMesh marks their vertices, "Vertex Sets").
  std::vector<std::pair<long long, std::array<double, 3>>> points;
  /// Each line element of a physical curve: (physical tag, its two nodes' coordinates); in a
  /// 3D mesh loadGmshMesh marks their edges ("Edge Sets").
  std::vector<std::pair<long long, std::array<double, 6>>> lines;
};

/// Reads the whole file at `path` and checks it against the MSH 2.2 and 4.1 formats (ASCII
/// and binary): header, section order and end markers, counts, node tags (unique, within
/// the declared range), element types (linear points, lines, triangles, quadrangles,
/// tetrahedra, hexahedra: what poroseam computes with), every element's nodes exist, entities
/// named by blocks exist, finite coordinates, and a $PhysicalNames block. Returns "" when the
/// file is good, with `names` and `summary` filled; otherwise one line naming the file
/// ("mesh file 'x.msh' (option -mesh): ...") and the place (line or byte offset).
std::string checkGmshFile(const std::string &path, std::vector<PhysicalName> &names,
                          MshSummary &summary);

} // namespace poroseam
