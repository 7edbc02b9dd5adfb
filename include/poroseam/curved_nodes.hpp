// Curved cells (-mesh_geometry_order 2): where a second-order Gmsh mesh puts the node of each
// edge, quadrilateral face and hexahedron (docs/elements.md, "Curved geometry"). The DMPlex
// poroseam computes on keeps its coordinates on the vertices (every reader of vertex
// coordinates stays as it is); the high-order nodes live in this table, found by the place
// where the straight-sided cell would put them (the mean of the point's vertices). That key
// survives what changes point numbers: the interfaces' split (both copies of a face find the
// same node) and the distribution.
#pragma once

#include <petscdm.h>
#include <unordered_map>
#include <vector>

namespace poroseam {

class CurvedNodes {
public:
  /// Notes the node of a point with `corners` vertices whose mean is `straight`.
  void add(int corners, const double straight[3], const double curved[3]);
  /// Builds the look-up; `tolerance` is the distance within which two means are one place.
  void finish(double tolerance);
  /// The curved node of a point with `corners` vertices whose mean is `straight`; false when
  /// the table has none there.
  bool find(int corners, const double straight[3], double curved[3]) const;
  size_t size() const { return entries_.size() / kStride; }
  /// All entries, packed (for the broadcast from rank 0): corners, straight[3], curved[3].
  const std::vector<double> &packed() const { return entries_; }
  void setPacked(std::vector<double> entries) { entries_ = std::move(entries); }
  double tolerance() const { return tolerance_; }

  static constexpr int kStride = 7;

private:
  long long bucketKey(int corners, const long long cell[3]) const;
  void bucketOf(const double x[3], long long cell[3]) const;
  std::vector<double> entries_;
  double tolerance_ = 0.0, bucket_ = 1.0;
  std::unordered_multimap<long long, size_t> index_;
};

/// On every rank of `comm`: reads the second-order Gmsh file `msh` a second time on rank 0,
/// with PETSc's high-order coordinates (-dm_plex_gmsh_highorder: a coordinate field of degree
/// 2, one node on each edge, quadrilateral and hexahedron), checks that its points are those
/// of `linear` (the same file read with vertex coordinates), and attaches the table of its
/// nodes to `linear` (curvedNodes).
PetscErrorCode attachCurvedNodes(MPI_Comm comm, const char *msh, DM linear);

/// Reads a Gmsh file into an interpolated DMPlex with PETSc's reader, with or without its
/// high-order coordinate field (PETSc 3.18 keeps it by default: -dm_plex_gmsh_highorder).
PetscErrorCode readGmshFile(MPI_Comm comm, const char *msh, bool high_order, DM *dm);

/// The table attached to dm, or nullptr (straight-sided cells).
const CurvedNodes *curvedNodes(DM dm);

/// Attaches the table of `from` (if any) to `to`: a DM made from another (split, distributed).
PetscErrorCode keepCurvedNodes(DM from, DM to);

} // namespace poroseam
