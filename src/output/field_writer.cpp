// Bulk field output: HDF5 (through PETSc's HDF5 viewer) plus an XDMF index for ParaView.
//
// HDF5 layout of <dir>/<basename>.h5 (vertices and cells in the order of their point numbers
// in the serial mesh, serialPointNumbers: the same files on any number of ranks and any
// partition; the same order in the geometry and in every field):
//   /geometry/vertices              [Nv, cdim]  double   node coordinates (the vertices at
//                                               displacement order 1; output_mesh.hpp)
//   /topology/cells                 [Nc, nc]    PetscInt connectivity (0-based, XDMF order)
//   /fields/displacement/<step>     [Nv, 3]     double   (padded with zeros when dim < 3)
//   /fields/pressure/<step>         [Nv]        double   (only when the section has pressure;
//                                                        NaN at vertices without pressure)
//   /fields/excess_pressure/<step>  [Nv]        double   (pressure - steady pressure)
//   /fields/steady_pressure/<step>  [Nv]        double   (the steady pore pressure)
//   /cell_fields/region             [Nc, 1]     PetscInt region index; attribute "names"
//   /fields/recovered_effective_stress/<step>, /fields/recovered_total_stress/<step>
//                                   [Nv, 9]     double   stresses recovered at the nodes from
//                                                        the integration points (CellFields::
//                                                        vertex_fields, stress_recovery.hpp)
//   /cell_fields/<name>/<step>      [Nc, 9] or [Nc] double ([Nc, 1] PetscInt when integer):
//                                   the CellFields given to write()
// Every dataset carries a string attribute "units"; every field dataset an attribute "time".
// The XDMF file is rewritten by rank 0 after every write() (to a temporary file that is then
// renamed), so a crashed run still leaves a readable time series.
#include "poroseam/field_writer.hpp"

#include "output_mesh.hpp"
#include "xdmf.hpp"

#include "poroseam/mesh.hpp"
#include "poroseam/option_registry.hpp"

#include <petscdmplex.h>
#include <petscsf.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

namespace poroseam {

namespace {

PetscErrorCode findField(PetscSection section, const char *name, PetscInt *field)
{
  PetscInt nf;

  PetscFunctionBeginUser;
  *field = -1;
  PetscCall(PetscSectionGetNumFields(section, &nf));
  for (PetscInt f = 0; f < nf; ++f) {
    const char *fname = nullptr;
    PetscBool match = PETSC_FALSE;

    PetscCall(PetscSectionGetFieldName(section, f, &fname));
    if (fname) PetscCall(PetscStrcmp(fname, name, &match));
    if (match) {
      *field = f;
      break;
    }
  }
  PetscFunctionReturn(0);
}

} // namespace

struct FieldWriter::Impl {
  MPI_Comm comm = MPI_COMM_NULL;
  DM dm = nullptr;
  PetscViewer viewer = nullptr;
  std::string h5name; // file name relative to the XDMF file
  std::string h5Path;
  std::string dir;
  std::string xmfPath;
  bool failed = false;          // a write failed (agreed by every rank): close without writing more
  xdmf::Rendezvous closing;     // for a close from the destructor
  PetscInt test_fail_rank = -2; // -test_io_fail_rank: this rank's writes fail (-1: every rank)
  PetscInt dispField = -1;
  PetscInt presField = -1;
  PetscInt dispComp = 0;
  OutputMesh mesh; // nodes, coordinates, connectivity in the files' order
  std::vector<double> times;
  bool regions = false;             // /cell_fields/region written
  std::vector<CellField> cellNames; // name, units, components, integer of the cell fields
  std::vector<CellField> nodeNames; // the same of the vertex fields (CellFields::vertex_fields)

  /// index[k]: position in `cells` of ownedCells[k]; an error if some cell is missing.
  PetscErrorCode cellIndex(const std::vector<PetscInt> &cells, std::vector<size_t> &index) const;

  PetscErrorCode writeXdmf();
  /// The datasets of one write() (collective), flushed.
  PetscErrorCode writeStep(double time, const std::vector<PetscScalar> &disp,
                           const std::vector<PetscScalar> &pres,
                           const std::vector<PetscScalar> &excess,
                           const std::vector<PetscScalar> &steady, const CellFields *cells);
  PetscErrorCode writeVertexVec(const char *group, const std::string &name, PetscInt bs,
                                const std::vector<PetscScalar> &values, const char *units,
                                double time, bool withTime);
};

PetscErrorCode FieldWriter::Impl::writeVertexVec(const char *group, const std::string &name,
                                                 PetscInt bs,
                                                 const std::vector<PetscScalar> &values,
                                                 const char *units, double time, bool withTime)
{
  const PetscInt n = static_cast<PetscInt>(mesh.ownedNodes.size()) * bs;

  PetscFunctionBeginUser;
  PetscCheck(static_cast<PetscInt>(values.size()) == n, comm, PETSC_ERR_PLIB,
             "FieldWriter: wrong number of values for %s", name.c_str());
  std::vector<PetscScalar> rows(values);
  PetscCall(mesh.nodeOrder.permute(rows, bs));
  PetscCall(
      xdmf::writeReals(viewer, comm, group, name, bs, rows, units, withTime ? &time : nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::Impl::cellIndex(const std::vector<PetscInt> &cells,
                                            std::vector<size_t> &index) const
{
  PetscInt pStart, pEnd;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  std::vector<size_t> position(pEnd - pStart, std::numeric_limits<size_t>::max());
  for (size_t i = 0; i < cells.size(); ++i)
    if (cells[i] >= pStart && cells[i] < pEnd) position[cells[i] - pStart] = i;
  index.resize(mesh.ownedCells.size());
  for (size_t k = 0; k < mesh.ownedCells.size(); ++k) {
    index[k] = position[mesh.ownedCells[k] - pStart];
    PetscCheck(index[k] != std::numeric_limits<size_t>::max(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "FieldWriter: no cell value for cell %" PetscInt_FMT, mesh.ownedCells[k]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::Impl::writeXdmf()
{
  PetscMPIInt rank;
  std::ostringstream x;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const char *topo = mesh.topology;
    const PetscInt numCells = mesh.numCells, corners = mesh.nodesPerCell, cdim = mesh.cdim;
    const std::string intPrec = std::to_string(sizeof(PetscInt));
    const std::string nv = std::to_string(mesh.numNodes);

    auto topologyAndGeometry = [&](std::ostringstream &o) {
      o << "        <Topology TopologyType=\"" << topo << "\" NumberOfElements=\"" << numCells
        << "\" NodesPerElement=\"" << corners << "\">\n"
        << "          <DataItem Dimensions=\"" << numCells << " " << corners
        << "\" NumberType=\"Int\" Precision=\"" << intPrec << "\" Format=\"HDF\">" << h5name
        << ":/topology/cells</DataItem>\n"
        << "        </Topology>\n"
        << "        <Geometry GeometryType=\"" << (cdim == 3 ? "XYZ" : "XY") << "\">\n"
        << "          <DataItem Dimensions=\"" << nv << " " << cdim
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5name
        << ":/geometry/vertices</DataItem>\n"
        << "        </Geometry>\n";
    };
    auto attribute = [&](std::ostringstream &o, const char *name, bool vector, size_t step) {
      o << "        <Attribute Name=\"" << name << "\" AttributeType=\""
        << (vector ? "Vector" : "Scalar") << "\" Center=\"Node\">\n"
        << "          <DataItem Dimensions=\"" << nv << (vector ? " 3" : "")
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5name << ":/fields/"
        << name << "/" << step << "</DataItem>\n"
        << "        </Attribute>\n";
    };

    auto nodeTensor = [&](std::ostringstream &o, const CellField &f, size_t step) {
      o << "        <Attribute Name=\"" << f.name << "\" AttributeType=\""
        << (f.components == 9 ? "Tensor" : "Scalar") << "\" Center=\"Node\">\n"
        << "          <DataItem Dimensions=\"" << nv << " " << f.components
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5name << ":/fields/"
        << f.name << "/" << step << "</DataItem>\n"
        << "        </Attribute>\n";
    };
    const std::string nc = std::to_string(numCells);
    auto cellAttribute = [&](std::ostringstream &o, const CellField &f, const std::string &path) {
      const char *type = f.components == 9 ? "Tensor" : "Scalar";
      // Integers are [N, 1] (ISView); a scalar of doubles is [N].
      const std::string dims =
          f.integer || f.components > 1 ? nc + " " + std::to_string(f.components) : nc;
      o << "        <Attribute Name=\"" << f.name << "\" AttributeType=\"" << type
        << "\" Center=\"Cell\">\n          " << xdmf::dataItem(dims, f.integer, h5name, path)
        << "\n        </Attribute>\n";
    };

    x << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    if (times.empty()) {
      // No time written yet: the mesh alone, so that the file is still valid.
      x << "      <Grid Name=\"mesh\" GridType=\"Uniform\">\n";
      topologyAndGeometry(x);
      x << "      </Grid>\n";
    }
    for (size_t s = 0; s < times.size(); ++s) {
      x << "      <Grid Name=\"mesh\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << xdmf::formatDouble(times[s]) << "\" />\n";
      topologyAndGeometry(x);
      attribute(x, "displacement", true, s);
      if (presField >= 0) {
        attribute(x, "pressure", false, s);
        attribute(x, "excess_pressure", false, s);
        attribute(x, "steady_pressure", false, s);
      }
      if (regions) {
        CellField region;
        region.name = "region";
        region.integer = true;
        cellAttribute(x, region, "/cell_fields/region");
      }
      for (const CellField &f : nodeNames)
        nodeTensor(x, f, s);
      for (const CellField &f : cellNames)
        cellAttribute(x, f, "/cell_fields/" + f.name + "/" + std::to_string(s));
      x << "      </Grid>\n";
    }
    x << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  }
  failed = true; // until the index is written: a close after this error writes nothing more
  PetscCall(xdmf::replaceFile(comm, xmfPath, x.str(), "FieldWriter"));
  failed = false;
  PetscFunctionReturn(0);
}

FieldWriter::~FieldWriter()
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

std::vector<double> FieldWriter::times() const
{
  return impl_ ? impl_->times : std::vector<double>();
}

PetscErrorCode FieldWriter::open(DM solution_dm, const std::string &dir,
                                 const std::string &basename, const std::vector<double> *resume)
{
  MPI_Comm comm;
  PetscMPIInt rank;
  PetscSection section;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)solution_dm, &comm));
  PetscCheck(!impl_ || !impl_->viewer, comm, PETSC_ERR_ARG_WRONGSTATE,
             "FieldWriter::open called twice");
  PetscCheck(!basename.empty(), comm, PETSC_ERR_ARG_WRONG, "FieldWriter: empty basename");
  delete impl_;
  impl_ = new Impl;
  Impl &im = *impl_;
  im.comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));

  // Output directory (rank 0 creates it).
  PetscCall(xdmf::createDirectory(comm, dir, "FieldWriter"));
  const std::string prefix = dir.empty() ? basename : dir + "/" + basename;
  im.h5name = basename + ".h5";
  im.h5Path = prefix + ".h5";
  PetscCall(im.closing.init(comm));
  im.dir = dir;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, spec(Option::test_io_fail_rank).flag,
                               &im.test_fail_rank, nullptr));
  { // read where an error needs it (xdmf::agreeOn); here too, so that it is never "unused"
    PetscReal grace;
    PetscCall(xdmf::readAgreementTimeout(&grace));
  }
  im.xmfPath = prefix + ".xmf";

  PetscCall(PetscObjectReference((PetscObject)solution_dm));
  im.dm = solution_dm;
  {
    PetscInt cdim;
    PetscCall(DMGetCoordinateDim(im.dm, &cdim));
    PetscCheck(cdim == 2 || cdim == 3, comm, PETSC_ERR_SUP,
               "FieldWriter: coordinate dimension %" PetscInt_FMT " not supported", cdim);
  }

  // Fields of the local section.
  PetscCall(DMGetLocalSection(im.dm, &section));
  PetscCheck(section, comm, PETSC_ERR_ARG_WRONGSTATE, "FieldWriter: the DM has no local section");
  {
    PetscInt nf;
    PetscCall(PetscSectionGetNumFields(section, &nf));
    PetscCall(findField(section, "displacement", &im.dispField));
    PetscCall(findField(section, "pressure", &im.presField));
    if (im.dispField < 0 && nf > 0) im.dispField = 0;
    PetscCheck(im.dispField >= 0, comm, PETSC_ERR_ARG_WRONG,
               "FieldWriter: the section has no displacement field");
    PetscCall(PetscSectionGetFieldComponents(section, im.dispField, &im.dispComp));
    PetscCheck(im.dispComp >= 1 && im.dispComp <= 3, comm, PETSC_ERR_SUP,
               "FieldWriter: displacement has %" PetscInt_FMT " components", im.dispComp);
    if (im.presField >= 0) {
      PetscInt nc;
      PetscCall(PetscSectionGetFieldComponents(section, im.presField, &nc));
      PetscCheck(nc == 1, comm, PETSC_ERR_SUP,
                 "FieldWriter: pressure has %" PetscInt_FMT " components", nc);
    }
  }

  PetscCall(im.mesh.build(im.dm, im.dispField));
  const std::vector<PetscScalar> &xyz = im.mesh.coordinates;
  const std::vector<PetscInt> &cells = im.mesh.connectivity;

  // HDF5 file with geometry and topology.
  // A restarted run appends: PETSc's HDF5 viewer overwrites datasets that exist (the same
  // geometry and topology; field times after the checkpoint), so no stale time survives.
  if (resume) im.times = *resume;
  PetscCall(reserveSpace(comm, dir, im.h5Path, 8.0 * (xyz.size() + cells.size()), "the mesh"));
  PetscCall(xdmf::agreed(comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscViewerHDF5Open(comm, im.h5Path.c_str(),
                                  resume ? FILE_MODE_APPEND : FILE_MODE_WRITE, &im.viewer));
    PetscCall(im.writeVertexVec("/geometry", "vertices", im.mesh.cdim, xyz, "m", 0.0, false));
    PetscCall(
        xdmf::writeInts(im.viewer, comm, "/topology", "cells", im.mesh.nodesPerCell, cells, "1"));
    PetscCall(PetscViewerFlush(im.viewer));
    PetscFunctionReturn(0);
  }));
  PetscCall(im.writeXdmf());
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::write(double time, Vec local_solution, Vec local_initial,
                                  const CellFields *cells)
{
  PetscFunctionBeginUser;
  PetscCheck(impl_ && impl_->viewer, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
             "FieldWriter::write called before open or after close");
  Impl &im = *impl_;
  PetscSection section;
  PetscInt storage, n;
  const PetscScalar *sol, *init = nullptr;
  const size_t nv = im.mesh.ownedNodes.size();

  PetscCall(DMGetLocalSection(im.dm, &section));
  PetscCall(PetscSectionGetStorageSize(section, &storage));
  PetscCall(VecGetLocalSize(local_solution, &n));
  PetscCheck(n == storage, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "FieldWriter: local solution has size %" PetscInt_FMT ", local section %" PetscInt_FMT,
             n, storage);
  if (local_initial) {
    PetscCall(VecGetLocalSize(local_initial, &n));
    PetscCheck(n == storage, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
               "FieldWriter: local initial vector has size %" PetscInt_FMT
               ", local section %" PetscInt_FMT,
               n, storage);
  }

  std::vector<PetscScalar> disp(nv * 3, 0.0), pres, excess, steady;
  if (im.presField >= 0) {
    // A vertex without pressure belongs to non-porous regions only: no pore pressure there.
    pres.assign(nv, std::numeric_limits<double>::quiet_NaN());
    excess.assign(nv, std::numeric_limits<double>::quiet_NaN());
    steady.assign(nv, std::numeric_limits<double>::quiet_NaN());
  }
  PetscCall(VecGetArrayRead(local_solution, &sol));
  if (local_initial) PetscCall(VecGetArrayRead(local_initial, &init));
  for (size_t i = 0; i < nv; ++i) {
    const PetscInt node = im.mesh.ownedNodes[i];
    PetscInt dof, off;
    PetscCall(PetscSectionGetFieldDof(section, node, im.dispField, &dof));
    if (dof > 0) {
      PetscCall(PetscSectionGetFieldOffset(section, node, im.dispField, &off));
      for (PetscInt d = 0; d < PetscMin(dof, (PetscInt)3); ++d)
        disp[3 * i + d] = sol[off + d];
    }
    if (im.presField < 0) continue;
    // The pressure is linear at both orders: at a node that is not a vertex (order 2) it is
    // the mean over the node's corners, which is its value there; NaN when a corner has none.
    double p = 0.0, dp = 0.0, sp = 0.0;
    const double share = 1.0 / (double)im.mesh.nodeVertices[i].size();
    for (PetscInt v : im.mesh.nodeVertices[i]) {
      PetscCall(PetscSectionGetFieldDof(section, v, im.presField, &dof));
      if (dof == 0) {
        p = dp = sp = std::numeric_limits<double>::quiet_NaN();
        break;
      }
      PetscCall(PetscSectionGetFieldOffset(section, v, im.presField, &off));
      p += share * sol[off];
      dp += share * (init ? sol[off] - init[off] : sol[off]);
      sp += share * (init ? init[off] : 0.0);
    }
    pres[i] = p;
    excess[i] = dp;
    steady[i] = sp;
  }
  PetscCall(VecRestoreArrayRead(local_solution, &sol));
  if (local_initial) PetscCall(VecRestoreArrayRead(local_initial, &init));

  PetscCheck(!im.failed, im.comm, PETSC_ERR_ARG_WRONGSTATE, "FieldWriter::write after a failure");
  double bytes = 8.0 * (disp.size() + pres.size() + excess.size() + steady.size());
  if (cells) {
    for (const CellField &f : cells->fields)
      bytes += 8.0 * f.values.size();
    for (const CellField &f : cells->vertex_fields)
      bytes += 8.0 * f.components * im.mesh.ownedNodes.size();
  }
  {
    char what[64];
    std::snprintf(what, sizeof what, "the fields at t = %g s", time);
    PetscCall(reserveSpace(im.comm, im.dir, im.h5Path, bytes, what));
  }
  PetscCall(xdmf::agreed(im.comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscMPIInt rank;
    PetscFunctionBeginUser;
    PetscCallMPI(MPI_Comm_rank(im.comm, &rank));
    // Test hook standing in for a write refused on one rank (tests/input/io_faults.py).
    PetscCheck(im.test_fail_rank != rank && im.test_fail_rank != -1, PETSC_COMM_SELF,
               PETSC_ERR_FILE_WRITE, "write refused (test hook -test_io_fail_rank)");
    PetscCall(im.writeStep(time, disp, pres, excess, steady, cells));
    PetscFunctionReturn(0);
  }));
  im.times.push_back(time);
  PetscCall(im.writeXdmf());
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::Impl::writeStep(double time, const std::vector<PetscScalar> &disp,
                                            const std::vector<PetscScalar> &pres,
                                            const std::vector<PetscScalar> &excess,
                                            const std::vector<PetscScalar> &steady,
                                            const CellFields *cells)
{
  Impl &im = *this;
  PetscFunctionBeginUser;
  const std::string step = std::to_string(im.times.size());
  PetscCall(im.writeVertexVec("/fields/displacement", step, 3, disp, "m", time, true));
  if (im.presField >= 0) {
    PetscCall(im.writeVertexVec("/fields/pressure", step, 1, pres, "Pa", time, true));
    PetscCall(im.writeVertexVec("/fields/excess_pressure", step, 1, excess, "Pa", time, true));
    PetscCall(im.writeVertexVec("/fields/steady_pressure", step, 1, steady, "Pa", time, true));
  }
  if (cells && !cells->vertex_fields.empty()) {
    // At each node the mean over its corners (the vertex itself at a vertex): the recovered
    // fields are linear between vertices, at both displacement orders.
    PetscInt pStart, pEnd;
    PetscCall(DMPlexGetChart(im.dm, &pStart, &pEnd));
    std::vector<PetscInt> position(pEnd - pStart, -1);
    for (size_t k = 0; k < cells->vertices.size(); ++k)
      position[cells->vertices[k] - pStart] = (PetscInt)k;
    std::vector<CellField> names;
    for (const CellField &f : cells->vertex_fields) {
      const size_t nc = f.components;
      PetscCheck(f.values.size() == cells->vertices.size() * nc, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "FieldWriter: vertex field %s has %zu values for %zu vertices", f.name.c_str(),
                 f.values.size(), cells->vertices.size());
      std::vector<PetscScalar> v(im.mesh.ownedNodes.size() * nc, 0.0);
      for (size_t i = 0; i < im.mesh.ownedNodes.size(); ++i) {
        const std::vector<PetscInt> &corners = im.mesh.nodeVertices[i];
        for (PetscInt q : corners) {
          const PetscInt k = position[q - pStart];
          PetscCheck(k >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                     "FieldWriter: no value of %s at vertex %" PetscInt_FMT, f.name.c_str(), q);
          for (size_t c = 0; c < nc; ++c)
            v[i * nc + c] += f.values[k * nc + c] / (double)corners.size();
        }
      }
      PetscCall(im.writeVertexVec(("/fields/" + f.name).c_str(), step, f.components, v,
                                  f.units.c_str(), time, true));
      CellField name = f;
      name.values.clear();
      names.push_back(name);
    }
    im.nodeNames = names;
  }
  if (cells) {
    std::vector<size_t> index;
    PetscCall(im.cellIndex(cells->cells, index));
    std::vector<CellField> names;
    for (const CellField &f : cells->fields) {
      const size_t nc = f.components;
      PetscCheck(f.components >= 1 && f.values.size() == cells->cells.size() * nc, PETSC_COMM_SELF,
                 PETSC_ERR_PLIB, "FieldWriter: cell field %s has %zu values for %zu cells",
                 f.name.c_str(), f.values.size(), cells->cells.size());
      const std::string group = "/cell_fields/" + f.name;
      if (f.integer) {
        std::vector<PetscInt> v;
        v.reserve(index.size() * nc);
        for (size_t k : index)
          for (size_t j = 0; j < nc; ++j)
            v.push_back(static_cast<PetscInt>(f.values[k * nc + j]));
        PetscCall(im.mesh.cellOrder.permute(v, f.components));
        PetscCall(xdmf::writeInts(im.viewer, im.comm, group, step, f.components, v, f.units.c_str(),
                                  &time));
      } else {
        std::vector<PetscScalar> v;
        v.reserve(index.size() * nc);
        for (size_t k : index)
          for (size_t j = 0; j < nc; ++j)
            v.push_back(f.values[k * nc + j]);
        PetscCall(im.mesh.cellOrder.permute(v, f.components));
        PetscCall(xdmf::writeReals(im.viewer, im.comm, group, step, f.components, v,
                                   f.units.c_str(), &time));
      }
      CellField name = f;
      name.values.clear();
      names.push_back(name);
    }
    im.cellNames = names;
  }
  PetscCall(PetscViewerFlush(im.viewer));
  PetscFunctionReturn(0);
}

void FieldWriter::declareCellFields(const CellFields &cells)
{
  if (!impl_) return;
  impl_->cellNames.clear();
  impl_->nodeNames.clear();
  for (const CellField &f : cells.vertex_fields) {
    CellField name = f;
    name.values.clear();
    impl_->nodeNames.push_back(name);
  }
  for (const CellField &f : cells.fields) {
    CellField name = f;
    name.values.clear();
    impl_->cellNames.push_back(name);
  }
}

PetscErrorCode FieldWriter::writeRegions(const std::vector<PetscInt> &cells,
                                         const std::vector<int> &region,
                                         const std::vector<std::string> &names)
{
  PetscFunctionBeginUser;
  PetscCheck(impl_ && impl_->viewer, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
             "FieldWriter::writeRegions called before open or after close");
  Impl &im = *impl_;
  PetscCheck(cells.size() == region.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "FieldWriter::writeRegions: %zu cells, %zu regions", cells.size(), region.size());
  std::vector<size_t> index;
  PetscCall(im.cellIndex(cells, index));
  std::vector<PetscInt> ids;
  ids.reserve(index.size());
  for (size_t k : index)
    ids.push_back(region[k]);
  PetscCall(im.mesh.cellOrder.permute(ids, 1));
  std::string list;
  for (size_t r = 0; r < names.size(); ++r)
    list += (r ? "," : "") + names[r];
  PetscCheck(!im.failed, im.comm, PETSC_ERR_ARG_WRONGSTATE, "FieldWriter: write after a failure");
  PetscCall(
      reserveSpace(im.comm, im.dir, im.h5Path, 8.0 * ids.size() + list.size(), "the cell regions"));
  PetscCall(xdmf::agreed(im.comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(xdmf::writeInts(im.viewer, im.comm, "/cell_fields", "region", 1, ids, "1"));
    PetscCall(xdmf::writeText(im.viewer, "/cell_fields/region", "names", list));
    PetscCall(PetscViewerFlush(im.viewer));
    PetscFunctionReturn(0);
  }));
  im.regions = true;
  PetscCall(im.writeXdmf());
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::close()
{
  PetscFunctionBeginUser;
  if (!impl_ || !impl_->viewer) PetscFunctionReturn(0);
  Impl &im = *impl_;
  if (im.failed) { // the index names what the file holds; the error is on its way up
    PetscCall(PetscViewerDestroy(&im.viewer));
    PetscCall(DMDestroy(&im.dm));
    PetscCall(im.mesh.destroy());
    PetscFunctionReturn(0);
  }
  PetscCall(xdmf::agreed(im.comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscViewerDestroy(&im.viewer));
    PetscFunctionReturn(0);
  }));
  PetscCall(im.writeXdmf());
  PetscCall(DMDestroy(&im.dm));
  PetscCall(im.mesh.destroy());
  PetscFunctionReturn(0);
}

} // namespace poroseam
