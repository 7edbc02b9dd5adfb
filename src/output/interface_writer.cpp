// Interface output: HDF5 (through PETSc's HDF5 viewer) plus an XDMF index for ParaView.
//
// HDF5 layout of <dir>/interfaces.h5. Nc cells (one per cohesive cell: its side-1 face), Nn
// cell nodes (every cell has its own copies, cell after cell), Np integration points; all in
// the order of the cohesive cells' point numbers in the serial mesh (serialPointNumbers: the
// same files on any number of ranks and any partition), a cell's nodes and points in the
// order InterfaceAssembly::visit gives them. d = mesh dimension, t = d - 1 tangent components.
// Integers are PetscInt.
//   /cells/geometry                  [Nn, d]  double  face vertex coordinates
//   /cells/topology                  [Nc, n]  int     node indices (n = 2, 3 or 4; face closure
//                                                     order, the XDMF/VTK order), or [L, 1] in
//                                                     XDMF "Mixed" form (4 = Triangle, 5 = Quad,
//                                                     then the nodes) when triangles and quads mix
//   /cells/nodes_per_cell            [Nc, 1]  int
//   /cells/interface, /cells/surface [Nc, 1]  int     index in Scene::interfaces / its surfaces
//   /cells/part                      [Nc, 1]  int     index of the named part (interface, or
//                                                     interface.surface when it has several);
//                                                     attribute "names": the parts, comma
//                                                     separated (interface likewise)
//   /cells/area                      [Nc]     double  sum of the integration point weights
//   /cells/normal                    [Nc, 3]  double  e1 (side 1 -> side 2)
//   /points/geometry                 [Np, d]  double  integration point positions
//   /points/topology                 [Np, 1]  int     0..Np-1 (Polyvertex)
//   /points/interface, /points/surface, /points/part, /points/cell (index of its cell),
//   /points/point (index within the cell)   [Np, 1] int (PETSc writes integers as [N, bs])
//   /points/weight [Np], /points/normal [Np, 3]       double
//   /cells/fields/<name>/<step>, /points/fields/<name>/<step>, each with attribute "time":
//     gap_normal [N], opening [N], slip [N] (2D) or [N, 2] (3D): local tangential gap,
//     slip_vector [N, 3] = sum_k slip_k e_(k+1), contact_pressure_effective [N],
//     shear_stress [N] or [N, 2]: local tau, shear_traction [N, 3] = sum_k tau_k e_(k+1),
//     traction [N, 3] (on side 1, global), mobilised_friction [N] = |tau| / p'_N (0 where
//     p'_N = 0), state [N, 1] int (0 open, 1 stick, 2 slip).
//   /cells/fields/displacement_minus/<step>, .../displacement_plus/<step> [Nn, 3]: the
//     displacement of side 1 (minus) and side 2 (plus) at each cell node, so that the faces
//     can be warped with the bulk; /points/fields/displacement_minus|plus [Np, 3] the same
//     interpolated at the integration points.
//   Only when some interface of the scene has flow (Scene::hasInterfacePressure()), also:
//     interface_pressure [N] (p3), aperture [N] (h = D0 + opening), aperture_rate [N] (dh/dt),
//     longitudinal_flux [N, 3] (q_l, global, m2/s), transversal_flux1 [N] (side 1 -> gap) and
//     transversal_flux2 [N] (gap -> side 2), m/s. They are 0 on interfaces without flow and
//     everywhere when write() gets no rate vector (InterfaceAssembly::visit computes them
//     only with rates.rate).
//   Cell values are averages over the cell's points weighted by `weight`; the cell's
//   mobilised_friction is |mean tau| / mean p'_N and its state the maximum over its points.
// Every dataset has a string attribute "units" (SI; "1" for numbers without a unit).
// XDMF: two files, each one temporal collection (one grid per file: meshio reads only the
// first grid of a file, ParaView opens both together): <dir>/interface_cells.xmf,
// "interface_cells" (Polyline / Triangle / Quadrilateral / Mixed, Center="Cell" attributes,
// displacement_minus / _plus Center="Node"), and <dir>/interface_points.xmf,
// "interface_points" (Polyvertex, Center="Node" attributes). 2-component arrays have
// AttributeType "Matrix" (XDMF "Vector" means 3 components). Rank 0 rewrites the XDMF files
// after every write() (temporary file + rename).
#include "interface_writer_impl.hpp"

#include "poroseam/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace poroseam {

using namespace interface_output;

std::string InterfaceWriter::Impl::interfaceNames() const
{
  std::string list;
  for (const Interface &i : scene->interfaces)
    list += (list.empty() ? "" : ",") + i.name;
  return list;
}

std::string InterfaceWriter::Impl::partNames() const
{
  std::string list;
  for (const Interface &i : scene->interfaces) {
    if (i.surfaces.size() <= 1)
      list += (list.empty() ? "" : ",") + i.name;
    else
      for (const std::string &surface : i.surfaces)
        list += (list.empty() ? "" : ",") + i.name + "." + surface;
  }
  return list;
}

int InterfaceWriter::Impl::part(int iface, int surface) const
{
  int k = 0;
  for (int i = 0; i < iface; ++i)
    k += std::max<int>(1, static_cast<int>(scene->interfaces[i].surfaces.size()));
  return k + (scene->interfaces[iface].surfaces.size() <= 1 ? 0 : surface);
}

InterfaceWriter::~InterfaceWriter()
{
  if (impl_) {
    // Errors cannot propagate from a destructor; close() is expected to be called explicitly.
    // Here the run is ending in an error: close the file on every rank together, quietly (the
    // error has been reported), if every rank is here within 20 s; after an error on one rank
    // only, the others never come (main.cpp then ends the run with MPI_Abort).
    if (impl_->viewer && impl_->closing.allThere(20.0) &&
        !PetscPushErrorHandler(PetscReturnErrorHandler, nullptr)) {
      (void)close();
      (void)PetscPopErrorHandler();
    }
    delete impl_;
    impl_ = nullptr;
  }
}

std::vector<double> InterfaceWriter::times() const
{
  return impl_ ? impl_->times : std::vector<double>();
}

PetscErrorCode InterfaceWriter::open(MPI_Comm comm, const Scene &scene, const std::string &dir,
                                     const std::vector<double> *resume)
{
  PetscFunctionBeginUser;
  PetscCheck(!impl_ || !impl_->viewer, comm, PETSC_ERR_ARG_WRONGSTATE,
             "InterfaceWriter::open called twice");
  delete impl_;
  impl_ = new Impl;
  Impl &im = *impl_;
  im.comm = comm;
  im.scene = &scene;
  im.dim = scene.dim;
  im.enabled = !scene.interfaces.empty();
  im.flow = scene.hasInterfacePressure();
  if (!im.enabled) PetscFunctionReturn(0);
  PetscCheck(im.dim == 2 || im.dim == 3, comm, PETSC_ERR_SUP,
             "InterfaceWriter: dimension %d not supported", im.dim);
  PetscCall(xdmf::createDirectory(comm, dir, kWho));
  const std::string prefix = dir.empty() ? std::string("interfaces") : dir + "/interfaces";
  const std::string folder = dir.empty() ? std::string() : dir + "/";
  im.xmfPath[0] = folder + "interface_cells.xmf";
  im.xmfPath[1] = folder + "interface_points.xmf";
  // Resuming: the mesh is written again at the first write (PETSc's HDF5 viewer overwrites
  // existing datasets), values after the checkpoint's last time are overwritten.
  if (resume) im.times = *resume;
  im.h5Path = prefix + ".h5";
  PetscCall(im.closing.init(comm));
  im.dir = dir;
  PetscCall(xdmf::agreed(comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscViewerHDF5Open(comm, im.h5Path.c_str(),
                                  resume ? FILE_MODE_APPEND : FILE_MODE_WRITE, &im.viewer));
    PetscFunctionReturn(0);
  }));
  // (The interrupted run's index stays until the first write knows the mesh again.)
  if (!resume) PetscCall(im.writeXdmf());
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceWriter::write(double time, const InterfaceAssembly &mech,
                                      Vec local_solution, const InterfaceRates &rates)
{
  PetscFunctionBeginUser;
  PetscCheck(impl_, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
             "InterfaceWriter::write called before open");
  Impl &im = *impl_;
  if (!im.enabled) PetscFunctionReturn(0);
  PetscCheck(im.viewer && !im.failed, im.comm, PETSC_ERR_ARG_WRONGSTATE,
             "InterfaceWriter::write after close or a failure");

  std::vector<CellRecord> cells;
  std::vector<PointRecord> points;
  PetscCall(interface_output::collect(mech, im.dim, local_solution, rates, cells, points));
  // The serial point numbers that order the output (collective, so outside the agreed write).
  std::vector<PetscInt> serial;
  if (!im.mesh_written) {
    DM dm;
    PetscCall(VecGetDM(local_solution, &dm));
    PetscCheck(dm, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "InterfaceWriter::write: the solution vector has no DM");
    PetscCall(serialPointNumbers(dm, serial));
  } else {
    int same = cells.size() == im.local_cells.size(), all;
    for (size_t i = 0; same && i < cells.size(); ++i)
      same = cells[i].cell == im.local_cells[i] &&
             static_cast<int>(cells[i].count) == im.local_point_count[i];
    PetscCallMPI(MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, im.comm));
    PetscCheck(all, im.comm, PETSC_ERR_ARG_WRONGSTATE,
               "InterfaceWriter: the interface cells changed since the first write");
  }
  {
    // At most some 40 values per point and cell node, and the mesh at the first write.
    const double bytes = 8.0 * 64.0 * (double)(cells.size() + points.size());
    char what[64];
    std::snprintf(what, sizeof what, "the interface fields at t = %g s", time);
    PetscCall(reserveSpace(im.comm, im.dir, im.h5Path, bytes, what));
  }
  PetscCall(xdmf::agreed(im.comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (!im.mesh_written) PetscCall(im.writeMesh(cells, points, serial));
    PetscCall(im.writeStep(cells, points, time));
    PetscFunctionReturn(0);
  }));
  im.times.push_back(time);
  PetscCall(im.writeXdmf());
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceWriter::close()
{
  PetscFunctionBeginUser;
  if (!impl_ || !impl_->viewer) PetscFunctionReturn(0);
  Impl &im = *impl_;
  if (im.failed) { // the indexes name what the file holds; the error is on its way up
    PetscCall(PetscViewerDestroy(&im.viewer));
    PetscFunctionReturn(0);
  }
  PetscCall(xdmf::agreed(im.comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscViewerDestroy(&im.viewer));
    PetscFunctionReturn(0);
  }));
  // A resumed writer that wrote nothing does not know the mesh: keep the existing index.
  if (impl_->mesh_written || impl_->times.empty()) PetscCall(impl_->writeXdmf());
  for (OutputOrder *o : {&impl_->cell_order, &impl_->node_order, &impl_->point_order})
    PetscCall(o->destroy());
  PetscFunctionReturn(0);
}

} // namespace poroseam
