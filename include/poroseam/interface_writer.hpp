// Interface output: HDF5 + XDMF time series of the zero-thickness interfaces (cohesive cells)
// that ParaView opens next to the bulk fields.
#pragma once

#include "poroseam/interface_assembly.hpp"
#include "poroseam/scene.hpp"
#include <petscvec.h>
#include <string>

namespace poroseam {

/// Writes `<dir>/interfaces.h5` and two XDMF files over it, `<dir>/interface_cells.xmf` and
/// `<dir>/interface_points.xmf`, each one temporal collection (meshio reads one grid per file;
/// ParaView opens both):
///  - "interface_cells": one cell per cohesive cell, its side-1 face (Polyline of 2 nodes in
///    2D; Triangle or Quadrilateral in 3D, or XDMF "Mixed" topology when the interfaces have
///    both). Nodes are duplicated per cell (cell i's nodes follow cell i-1's). Cell data are
///    averages over the cell's integration points weighted by their area (`weight`), except
///    state (the maximum: 0 open, 1 stick, 2 slip) and mobilised_friction (|mean tau| /
///    mean p'_N of the cell, 0 where mean p'_N = 0).
///  - "interface_points": every integration point as a Polyvertex at its position x, with
///    the same quantities unaveraged (mobilised_friction = |tau| / p'_N there).
/// Both grids carry displacement_minus and displacement_plus, the displacements of side 1 and
/// side 2 (at the cell grid's nodes, interpolated at the points), to warp the interface with
/// the bulk, and the id of each cell's named part (`part`, names in an HDF5 attribute).
/// When some interface has flow (Scene::hasInterfacePressure()) both grids also carry
/// interface_pressure, aperture, aperture_rate, longitudinal_flux (3-vector), transversal_flux1
/// and transversal_flux2 (cell values: weighted averages; 0 on interfaces without flow and
/// when write() gets no rate vector).
/// Geometry, topology and the constant data (interface, surface, normal, area/weight, owning
/// cell) are written at the first write(); every write() appends one time. The HDF5 layout
/// is described in src/output/interface_writer.cpp; tests/support/interface_reader.py reads it.
/// Cells are ordered by rank, then in InterfaceAssembly::visit order. Collective on comm.
class InterfaceWriter {
public:
  InterfaceWriter() = default;
  InterfaceWriter(const InterfaceWriter &) = delete;
  InterfaceWriter &operator=(const InterfaceWriter &) = delete;
  ~InterfaceWriter();

  /// Prepares the files (nothing at all when the scene has no interfaces). `scene` must
  /// outlive the writer. With `resume` (a restarted run) the files of the interrupted run
  /// are continued after their first resume->size() times (see FieldWriter::open).
  PetscErrorCode open(MPI_Comm comm, const Scene &scene, const std::string &dir,
                      const std::vector<double> *resume = nullptr);
  /// Appends one time: the interface state at `local_solution` (a local vector of the
  /// solution DM with boundary values inserted). `rates` (local rate vector and dt) are
  /// needed for the hydraulic fields: without rates.rate they are written as 0. Returns at
  /// once without interfaces.
  PetscErrorCode write(double time, const InterfaceAssembly &mech, Vec local_solution,
                       const InterfaceRates &rates = InterfaceRates{});
  /// The times written so far (a resumed writer's included): what a checkpoint keeps.
  std::vector<double> times() const;
  /// Closes the HDF5 file and finishes the XDMF index (also called by the destructor).
  PetscErrorCode close();

private:
  struct Impl;
  Impl *impl_ = nullptr;
};

} // namespace poroseam
