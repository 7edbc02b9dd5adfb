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
#include "poroseam/interface_writer.hpp"

#include "interface_records.hpp"
#include "output_order.hpp"
#include "xdmf.hpp"

#include "poroseam/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace poroseam {

using namespace interface_output;

namespace {

constexpr const char *kWho = "InterfaceWriter";

struct Attribute {
  std::string name, path; // path: the dataset, or the group of per-step datasets
  int components;
  bool integer, per_step;
  bool node = false; // on the nodes of the cell grid (the point grid has nodes only)
};

} // namespace

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
  PetscErrorCode writeMesh(const std::vector<CellRecord> &cells,
                           const std::vector<PointRecord> &points,
                           const std::vector<PetscInt> &serial);
  PetscErrorCode writeValues(const std::string &grid, const std::vector<Values> &values,
                             size_t step, double time);
  /// displacement_minus / _plus at the nodes of the cell grid.
  PetscErrorCode writeNodeDisplacements(const std::vector<CellRecord> &cells, size_t step,
                                        double time);
  std::vector<Attribute> attributes(bool cells) const;
  PetscErrorCode writeXdmf();
  /// The values of one write() (collective), flushed.
  PetscErrorCode writeStep(const std::vector<CellRecord> &cells,
                           const std::vector<PointRecord> &points, double time);
  const char *units(const std::string &name) const
  {
    return unitsOf(name, dim, scene->axisymmetric);
  }
  /// The names of the interfaces and of the parts (/cells/part), comma separated.
  std::string interfaceNames() const;
  std::string partNames() const;
  /// Index of (interface, surface) in partNames().
  int part(int iface, int surface) const;
};

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

PetscErrorCode InterfaceWriter::Impl::writeMesh(const std::vector<CellRecord> &cells,
                                                const std::vector<PointRecord> &points,
                                                const std::vector<PetscInt> &serial)
{
  const PetscInt nc = static_cast<PetscInt>(cells.size());
  const PetscInt np = static_cast<PetscInt>(points.size());
  PetscInt nn = 0, lmin = PETSC_MAX_INT, lmax = 0;

  PetscFunctionBeginUser;
  for (const CellRecord &c : cells) {
    nn += c.nodes;
    lmin = PetscMin(lmin, (PetscInt)c.nodes);
    lmax = PetscMax(lmax, (PetscInt)c.nodes);
  }
  PetscInt local[3] = {nc, nn, np}, total[3];
  PetscCall(MPIU_Allreduce(local, total, 3, MPIU_INT, MPI_SUM, comm));
  {
    PetscInt in[2] = {-lmin, lmax}, out[2];
    PetscCall(MPIU_Allreduce(in, out, 2, MPIU_INT, MPI_MAX, comm));
    min_nodes = -out[0];
    max_nodes = out[1];
  }
  num_cells = total[0];
  num_nodes = total[1];
  num_points = total[2];
  mesh_written = true;
  local_cells.clear();
  local_point_count.clear();
  for (const CellRecord &c : cells) {
    local_cells.push_back(c.cell);
    local_point_count.push_back(static_cast<int>(c.count));
  }
  if (num_cells == 0) PetscFunctionReturn(0); // nothing to write (kept as an empty index)
  // Where each cell, node and point goes in the files: cells by their serial point number, a
  // cell's nodes and points after those of the cells before it.
  std::vector<PetscInt> keys, ones(cells.size(), 1), nodes, counts, mixed_lengths;
  std::vector<PetscInt> cell_at, node_at, point_at, mixed_at;
  for (const CellRecord &c : cells) {
    keys.push_back(serial[c.cell]);
    nodes.push_back(c.nodes);
    counts.push_back((PetscInt)c.count);
    mixed_lengths.push_back(c.nodes + 1); // XDMF Mixed: the cell type, then its nodes
  }
  PetscCall(positionsByKey(comm, keys, ones, cell_at));
  PetscCall(positionsByKey(comm, keys, nodes, node_at));
  PetscCall(positionsByKey(comm, keys, counts, point_at));
  PetscCall(cell_order.setup(comm, cell_at));
  PetscCall(node_order.setup(comm, node_at));
  PetscCall(point_order.setup(comm, point_at));
  PetscCheck(dim == 3 || (min_nodes == 2 && max_nodes == 2), comm, PETSC_ERR_PLIB,
             "%s: 2D interface faces must be segments", kWho);

  // Cells.
  std::vector<PetscScalar> xyz, area, normal;
  std::vector<PetscInt> topo, npc, iface, surface, part;
  const bool mixed = min_nodes != max_nodes;
  PetscInt node = 0, mixed_local = 0;
  for (const CellRecord &c : cells) {
    xyz.insert(xyz.end(), c.coords.begin(), c.coords.end());
    if (mixed) {
      topo.push_back(c.nodes == 3 ? 4 : 5); // XDMF Triangle, Quadrilateral
      ++mixed_local;
    }
    for (int k = 0; k < c.nodes; ++k)
      topo.push_back(node_at[node++]);
    mixed_local += c.nodes;
    npc.push_back(c.nodes);
    iface.push_back(c.iface);
    surface.push_back(c.surface);
    part.push_back(this->part(c.iface, c.surface));
    double a = 0.0;
    for (size_t i = c.first; i < c.first + c.count; ++i)
      a += points[i].weight;
    area.push_back(a);
    for (int i = 0; i < 3; ++i)
      normal.push_back(points[c.first].normal[i]);
  }
  PetscCall(MPIU_Allreduce(&mixed_local, &mixed_length, 1, MPIU_INT, MPI_SUM, comm));
  if (!mixed) mixed_length = 0;
  if (mixed) {
    OutputOrder mixed_order;
    PetscCall(positionsByKey(comm, keys, mixed_lengths, mixed_at));
    PetscCall(mixed_order.setup(comm, mixed_at));
    PetscCall(mixed_order.permute(topo, 1));
  } else {
    PetscCall(cell_order.permute(topo, max_nodes));
  }
  PetscCall(node_order.permute(xyz, dim));
  for (std::vector<PetscInt> *v : {&npc, &iface, &surface, &part})
    PetscCall(cell_order.permute(*v, 1));
  PetscCall(cell_order.permute(area, 1));
  PetscCall(cell_order.permute(normal, 3));
  PetscCall(
      xdmf::writeReals(viewer, comm, "/cells", "geometry", dim, xyz, units("geometry"), nullptr));
  PetscCall(xdmf::writeInts(viewer, comm, "/cells", "topology", mixed ? 1 : max_nodes, topo, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/cells", "nodes_per_cell", 1, npc, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/cells", "interface", 1, iface, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/cells", "surface", 1, surface, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/cells", "part", 1, part, "1"));
  PetscCall(xdmf::writeReals(viewer, comm, "/cells", "area", 1, area, units("area"), nullptr));
  PetscCall(xdmf::writeReals(viewer, comm, "/cells", "normal", 3, normal, "1", nullptr));

  // Integration points.
  std::vector<PetscScalar> px, weight, pnormal;
  std::vector<PetscInt> ptopo, piface, psurface, ppart, pcell, ppoint;
  for (size_t ci = 0; ci < cells.size(); ++ci) {
    const CellRecord &c = cells[ci];
    for (size_t i = c.first; i < c.first + c.count; ++i) {
      const PointRecord &p = points[i];
      for (int d = 0; d < dim; ++d)
        px.push_back(p.x[d]);
      ptopo.push_back(point_at[i]);
      piface.push_back(p.iface);
      psurface.push_back(p.surface);
      ppart.push_back(this->part(p.iface, p.surface));
      pcell.push_back(cell_at[ci]);
      ppoint.push_back(p.point);
      weight.push_back(p.weight);
      for (int d = 0; d < 3; ++d)
        pnormal.push_back(p.normal[d]);
    }
  }
  PetscCall(point_order.permute(px, dim));
  for (std::vector<PetscInt> *v : {&ptopo, &piface, &psurface, &ppart, &pcell, &ppoint})
    PetscCall(point_order.permute(*v, 1));
  PetscCall(point_order.permute(weight, 1));
  PetscCall(point_order.permute(pnormal, 3));
  PetscCall(
      xdmf::writeReals(viewer, comm, "/points", "geometry", dim, px, units("geometry"), nullptr));
  PetscCall(xdmf::writeInts(viewer, comm, "/points", "topology", 1, ptopo, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/points", "interface", 1, piface, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/points", "surface", 1, psurface, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/points", "part", 1, ppart, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/points", "cell", 1, pcell, "1"));
  PetscCall(xdmf::writeInts(viewer, comm, "/points", "point", 1, ppoint, "1"));
  PetscCall(
      xdmf::writeReals(viewer, comm, "/points", "weight", 1, weight, units("weight"), nullptr));
  PetscCall(xdmf::writeReals(viewer, comm, "/points", "normal", 3, pnormal, "1", nullptr));
  // The names behind the indices, where a user looking at the ids finds them.
  for (const char *group : {"/cells", "/points"}) {
    PetscCall(
        xdmf::writeText(viewer, std::string(group) + "/interface", "names", interfaceNames()));
    PetscCall(xdmf::writeText(viewer, std::string(group) + "/part", "names", partNames()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceWriter::Impl::writeValues(const std::string &grid,
                                                  const std::vector<Values> &values, size_t step,
                                                  double time)
{
  const int t = dim - 1;
  const std::string s = std::to_string(step);
  const std::string base = "/" + grid + "/fields/";
  std::vector<PetscScalar> a;
  auto scalar = [&](double Values::*m) {
    a.clear();
    for (const Values &v : values)
      a.push_back(v.*m);
    return a;
  };
  auto vec = [&](const double *(*get)(const Values &), int n) {
    a.clear();
    for (const Values &v : values)
      a.insert(a.end(), get(v), get(v) + n);
    return a;
  };
  const OutputOrder &order = grid == "cells" ? cell_order : point_order;
  auto real = [&](const char *name, int bs, const std::vector<PetscScalar> &v) -> PetscErrorCode {
    std::vector<PetscScalar> rows(v);
    PetscFunctionBeginUser;
    PetscCall(order.permute(rows, bs));
    PetscCall(xdmf::writeReals(viewer, comm, base + name, s, bs, rows, units(name), &time));
    PetscFunctionReturn(0);
  };

  PetscFunctionBeginUser;
  PetscCall(real("gap_normal", 1, scalar(&Values::gap_normal)));
  PetscCall(real("opening", 1, scalar(&Values::opening)));
  PetscCall(real("slip", t, vec([](const Values &v) -> const double * { return v.slip; }, t)));
  PetscCall(real("slip_vector", 3,
                 vec([](const Values &v) -> const double * { return v.slip_vector; }, 3)));
  PetscCall(real("contact_pressure_effective", 1, scalar(&Values::pressure)));
  PetscCall(
      real("shear_stress", t, vec([](const Values &v) -> const double * { return v.shear; }, t)));
  PetscCall(real("shear_traction", 3,
                 vec([](const Values &v) -> const double * { return v.shear_traction; }, 3)));
  PetscCall(
      real("traction", 3, vec([](const Values &v) -> const double * { return v.traction; }, 3)));
  PetscCall(real("mobilised_friction", 1, scalar(&Values::mobilised)));
  std::vector<PetscInt> state;
  for (const Values &v : values)
    state.push_back(v.state);
  PetscCall(order.permute(state, 1));
  PetscCall(xdmf::writeInts(viewer, comm, base + "state", s, 1, state, units("state"), &time));
  if (flow) {
    PetscCall(real("interface_pressure", 1, scalar(&Values::p3)));
    PetscCall(real("aperture", 1, scalar(&Values::aperture)));
    PetscCall(real("aperture_rate", 1, scalar(&Values::aperture_rate)));
    PetscCall(real("longitudinal_flux", 3,
                   vec([](const Values &v) -> const double * { return v.longitudinal_flux; }, 3)));
    PetscCall(real("transversal_flux1", 1, scalar(&Values::transversal_flux1)));
    PetscCall(real("transversal_flux2", 1, scalar(&Values::transversal_flux2)));
  }
  if (grid == "points") {
    PetscCall(real("displacement_minus", 3,
                   vec([](const Values &v) -> const double * { return v.displacement_minus; }, 3)));
    PetscCall(real("displacement_plus", 3,
                   vec([](const Values &v) -> const double * { return v.displacement_plus; }, 3)));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceWriter::Impl::writeNodeDisplacements(const std::vector<CellRecord> &cells,
                                                             size_t step, double time)
{
  const std::string s = std::to_string(step);
  std::vector<PetscScalar> minus, plus;
  PetscFunctionBeginUser;
  for (const CellRecord &c : cells) {
    minus.insert(minus.end(), c.displacement_minus.begin(), c.displacement_minus.end());
    plus.insert(plus.end(), c.displacement_plus.begin(), c.displacement_plus.end());
  }
  PetscCall(node_order.permute(minus, 3));
  PetscCall(node_order.permute(plus, 3));
  PetscCall(xdmf::writeReals(viewer, comm, "/cells/fields/displacement_minus", s, 3, minus,
                             units("displacement_minus"), &time));
  PetscCall(xdmf::writeReals(viewer, comm, "/cells/fields/displacement_plus", s, 3, plus,
                             units("displacement_plus"), &time));
  PetscFunctionReturn(0);
}

std::vector<Attribute> InterfaceWriter::Impl::attributes(bool cells) const
{
  const int t = dim - 1;
  const std::string g = cells ? "/cells/" : "/points/";
  std::vector<Attribute> a;
  // Per time.
  a.push_back({"gap_normal", g + "fields/gap_normal", 1, false, true});
  a.push_back({"opening", g + "fields/opening", 1, false, true});
  a.push_back({"slip", g + "fields/slip", t, false, true});
  a.push_back({"slip_vector", g + "fields/slip_vector", 3, false, true});
  a.push_back(
      {"contact_pressure_effective", g + "fields/contact_pressure_effective", 1, false, true});
  a.push_back({"shear_stress", g + "fields/shear_stress", t, false, true});
  a.push_back({"shear_traction", g + "fields/shear_traction", 3, false, true});
  a.push_back({"traction", g + "fields/traction", 3, false, true});
  a.push_back({"mobilised_friction", g + "fields/mobilised_friction", 1, false, true});
  a.push_back({"state", g + "fields/state", 1, true, true});
  if (flow) {
    a.push_back({"interface_pressure", g + "fields/interface_pressure", 1, false, true});
    a.push_back({"aperture", g + "fields/aperture", 1, false, true});
    a.push_back({"aperture_rate", g + "fields/aperture_rate", 1, false, true});
    a.push_back({"longitudinal_flux", g + "fields/longitudinal_flux", 3, false, true});
    a.push_back({"transversal_flux1", g + "fields/transversal_flux1", 1, false, true});
    a.push_back({"transversal_flux2", g + "fields/transversal_flux2", 1, false, true});
  }
  // On the nodes: the faces' displacements, to warp the interface with the bulk.
  a.push_back({"displacement_minus", g + "fields/displacement_minus", 3, false, true, true});
  a.push_back({"displacement_plus", g + "fields/displacement_plus", 3, false, true, true});
  // Constant.
  a.push_back({"interface", g + "interface", 1, true, false});
  a.push_back({"surface", g + "surface", 1, true, false});
  a.push_back({"part", g + "part", 1, true, false});
  a.push_back({"normal", g + "normal", 3, false, false});
  if (cells) {
    a.push_back({"area", g + "area", 1, false, false});
  } else {
    a.push_back({"cell", g + "cell", 1, true, false});
    a.push_back({"point", g + "point", 1, true, false});
    a.push_back({"weight", g + "weight", 1, false, false});
  }
  return a;
}

PetscErrorCode InterfaceWriter::Impl::writeXdmf()
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (int grid = 0; grid < 2; ++grid) {
    std::ostringstream x;
    if (rank == 0) {
      const bool have = mesh_written && num_cells > 0;
      const std::string geomType = dim == 3 ? "XYZ" : "XY";
      x << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"3.0\">\n"
        << "  <Domain>\n";
      const bool cells = grid == 0;
      const std::string gname = cells ? "interface_cells" : "interface_points";
      const PetscInt n = cells ? num_cells : num_points;
      const std::string ns = std::to_string(n);
      x << "    <Grid Name=\"" << gname
        << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (size_t s = 0; have && s < times.size(); ++s) {
        x << "      <Grid Name=\"" << gname << "\" GridType=\"Uniform\">\n"
          << "        <Time Value=\"" << xdmf::formatDouble(times[s]) << "\" />\n";
        if (cells) {
          const bool mixed = min_nodes != max_nodes;
          const char *type = dim == 2         ? "Polyline"
                             : mixed          ? "Mixed"
                             : max_nodes == 3 ? "Triangle"
                                              : "Quadrilateral";
          x << "        <Topology TopologyType=\"" << type << "\" NumberOfElements=\"" << ns
            << "\"";
          if (!mixed) x << " NodesPerElement=\"" << max_nodes << "\"";
          x << ">\n          "
            << xdmf::dataItem(mixed ? std::to_string(mixed_length) + " 1"
                                    : ns + " " + std::to_string(max_nodes),
                              true, h5name, "/cells/topology")
            << "\n        </Topology>\n"
            << "        <Geometry GeometryType=\"" << geomType << "\">\n          "
            << xdmf::dataItem(std::to_string(num_nodes) + " " + std::to_string(dim), false, h5name,
                              "/cells/geometry")
            << "\n        </Geometry>\n";
        } else {
          x << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << ns
            << "\" NodesPerElement=\"1\">\n          "
            << xdmf::dataItem(ns + " 1", true, h5name, "/points/topology")
            << "\n        </Topology>\n"
            << "        <Geometry GeometryType=\"" << geomType << "\">\n          "
            << xdmf::dataItem(ns + " " + std::to_string(dim), false, h5name, "/points/geometry")
            << "\n        </Geometry>\n";
        }
        for (const Attribute &a : attributes(cells)) {
          const char *atype = a.components == 1   ? "Scalar"
                              : a.components == 3 ? "Vector"
                                                  : "Matrix";
          // Integers are [N, bs] even for bs = 1 (ISView).
          const std::string path = a.per_step ? a.path + "/" + std::to_string(s) : a.path;
          const std::string rows = a.node && cells ? std::to_string(num_nodes) : ns;
          const std::string dims =
              a.components == 1 && !a.integer ? rows : rows + " " + std::to_string(a.components);
          x << "        <Attribute Name=\"" << a.name << "\" AttributeType=\"" << atype
            << "\" Center=\"" << (cells && !a.node ? "Cell" : "Node") << "\">\n          "
            << xdmf::dataItem(dims, a.integer, h5name, path) << "\n        </Attribute>\n";
        }
        x << "      </Grid>\n";
      }
      x << "    </Grid>\n";
      x << "  </Domain>\n"
        << "</Xdmf>\n";
    }
    failed = true; // until the index is written: a close after this error writes nothing more
    PetscCall(xdmf::replaceFile(comm, xmfPath[grid], x.str(), kWho));
    failed = false;
  }
  PetscFunctionReturn(0);
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

PetscErrorCode InterfaceWriter::Impl::writeStep(const std::vector<CellRecord> &cells,
                                                const std::vector<PointRecord> &points, double time)
{
  Impl &im = *this;
  PetscFunctionBeginUser;
  if (im.num_cells > 0) {
    const int t = im.dim - 1;
    std::vector<Values> cv, pv;
    for (const CellRecord &c : cells)
      cv.push_back(cellValues(c, points, t));
    for (const PointRecord &p : points)
      pv.push_back(pointValues(p, t));
    const size_t step = im.times.size();
    PetscCall(im.writeValues("cells", cv, step, time));
    PetscCall(im.writeValues("points", pv, step, time));
    PetscCall(im.writeNodeDisplacements(cells, step, time));
    PetscCall(PetscViewerFlush(im.viewer));
  }
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
