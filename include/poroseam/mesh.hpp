// Gmsh input and distribution of the DMPlex mesh.
#pragma once

#include "poroseam/scene.hpp"
#include <petscdmplex.h>
#include <string>
#include <vector>

namespace poroseam {

/// Reads a Gmsh mesh (.msh, or .geo meshed with gmsh using the size factor) on rank 0 as an
/// interpolated DMPlex, with labels "Cell Sets" and "Face Sets" holding the physical tags.
/// `names` receives the physical names of the file (same on every rank); `dim` the mesh
/// dimension. A `.geo` is meshed into `work_dir`. `geometry_order` 2 (-mesh_geometry_order):
/// a .geo is meshed with gmsh -order 2, and the DM carries the table of the high-order nodes
/// (curved_nodes.hpp); its coordinates stay on the vertices. `displacement_order`
/// (-displacement_order) enters the memory estimate (mesh_limits.hpp).
PetscErrorCode loadGmshMesh(MPI_Comm comm, const std::string &file, double size_factor,
                            const std::string &work_dir, DM *dm, std::vector<PhysicalName> *names,
                            int *dim, int geometry_order = 1, int displacement_order = 1);

/// Distributes the mesh and replaces *dm by the distributed one; labels travel with the
/// points. The partitioner comes from -partitioner ptscotch|metis|simple (default ptscotch;
/// metis keeps cohesive cells with their bulk neighbours, see partition.hpp).
PetscErrorCode distributeMesh(DM *dm);

/// A number for every local point of the (distributed) mesh that does not depend on the
/// number of ranks or the partition: its point number in the mesh as read and split into
/// interfaces, before distributeMesh (which keeps it). The output files order their vertices
/// and cells by it, so the same run writes the same files.
PetscErrorCode serialPointNumbers(DM dm, std::vector<PetscInt> &number);

/// Stops with a clear error when a bulk cell has a non-positive Jacobian determinant
/// (inverted element), naming the cell and its centroid.
PetscErrorCode checkCellOrientation(DM dm);

} // namespace poroseam
