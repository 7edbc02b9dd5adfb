// Bulk field output: HDF5 (through PETSc's HDF5 viewer) plus an XDMF index for ParaView.
//
// HDF5 layout of <dir>/<basename>.h5 (vertices and cells in the order of their point numbers
// in the serial mesh, serialPointNumbers: the same files on any number of ranks and any
// partition; the same order in the geometry and in every field):
//   /geometry/vertices              [Nv, cdim]  double   vertex coordinates
//   /topology/cells                 [Nc, nc]    PetscInt connectivity (0-based, XDMF order)
//   /fields/displacement/<step>     [Nv, 3]     double   (padded with zeros when dim < 3)
//   /fields/pressure/<step>         [Nv]        double   (only when the section has pressure;
//                                                        NaN at vertices without pressure)
//   /fields/excess_pressure/<step>  [Nv]        double   (pressure - steady pressure)
//   /fields/steady_pressure/<step>  [Nv]        double   (the steady pore pressure)
//   /cell_fields/region             [Nc, 1]     PetscInt region index; attribute "names"
//   /cell_fields/<name>/<step>      [Nc, 9] or [Nc] double ([Nc, 1] PetscInt when integer):
//                                   the CellFields given to write()
// Every dataset carries a string attribute "units"; every field dataset an attribute "time".
// The XDMF file is rewritten by rank 0 after every write() (to a temporary file that is then
// renamed), so a crashed run still leaves a readable time series.
#include "poroseam/field_writer.hpp"

#include "output_order.hpp"
#include "xdmf.hpp"

#include "poroseam/mesh.hpp"

#include <petscdmplex.h>
#include <petscsf.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

namespace poroseam {

namespace {

// XDMF name and vertex count of a bulk cell type; nullptr for types that are not written.
const char *xdmfTopologyName(DMPolytopeType ct, PetscInt *corners)
{
  switch (ct) {
  case DM_POLYTOPE_TRIANGLE:
    *corners = 3;
    return "Triangle";
  case DM_POLYTOPE_QUADRILATERAL:
    *corners = 4;
    return "Quadrilateral";
  case DM_POLYTOPE_TETRAHEDRON:
    *corners = 4;
    return "Tetrahedron";
  case DM_POLYTOPE_HEXAHEDRON:
    *corners = 8;
    return "Hexahedron";
  default:
    *corners = 0;
    return nullptr;
  }
}

// Converts the vertices of a cell from DMPlex closure order to XDMF/VTK order (in place).
// DMPlex reference cells (DMPlexCreateReferenceCell): triangle and quadrilateral are
// counterclockwise (same as VTK); the tetrahedron (-1,-1,-1),(-1,1,-1),(1,-1,-1),(-1,-1,1) has
// negative VTK orientation (swap 0 and 1); the hexahedron lists the bottom face clockwise seen
// from above, (-1,-1,-1),(-1,1,-1),(1,1,-1),(1,-1,-1), then the top face counterclockwise
// (-1,-1,1),(1,-1,1),(1,1,1),(-1,1,1) (swap 1 and 3). This is DMPlexInvertCell().
void closureToXdmfOrder(DMPolytopeType ct, PetscInt *v)
{
  switch (ct) {
  case DM_POLYTOPE_TETRAHEDRON:
    std::swap(v[0], v[1]);
    break;
  case DM_POLYTOPE_HEXAHEDRON:
    std::swap(v[1], v[3]);
    break;
  default:
    break;
  }
}

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
  PetscInt dim = 0;             // topological dimension
  PetscInt cdim = 0;            // coordinate dimension
  DMPolytopeType cellType = DM_POLYTOPE_UNKNOWN;
  PetscInt corners = 0;
  PetscInt numCells = 0;    // global number of written cells
  PetscInt numVertices = 0; // global number of written vertices
  PetscInt dispField = -1;
  PetscInt presField = -1;
  PetscInt dispComp = 0;
  std::vector<PetscInt> ownedVertices; // local vertex points, in global output order
  std::vector<PetscInt> ownedCells;    // local cell points, in global output order
  OutputOrder vertexOrder, cellOrder;  // from this rank's order to the files' (output_order.hpp)
  std::vector<double> times;
  bool regions = false;             // /cell_fields/region written
  std::vector<CellField> cellNames; // name, units, components, integer of the cell fields

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
  const PetscInt n = static_cast<PetscInt>(ownedVertices.size()) * bs;

  PetscFunctionBeginUser;
  PetscCheck(static_cast<PetscInt>(values.size()) == n, comm, PETSC_ERR_PLIB,
             "FieldWriter: wrong number of values for %s", name.c_str());
  std::vector<PetscScalar> rows(values);
  PetscCall(vertexOrder.permute(rows, bs));
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
  index.resize(ownedCells.size());
  for (size_t k = 0; k < ownedCells.size(); ++k) {
    index[k] = position[ownedCells[k] - pStart];
    PetscCheck(index[k] != std::numeric_limits<size_t>::max(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "FieldWriter: no cell value for cell %" PetscInt_FMT, ownedCells[k]);
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
    PetscInt dummy;
    const char *topo = xdmfTopologyName(cellType, &dummy);
    const std::string intPrec = std::to_string(sizeof(PetscInt));
    const std::string nv = std::to_string(numVertices);

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
  PetscInt pStart, pEnd, vStart, vEnd, cStart, cEnd, cellHeight;

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
  PetscCall(
      PetscOptionsGetInt(nullptr, nullptr, "-test_io_fail_rank", &im.test_fail_rank, nullptr));
  { // read where an error needs it (xdmf::agreeOn); here too, so that it is never "unused"
    PetscReal grace;
    PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-io_agreement_timeout", &grace, nullptr));
  }
  im.xmfPath = prefix + ".xmf";

  PetscCall(PetscObjectReference((PetscObject)solution_dm));
  im.dm = solution_dm;
  PetscCall(DMGetDimension(im.dm, &im.dim));
  PetscCall(DMGetCoordinateDim(im.dm, &im.cdim));
  PetscCheck(im.cdim == 2 || im.cdim == 3, comm, PETSC_ERR_SUP,
             "FieldWriter: coordinate dimension %" PetscInt_FMT " not supported", im.cdim);

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

  // Ownership of points from the point SF: a point is owned unless it is a leaf.
  PetscCall(DMPlexGetChart(im.dm, &pStart, &pEnd));
  PetscCheck(pStart == 0, comm, PETSC_ERR_SUP, "FieldWriter: chart must start at 0");
  std::vector<char> owned(pEnd, 1);
  PetscSF sf;
  {
    PetscInt nroots, nleaves;
    const PetscInt *ilocal;
    PetscCall(DMGetPointSF(im.dm, &sf));
    PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &ilocal, nullptr));
    if (nroots >= 0)
      for (PetscInt l = 0; l < nleaves; ++l)
        owned[ilocal ? ilocal[l] : l] = 0;
  }

  // Global vertex numbers: the position of each vertex in the files, by its serial point number
  // (owned vertices; ghosts get theirs via the SF).
  PetscCall(DMPlexGetDepthStratum(im.dm, 0, &vStart, &vEnd));
  std::vector<PetscInt> serial;
  PetscCall(serialPointNumbers(im.dm, serial));
  std::vector<PetscInt> gnum(pEnd, -1);
  PetscInt nOwned = 0;
  std::vector<PetscInt> keys;
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (owned[v]) {
      ++nOwned;
      im.ownedVertices.push_back(v);
      keys.push_back(serial[v]);
    }
  PetscCall(MPIU_Allreduce(&nOwned, &im.numVertices, 1, MPIU_INT, MPI_SUM, comm));
  {
    std::vector<PetscInt> position;
    PetscCall(positionsByKey(comm, keys, std::vector<PetscInt>(keys.size(), 1), position));
    for (size_t i = 0; i < im.ownedVertices.size(); ++i)
      gnum[im.ownedVertices[i]] = position[i];
    PetscCall(im.vertexOrder.setup(comm, position));
  }
  {
    std::vector<PetscInt> leafNum(gnum);
    PetscCall(PetscSFBcastBegin(sf, MPIU_INT, gnum.data(), leafNum.data(), MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(sf, MPIU_INT, gnum.data(), leafNum.data(), MPI_REPLACE));
    gnum.swap(leafNum);
  }

  // Bulk cells owned by this rank; a single cell type over the whole mesh.
  PetscCall(DMPlexGetVTKCellHeight(im.dm, &cellHeight));
  PetscCall(DMPlexGetHeightStratum(im.dm, cellHeight, &cStart, &cEnd));
  std::vector<PetscInt> cells;
  PetscInt typeMin = PETSC_MAX_INT, typeMax = -1, nCellsLocal = 0;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscInt nc;
    PetscCall(DMPlexGetCellType(im.dm, c, &ct));
    if (!owned[c] || !xdmfTopologyName(ct, &nc)) continue;
    typeMin = PetscMin(typeMin, (PetscInt)ct);
    typeMax = PetscMax(typeMax, (PetscInt)ct);
  }
  {
    PetscInt in[2] = {-typeMin, typeMax}, out[2];
    PetscCall(MPIU_Allreduce(in, out, 2, MPIU_INT, MPI_MAX, comm));
    typeMin = -out[0];
    typeMax = out[1];
  }
  PetscCheck(typeMax >= 0, comm, PETSC_ERR_ARG_WRONG,
             "FieldWriter: the mesh has no bulk cells (triangle, quadrilateral, tetrahedron, "
             "hexahedron)");
  PetscCheck(typeMin == typeMax, comm, PETSC_ERR_SUP,
             "FieldWriter: mixed bulk cell types (%s and %s) are not supported; one bulk cell "
             "type per mesh",
             DMPolytopeTypes[typeMin], DMPolytopeTypes[typeMax]);
  im.cellType = (DMPolytopeType)typeMax;
  (void)xdmfTopologyName(im.cellType, &im.corners);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscInt *closure = nullptr, closureSize, nv = 0;
    PetscCall(DMPlexGetCellType(im.dm, c, &ct));
    if (!owned[c] || ct != im.cellType) continue;
    PetscCall(DMPlexGetTransitiveClosure(im.dm, c, PETSC_TRUE, &closureSize, &closure));
    PetscInt verts[8];
    for (PetscInt p = 0; p < 2 * closureSize; p += 2) {
      const PetscInt q = closure[p];
      if (q >= vStart && q < vEnd && nv < 8) verts[nv++] = q;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(im.dm, c, PETSC_TRUE, &closureSize, &closure));
    PetscCheck(nv == im.corners, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "FieldWriter: cell %" PetscInt_FMT " has %" PetscInt_FMT
               " vertices in its closure, expected %" PetscInt_FMT,
               c, nv, im.corners);
    closureToXdmfOrder(im.cellType, verts);
    for (PetscInt i = 0; i < nv; ++i) {
      PetscCheck(gnum[verts[i]] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "FieldWriter: vertex %" PetscInt_FMT " has no global number", verts[i]);
      cells.push_back(gnum[verts[i]]);
    }
    im.ownedCells.push_back(c);
    ++nCellsLocal;
  }
  PetscCall(MPIU_Allreduce(&nCellsLocal, &im.numCells, 1, MPIU_INT, MPI_SUM, comm));
  {
    std::vector<PetscInt> cellKeys, position;
    for (PetscInt c : im.ownedCells)
      cellKeys.push_back(serial[c]);
    PetscCall(positionsByKey(comm, cellKeys, std::vector<PetscInt>(cellKeys.size(), 1), position));
    PetscCall(im.cellOrder.setup(comm, position));
  }
  PetscCall(im.cellOrder.permute(cells, im.corners));

  // Coordinates of the owned vertices.
  std::vector<PetscScalar> xyz(im.ownedVertices.size() * im.cdim, 0.0);
  {
    Vec coords;
    PetscSection csec;
    const PetscScalar *ca;
    PetscCall(DMGetCoordinatesLocal(im.dm, &coords));
    PetscCall(DMGetCoordinateSection(im.dm, &csec));
    PetscCall(VecGetArrayRead(coords, &ca));
    for (size_t i = 0; i < im.ownedVertices.size(); ++i) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetDof(csec, im.ownedVertices[i], &dof));
      PetscCall(PetscSectionGetOffset(csec, im.ownedVertices[i], &off));
      PetscCheck(dof == im.cdim, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "FieldWriter: vertex %" PetscInt_FMT " has %" PetscInt_FMT " coordinates",
                 im.ownedVertices[i], dof);
      for (PetscInt d = 0; d < im.cdim; ++d)
        xyz[i * im.cdim + d] = ca[off + d];
    }
    PetscCall(VecRestoreArrayRead(coords, &ca));
  }

  // HDF5 file with geometry and topology.
  // A restarted run appends: PETSc's HDF5 viewer overwrites datasets that exist (the same
  // geometry and topology; field times after the checkpoint), so no stale time survives.
  if (resume) im.times = *resume;
  PetscCall(reserveSpace(comm, dir, im.h5Path, 8.0 * (xyz.size() + cells.size()), "the mesh"));
  PetscCall(xdmf::agreed(comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscViewerHDF5Open(comm, im.h5Path.c_str(),
                                  resume ? FILE_MODE_APPEND : FILE_MODE_WRITE, &im.viewer));
    PetscCall(im.writeVertexVec("/geometry", "vertices", im.cdim, xyz, "m", 0.0, false));
    PetscCall(xdmf::writeInts(im.viewer, comm, "/topology", "cells", im.corners, cells, "1"));
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
  const size_t nv = im.ownedVertices.size();

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
    const PetscInt v = im.ownedVertices[i];
    PetscInt dof, off;
    PetscCall(PetscSectionGetFieldDof(section, v, im.dispField, &dof));
    if (dof > 0) {
      PetscCall(PetscSectionGetFieldOffset(section, v, im.dispField, &off));
      for (PetscInt d = 0; d < PetscMin(dof, (PetscInt)3); ++d)
        disp[3 * i + d] = sol[off + d];
    }
    if (im.presField >= 0) {
      PetscCall(PetscSectionGetFieldDof(section, v, im.presField, &dof));
      if (dof > 0) {
        PetscCall(PetscSectionGetFieldOffset(section, v, im.presField, &off));
        pres[i] = sol[off];
        excess[i] = init ? sol[off] - init[off] : sol[off];
        steady[i] = init ? init[off] : 0.0;
      }
    }
  }
  PetscCall(VecRestoreArrayRead(local_solution, &sol));
  if (local_initial) PetscCall(VecRestoreArrayRead(local_initial, &init));

  PetscCheck(!im.failed, im.comm, PETSC_ERR_ARG_WRONGSTATE, "FieldWriter::write after a failure");
  double bytes = 8.0 * (disp.size() + pres.size() + excess.size() + steady.size());
  if (cells)
    for (const CellField &f : cells->fields)
      bytes += 8.0 * f.values.size();
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
        PetscCall(im.cellOrder.permute(v, f.components));
        PetscCall(xdmf::writeInts(im.viewer, im.comm, group, step, f.components, v, f.units.c_str(),
                                  &time));
      } else {
        std::vector<PetscScalar> v;
        v.reserve(index.size() * nc);
        for (size_t k : index)
          for (size_t j = 0; j < nc; ++j)
            v.push_back(f.values[k * nc + j]);
        PetscCall(im.cellOrder.permute(v, f.components));
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
  PetscCall(im.cellOrder.permute(ids, 1));
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
    PetscCall(im.vertexOrder.destroy());
    PetscCall(im.cellOrder.destroy());
    PetscFunctionReturn(0);
  }
  PetscCall(xdmf::agreed(im.comm, im.h5Path, &im.failed, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscViewerDestroy(&im.viewer));
    PetscFunctionReturn(0);
  }));
  PetscCall(im.writeXdmf());
  PetscCall(DMDestroy(&im.dm));
  PetscCall(im.vertexOrder.destroy());
  PetscCall(im.cellOrder.destroy());
  PetscFunctionReturn(0);
}

} // namespace poroseam
