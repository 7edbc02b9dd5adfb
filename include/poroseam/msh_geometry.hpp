// The geometry of a Gmsh mesh while msh_check.cpp reads it: node coordinates and the shape of
// every element, checked before PETSc's reader sees the file. PETSc builds the DMPlex from
// the connectivity alone, so coincident nodes (cells that look joined but are not), cells of
// zero size, folded quadrangles and hexahedra, a 2D mesh off the plane z = 0 (PETSc drops z)
// and physical groups that name no element all pass it silently or crash later.
#pragma once

#include "poroseam/scene.hpp"

#include <array>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace poroseam {

class MshGeometry {
public:
  /// The largest node tag a file with `nodes` nodes may use: PETSc's reader allocates arrays
  /// indexed by node tag, so a file of a few nodes with tag 2e9 takes gigabytes.
  static long long maxNodeTag(long long nodes) { return 100 * nodes + 1000000; }

  bool has(long long tag) const { return index_.count(tag) > 0; }
  /// The coordinates of a node that exists (has(tag)).
  const std::array<double, 3> &coordinates(long long tag) const { return x_[index_.at(tag)]; }
  /// Records a node; false when its tag is there already.
  bool node(long long tag, double x, double y, double z);
  /// Checks one linear element (Gmsh type 1, 2, 3, 4, 5 or 15) whose nodes exist, and notes
  /// its physical tag (-1: none). Returns "" or what is wrong with it (element named).
  std::string element(long long tag, long long type, const std::vector<long long> &nodes,
                      long long physical);
  /// Notes that physical group (dim, tag) has an element.
  void usePhysical(int dim, long long tag) { used_.insert({dim, tag}); }
  /// After the whole file: coincident nodes, a 2D mesh off z = 0, empty physical groups.
  std::string finish(const std::vector<PhysicalName> &names, int mesh_dim) const;

private:
  static int nodesOf(char type) { return type == 1 ? 2 : type == 2 ? 3 : type == 5 ? 8 : 4; }
  static int dimOf(char type) { return type == 1 ? 1 : type == 2 || type == 3 ? 2 : 3; }
  double diameter() const;
  std::string checkFaces(const std::vector<PhysicalName> &names, int mesh_dim) const;
  std::unordered_map<long long, size_t> index_;
  std::vector<long long> tags_;
  std::vector<std::array<double, 3>> x_;
  std::set<std::pair<int, long long>> used_;
  // elements of dimension >= 1: Gmsh type, tag, physical tag, node indices (flat)
  std::vector<char> types_;
  std::vector<long long> tags_of_elements_, physical_of_elements_;
  std::vector<unsigned> element_nodes_; // (dimension, physical tag) of some element
  double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
  mutable double diameter_ = -1;
};

} // namespace poroseam
