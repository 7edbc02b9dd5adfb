// The HDF5 datasets of interfaces.h5 (layout: interface_writer.cpp): the cells' and points'
// mesh, written once, and the values of each write(), in the files' order whatever the
// partition. Apart from interface_writer.cpp (the writer's life) and interface_xdmf.cpp (the
// index that names these datasets for ParaView).
#include "interface_writer_impl.hpp"

#include "poroseam/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace poroseam {

using namespace interface_output;

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

} // namespace poroseam
