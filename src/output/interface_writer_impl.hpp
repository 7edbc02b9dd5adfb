// The state of an InterfaceWriter between its calls (internal to src/output), shared by the
// files that write its parts: the writer's life (open, write, close: interface_writer.cpp),
// its HDF5 datasets (interface_datasets.cpp) and its XDMF index (interface_xdmf.cpp). The
// layout of the files is described at the top of interface_writer.cpp.
#pragma once

#include "poroseam/interface_writer.hpp"

#include "interface_records.hpp"
#include "output_order.hpp"
#include "xdmf.hpp"

#include <petscviewer.h>
#include <string>
#include <vector>

namespace poroseam {
namespace interface_output {

constexpr const char *kWho = "InterfaceWriter";

/// A dataset as the XDMF index names it.
struct Attribute {
  std::string name, path; // path: the dataset, or the group of per-step datasets
  int components;
  bool integer, per_step;
  bool node = false; // on the nodes of the cell grid (the point grid has nodes only)
};

} // namespace interface_output

struct InterfaceWriter::Impl {
  MPI_Comm comm = MPI_COMM_NULL;
  const Scene *scene = nullptr;
  bool enabled = false;
  bool flow = false; // write the hydraulic fields
  int dim = 0;
  PetscViewer viewer = nullptr;
  std::string h5name = "interfaces.h5";
  std::string xmfPath[2]; // interface_cells.xmf, interface_points.xmf
  std::string h5Path, dir;
  bool failed = false;      // a write failed (agreed by every rank): close without writing more
  xdmf::Rendezvous closing; // for a close from the destructor
  std::vector<double> times;

  // Set at the first write.
  bool mesh_written = false;
  PetscInt num_cells = 0, num_nodes = 0, num_points = 0;
  PetscInt min_nodes = 0, max_nodes = 0, mixed_length = 0;
  std::vector<PetscInt> local_cells;  // cohesive cell of each local output cell (for checks)
  std::vector<int> local_point_count; // integration points of each local output cell
  /// From this rank's order to the files' (output_order.hpp): cells, their nodes, points.
  OutputOrder cell_order, node_order, point_order;

  /// `serial`: serialPointNumbers of the mesh, the key of each cohesive cell's place.
  PetscErrorCode writeMesh(const std::vector<interface_output::CellRecord> &cells,
                           const std::vector<interface_output::PointRecord> &points,
                           const std::vector<PetscInt> &serial);
  PetscErrorCode writeValues(const std::string &grid,
                             const std::vector<interface_output::Values> &values, size_t step,
                             double time);
  /// displacement_minus / _plus at the nodes of the cell grid.
  PetscErrorCode writeNodeDisplacements(const std::vector<interface_output::CellRecord> &cells,
                                        size_t step, double time);
  std::vector<interface_output::Attribute> attributes(bool cells) const;
  PetscErrorCode writeXdmf();
  /// The values of one write() (collective), flushed.
  PetscErrorCode writeStep(const std::vector<interface_output::CellRecord> &cells,
                           const std::vector<interface_output::PointRecord> &points, double time);
  const char *units(const std::string &name) const
  {
    return interface_output::unitsOf(name, dim, scene->axisymmetric);
  }
  /// The names of the interfaces and of the parts (/cells/part), comma separated.
  std::string interfaceNames() const;
  std::string partNames() const;
  /// Index of (interface, surface) in partNames().
  int part(int iface, int surface) const;
};

} // namespace poroseam
