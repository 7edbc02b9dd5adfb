// Limits on making and reading a mesh: the element count (-mesh_max_elements), gmsh's time
// (-mesh_time_limit) and the memory the run will need (-mesh_memory_check), estimated from the
// mesh's nodes and the linear solver preset before the mesh is made or read.
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

struct MeshLimits {
  long max_elements = 2000000; ///< cells of the mesh dimension (-mesh_max_elements)
  double time_limit = 600.0;   ///< seconds gmsh may take for one mesh (-mesh_time_limit)
  bool memory_check = true;    ///< refuse a mesh whose estimated memory exceeds the machine's
  std::string preset;          ///< -solver_preset as given ("" when none)
  std::string pc_type;         ///< -pc_type as given ("" when none)
  std::string ksp_type;        ///< -ksp_type as given ("" when none)
  long auto_threshold = 30000; ///< -solver_auto_threshold (default: by order, readMeshLimits)
  int ranks = 1;
};

/// Reads the options above (collective; -help lists them); `displacement_order` gives the
/// default of -solver_auto_threshold (solver_preset.hpp).
PetscErrorCode readMeshLimits(MPI_Comm comm, int displacement_order, MeshLimits *limits);

/// The memory a run on a mesh with `nodes` vertices of dimension `dim` needs, estimated from
/// its unknowns (at most dim + 1 per node: displacement and pressure) and the linear solver
/// the preset will choose. `what` describes the mesh for the messages ("-mesh_size_factor 0.2
/// would make about ... from 'x.geo'"). Returns "" when it fits (then *note holds one line for
/// the output when the estimate is large enough to matter, else ""), or the error.
std::string checkMeshMemory(const MeshLimits &limits, double nodes, int dim,
                            const std::string &what, const std::string &remedy, std::string *note);

} // namespace poroseam
