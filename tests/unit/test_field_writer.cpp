// FieldWriter: writes box meshes (quads, hexes, triangles, tetrahedra, and quads with cohesive
// cells) with known vertex fields, reads the HDF5 file back and checks values and orientation.
#include "poroseam/field_writer.hpp"

#include <gtest/gtest.h>
#include <petscdmplex.h>
#include <petscviewerhdf5.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

constexpr double kPressureXMax = 0.5 + 1e-10; // pressure dofs only on vertices with x <= 0.5
constexpr double kInitialPressure = 1.0;

// Field values written at step s (scale = s + 1): u = scale (x, 2y, 3z), p = 10 scale x.
double dispValue(const double *x, PetscInt cdim, PetscInt d, int step)
{
  return d < cdim ? (step + 1.0) * (d + 1.0) * x[d] : 0.0;
}
double presValue(const double *x, int step)
{
  return (step + 1.0) * 10.0 * x[0];
}

// Distributes dm (replacing it) over the communicator with the given overlap.
PetscErrorCode distribute(DM *dm, PetscInt overlap)
{
  DM dist = nullptr;
  PetscPartitioner part;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetPartitioner(*dm, &part));
  PetscCall(PetscPartitionerSetFromOptions(part));
  PetscCall(DMPlexDistribute(*dm, overlap, nullptr, &dist));
  if (dist) {
    PetscCall(DMDestroy(dm));
    *dm = dist;
  }
  PetscFunctionReturn(0);
}

// Section with "displacement" (dim comps on every vertex) and "pressure" (1 comp on vertices
// with x <= 0.5). Vertices with x == 0 have their displacement constrained, vertices with
// y == 0 and pressure have their pressure constrained.
PetscErrorCode setSection(DM dm)
{
  PetscSection s;
  PetscInt dim, cdim, pStart, pEnd, vStart, vEnd;
  Vec coords;
  PetscSection csec;
  const PetscScalar *ca;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(VecGetArrayRead(coords, &ca));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, 2));
  PetscCall(PetscSectionSetFieldName(s, 0, "displacement"));
  PetscCall(PetscSectionSetFieldName(s, 1, "pressure"));
  PetscCall(PetscSectionSetFieldComponents(s, 0, dim));
  PetscCall(PetscSectionSetFieldComponents(s, 1, 1));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  auto xOf = [&](PetscInt v, PetscInt d) -> PetscReal {
    PetscInt off;
    PetscSectionGetOffset(csec, v, &off);
    return PetscRealPart(ca[off + d]);
  };
  for (PetscInt v = vStart; v < vEnd; ++v) {
    const bool hasP = xOf(v, 0) <= kPressureXMax;
    PetscInt nc = 0;
    PetscCall(PetscSectionSetFieldDof(s, v, 0, dim));
    PetscCall(PetscSectionSetFieldDof(s, v, 1, hasP ? 1 : 0));
    PetscCall(PetscSectionSetDof(s, v, dim + (hasP ? 1 : 0)));
    if (std::abs(xOf(v, 0)) < 1e-12) {
      PetscCall(PetscSectionSetFieldConstraintDof(s, v, 0, dim));
      nc += dim;
    }
    if (hasP && std::abs(xOf(v, 1)) < 1e-12) {
      PetscCall(PetscSectionSetFieldConstraintDof(s, v, 1, 1));
      nc += 1;
    }
    if (nc) PetscCall(PetscSectionSetConstraintDof(s, v, nc));
  }
  PetscCall(PetscSectionSetUp(s));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt nc, idx[4], fidx[3] = {0, 1, 2}, zero = 0, n = 0;
    PetscCall(PetscSectionGetConstraintDof(s, v, &nc));
    if (!nc) continue;
    PetscInt fc;
    PetscCall(PetscSectionGetFieldConstraintDof(s, v, 0, &fc));
    if (fc) {
      PetscCall(PetscSectionSetFieldConstraintIndices(s, v, 0, fidx));
      for (PetscInt d = 0; d < dim; ++d)
        idx[n++] = d;
    }
    PetscCall(PetscSectionGetFieldConstraintDof(s, v, 1, &fc));
    if (fc) {
      PetscCall(PetscSectionSetFieldConstraintIndices(s, v, 1, &zero));
      idx[n++] = dim;
    }
    PetscCall(PetscSectionSetConstraintIndices(s, v, idx));
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(DMSetLocalSection(dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(0);
}

// Local vector with the known fields at the given step; `initial` gives p = kInitialPressure.
PetscErrorCode fillLocal(DM dm, int step, bool initial, Vec *local)
{
  PetscSection s, csec;
  PetscInt cdim, vStart, vEnd, nf;
  Vec coords;
  const PetscScalar *ca;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(DMCreateLocalVector(dm, local));
  PetscCall(VecSet(*local, -999.0));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(PetscSectionGetNumFields(s, &nf));
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(VecGetArrayRead(coords, &ca));
  PetscCall(VecGetArray(*local, &a));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt coff, dof, off;
    double x[3] = {0, 0, 0};
    PetscCall(PetscSectionGetOffset(csec, v, &coff));
    for (PetscInt d = 0; d < cdim; ++d)
      x[d] = PetscRealPart(ca[coff + d]);
    PetscCall(PetscSectionGetFieldDof(s, v, 0, &dof));
    PetscCall(PetscSectionGetFieldOffset(s, v, 0, &off));
    for (PetscInt d = 0; d < dof; ++d)
      a[off + d] = initial ? 0.0 : dispValue(x, cdim, d, step);
    if (nf < 2) continue;
    PetscCall(PetscSectionGetFieldDof(s, v, 1, &dof));
    if (dof) {
      PetscCall(PetscSectionGetFieldOffset(s, v, 1, &off));
      a[off] = initial ? kInitialPressure : presValue(x, step);
    }
  }
  PetscCall(VecRestoreArray(*local, &a));
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscFunctionReturn(0);
}

// One dataset read back on this rank alone.
struct Dataset {
  std::vector<double> values;
  PetscInt rows = 0, cols = 0;
};

PetscErrorCode readVec(PetscViewer viewer, const char *group, const char *name, Dataset *out)
{
  Vec v;
  PetscInt n, bs;
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(PETSC_COMM_SELF, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group));
  PetscCall(VecLoad(v, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCall(VecGetSize(v, &n));
  PetscCall(VecGetBlockSize(v, &bs));
  PetscCall(VecGetArrayRead(v, &a));
  out->values.assign(a, a + n);
  PetscCall(VecRestoreArrayRead(v, &a));
  out->cols = bs;
  out->rows = n / bs;
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode readCells(PetscViewer viewer, std::vector<PetscInt> *cells, PetscInt *corners)
{
  IS is;
  PetscInt n;
  const PetscInt *idx;

  PetscFunctionBeginUser;
  PetscCall(ISCreate(PETSC_COMM_SELF, &is));
  PetscCall(ISSetType(is, ISGENERAL));
  PetscCall(PetscObjectSetName((PetscObject)is, "cells"));
  PetscCall(PetscViewerHDF5PushGroup(viewer, "/topology"));
  PetscCall(ISLoad(is, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetBlockSize(is, corners));
  PetscCall(ISGetIndices(is, &idx));
  cells->assign(idx, idx + n);
  PetscCall(ISRestoreIndices(is, &idx));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

struct Output {
  Dataset xyz;
  std::vector<PetscInt> cells;
  PetscInt corners = 0;
  Dataset disp[2], pres[2], excess[2];
  Dataset tensor[2];            // the cell field "tensor" (9 values per cell)
  std::vector<PetscInt> region; // /cell_fields/region
  double time[2] = {0, 0};
};

// Cell field values written at step s, from the cell's centroid c: component k of "tensor" is
// (s + 1) (k + 1) + 10 c_x + 100 c_y + 1000 c_z; the region is 1 right of x = 0.5, else 0.
double cellValue(const double *c, int k, int step)
{
  return (step + 1.0) * (k + 1.0) + 10.0 * c[0] + 100.0 * c[1] + 1000.0 * c[2];
}
int cellRegion(const double *c)
{
  return c[0] > 0.5 ? 1 : 0;
}

// Centroid (vertex mean) of every local bulk cell, the cells in chart order.
PetscErrorCode bulkCellCentroids(DM dm, std::vector<PetscInt> *cells, std::vector<double> *centroid)
{
  PetscInt cStart, cEnd, cdim;
  Vec coords;
  PetscSection csec;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (ct != DM_POLYTOPE_TRIANGLE && ct != DM_POLYTOPE_QUADRILATERAL &&
        ct != DM_POLYTOPE_TETRAHEDRON && ct != DM_POLYTOPE_HEXAHEDRON)
      continue;
    PetscScalar *x = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, csec, coords, c, &n, &x));
    double m[3] = {0, 0, 0};
    for (PetscInt i = 0; i < n; ++i)
      m[i % cdim] += x[i] / (double)(n / cdim);
    PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, c, &n, &x));
    cells->push_back(c);
    centroid->insert(centroid->end(), m, m + 3);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readOutput(const std::string &file, Output *o)
{
  PetscViewer viewer;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(PETSC_COMM_SELF, file.c_str(), FILE_MODE_READ, &viewer));
  PetscCall(readVec(viewer, "/geometry", "vertices", &o->xyz));
  PetscCall(readCells(viewer, &o->cells, &o->corners));
  for (int s = 0; s < 2; ++s) {
    const std::string step = std::to_string(s);
    const std::string path = "/fields/displacement/" + step;
    PetscReal t;
    PetscCall(readVec(viewer, "/fields/displacement", step.c_str(), &o->disp[s]));
    PetscCall(readVec(viewer, "/fields/pressure", step.c_str(), &o->pres[s]));
    PetscCall(readVec(viewer, "/fields/excess_pressure", step.c_str(), &o->excess[s]));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, path.c_str(), "time", PETSC_REAL, nullptr, &t));
    o->time[s] = t;
    PetscCall(readVec(viewer, "/cell_fields/tensor", step.c_str(), &o->tensor[s]));
  }
  {
    IS is;
    PetscInt n;
    const PetscInt *idx;
    PetscCall(ISCreate(PETSC_COMM_SELF, &is));
    PetscCall(ISSetType(is, ISGENERAL));
    PetscCall(PetscObjectSetName((PetscObject)is, "region"));
    PetscCall(PetscViewerHDF5PushGroup(viewer, "/cell_fields"));
    PetscCall(ISLoad(is, viewer));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &idx));
    o->region.assign(idx, idx + n);
    PetscCall(ISRestoreIndices(is, &idx));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

// Output directory shared by all ranks (created by rank 0, name broadcast).
std::string makeTempDir(const std::string &tag)
{
  char buf[4096] = {0};
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    std::string templ =
        (std::filesystem::temp_directory_path() / ("poroseam_fw_" + tag + "_XXXXXX")).string();
    std::vector<char> t(templ.begin(), templ.end());
    t.push_back('\0');
    if (mkdtemp(t.data())) std::snprintf(buf, sizeof(buf), "%s", t.data());
  }
  MPI_Bcast(buf, sizeof(buf), MPI_CHAR, 0, PETSC_COMM_WORLD);
  return buf;
}

double triple(const double *a, const double *b, const double *c, const double *o)
{
  const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
  const double v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
  const double w[3] = {c[0] - o[0], c[1] - o[1], c[2] - o[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// Signed measure of a cell in XDMF vertex order (area in 2D, volume in 3D).
double signedMeasure(const std::vector<std::array<double, 3>> &x, PetscInt corners, PetscInt dim)
{
  if (dim == 2) { // shoelace
    double a = 0;
    for (PetscInt i = 0; i < corners; ++i) {
      const auto &p = x[i], &q = x[(i + 1) % corners];
      a += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * a;
  }
  if (corners == 4) return triple(x[1].data(), x[2].data(), x[3].data(), x[0].data()) / 6.0;
  // Hexahedron: six tetrahedra around the diagonal 0-6.
  static const int tets[6][3] = {{1, 2, 6}, {2, 3, 6}, {3, 7, 6}, {7, 4, 6}, {4, 5, 6}, {5, 1, 6}};
  double vol = 0;
  for (const auto &t : tets)
    vol += triple(x[t[0]].data(), x[t[1]].data(), x[t[2]].data(), x[0].data()) / 6.0;
  return vol;
}

// Checks that PETSc sees positive Jacobians in its own convention (the mesh is valid input).
PetscErrorCode minDetJ(DM dm, double *minDet)
{
  PetscInt cStart, cEnd;
  double local = 1e300;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscReal v0[3], J[9], invJ[9], detJ;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (ct != DM_POLYTOPE_TRIANGLE && ct != DM_POLYTOPE_QUADRILATERAL &&
        ct != DM_POLYTOPE_TETRAHEDRON && ct != DM_POLYTOPE_HEXAHEDRON)
      continue;
    PetscCall(DMPlexComputeCellGeometryFEM(dm, c, nullptr, v0, J, invJ, &detJ));
    local = std::min(local, (double)detJ);
  }
  PetscCall(
      MPIU_Allreduce(&local, minDet, 1, MPI_DOUBLE, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode writeTwoSteps(DM dm, const std::string &dir)
{
  poroseam::FieldWriter writer;
  Vec sol0, sol1, init;

  PetscFunctionBeginUser;
  PetscCall(fillLocal(dm, 0, false, &sol0));
  PetscCall(fillLocal(dm, 1, false, &sol1));
  PetscCall(fillLocal(dm, 0, true, &init));
  PetscCall(writer.open(dm, dir, "fields"));
  // Cell fields as Problem hands them: every local bulk cell (ghosts too), in chart order.
  std::vector<PetscInt> cells;
  std::vector<double> centroid;
  PetscCall(bulkCellCentroids(dm, &cells, &centroid));
  std::vector<int> region;
  for (size_t i = 0; i < cells.size(); ++i)
    region.push_back(cellRegion(&centroid[3 * i]));
  PetscCall(writer.writeRegions(cells, region, {"left", "right"}));
  poroseam::CellFields f[2];
  for (int s = 0; s < 2; ++s) {
    f[s].cells = cells;
    f[s].fields.resize(1);
    f[s].fields[0].name = "tensor";
    f[s].fields[0].units = "Pa";
    f[s].fields[0].components = 9;
    for (size_t i = 0; i < cells.size(); ++i)
      for (int k = 0; k < 9; ++k)
        f[s].fields[0].values.push_back(cellValue(&centroid[3 * i], k, s));
  }
  PetscCall(writer.write(0.25, sol0, init, &f[0]));
  PetscCall(writer.write(1.5, sol1, nullptr, &f[1]));
  PetscCall(writer.close());
  PetscCall(writer.close()); // idempotent
  PetscCall(VecDestroy(&sol0));
  PetscCall(VecDestroy(&sol1));
  PetscCall(VecDestroy(&init));
  PetscFunctionReturn(0);
}

// Writes dm, reads back, checks everything. `cellMeasure` is the exact measure of each cell.
void checkMesh(DM dm, const std::string &tag, PetscInt expectVertices, PetscInt expectCells,
               PetscInt expectCorners, double cellMeasure, bool uniqueCoordinates)
{
  PetscInt dim, cdim;
  double det;
  ASSERT_EQ(DMGetDimension(dm, &dim), 0);
  ASSERT_EQ(DMGetCoordinateDim(dm, &cdim), 0);
  ASSERT_EQ(minDetJ(dm, &det), 0);
  ASSERT_GT(det, 0.0) << "test mesh is not in PETSc's orientation convention";
  {
    PetscMPIInt size;
    PetscInt cStart, cEnd;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    ASSERT_EQ(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd), 0);
    if (size > 1) {
      EXPECT_GT(cEnd - cStart, 0) << "the mesh is not distributed over all ranks";
    }
  }
  ASSERT_EQ(setSection(dm), 0);

  const std::string dir = makeTempDir(tag);
  ASSERT_FALSE(dir.empty());
  ASSERT_EQ(writeTwoSteps(dm, dir), 0);

  Output o;
  ASSERT_EQ(readOutput(dir + "/fields.h5", &o), 0);
  const PetscInt nv = o.xyz.rows;
  EXPECT_EQ(o.xyz.cols, cdim);
  EXPECT_EQ(nv, expectVertices);
  ASSERT_EQ(o.corners, expectCorners);
  EXPECT_EQ((PetscInt)o.cells.size(), expectCells * expectCorners);
  EXPECT_DOUBLE_EQ(o.time[0], 0.25);
  EXPECT_DOUBLE_EQ(o.time[1], 1.5);

  // Coordinates: every vertex once.
  if (uniqueCoordinates) {
    std::map<std::array<long, 3>, int> seen;
    for (PetscInt i = 0; i < nv; ++i) {
      std::array<long, 3> key{0, 0, 0};
      for (PetscInt d = 0; d < cdim; ++d)
        key[d] = std::lround(o.xyz.values[i * cdim + d] * 1e6);
      EXPECT_EQ(seen[key]++, 0) << "duplicate vertex " << i;
    }
  }

  // Field values against the functions of the written coordinates.
  int bad = 0;
  for (int s = 0; s < 2; ++s) {
    ASSERT_EQ(o.disp[s].rows, nv);
    ASSERT_EQ(o.disp[s].cols, 3);
    ASSERT_EQ(o.pres[s].rows, nv);
    ASSERT_EQ(o.excess[s].rows, nv);
    for (PetscInt i = 0; i < nv; ++i) {
      const double *x = &o.xyz.values[i * cdim];
      const bool hasP = x[0] <= kPressureXMax;
      for (PetscInt d = 0; d < 3; ++d)
        if (!(std::abs(o.disp[s].values[3 * i + d] - dispValue(x, cdim, d, s)) <= 1e-12)) ++bad;
      if (!hasP) {
        // No pressure dof: a vertex of non-porous cells only, written as NaN.
        if (!std::isnan(o.pres[s].values[i]) || !std::isnan(o.excess[s].values[i])) ++bad;
        continue;
      }
      const double p = presValue(x, s);
      const double ex = s == 0 ? p - kInitialPressure : p;
      if (!(std::abs(o.pres[s].values[i] - p) <= 1e-12)) ++bad;
      if (!(std::abs(o.excess[s].values[i] - ex) <= 1e-12)) ++bad;
    }
  }
  EXPECT_EQ(bad, 0) << "field values differ from the functions at the written coordinates";

  // Connectivity: in range, distinct, positively oriented with the exact measure.
  int badCells = 0;
  for (size_t c = 0; c * o.corners < o.cells.size(); ++c) {
    std::vector<std::array<double, 3>> x(o.corners);
    for (PetscInt k = 0; k < o.corners; ++k) {
      const PetscInt g = o.cells[c * o.corners + k];
      ASSERT_GE(g, 0);
      ASSERT_LT(g, nv);
      x[k] = {0, 0, 0};
      for (PetscInt d = 0; d < cdim; ++d)
        x[k][d] = o.xyz.values[g * cdim + d];
    }
    const double m = signedMeasure(x, o.corners, dim);
    if (std::abs(m - cellMeasure) > 1e-10 * std::max(1.0, cellMeasure)) ++badCells;
  }
  EXPECT_EQ(badCells, 0) << "cells with wrong orientation or measure (expected " << cellMeasure
                         << ")";

  // Cell fields: each written cell's values are those of its own centroid (from the written
  // connectivity and geometry), whichever rank owned it.
  {
    const size_t nc = o.cells.size() / o.corners;
    ASSERT_EQ(o.region.size(), nc);
    int badValues = 0;
    for (size_t c = 0; c < nc; ++c) {
      double m[3] = {0, 0, 0};
      for (PetscInt k = 0; k < o.corners; ++k)
        for (PetscInt d = 0; d < cdim; ++d)
          m[d] += o.xyz.values[o.cells[c * o.corners + k] * cdim + d] / o.corners;
      badValues += o.region[c] != cellRegion(m);
      for (int s = 0; s < 2; ++s) {
        ASSERT_EQ(o.tensor[s].cols, 9);
        ASSERT_EQ((size_t)o.tensor[s].rows, nc);
        for (int k = 0; k < 9; ++k)
          badValues += !(std::abs(o.tensor[s].values[9 * c + k] - cellValue(m, k, s)) <= 1e-9);
      }
    }
    EXPECT_EQ(badValues, 0) << "cell fields not at their cells";
  }

  // XDMF: two times.
  {
    std::ifstream in(dir + "/fields.xmf");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string xmf = ss.str();
    EXPECT_NE(xmf.find("CollectionType=\"Temporal\""), std::string::npos);
    EXPECT_NE(xmf.find("<Time Value=\"0.25\""), std::string::npos);
    EXPECT_NE(xmf.find("<Time Value=\"1.5\""), std::string::npos);
    EXPECT_NE(xmf.find("excess_pressure"), std::string::npos);
    EXPECT_NE(xmf.find("<Attribute Name=\"tensor\" AttributeType=\"Tensor\" Center=\"Cell\">"),
              std::string::npos);
    EXPECT_NE(xmf.find("<Attribute Name=\"region\" AttributeType=\"Scalar\" Center=\"Cell\">"),
              std::string::npos);
  }

  MPI_Barrier(PETSC_COMM_WORLD);
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0 && !std::getenv("POROSEAM_KEEP_TEST_OUTPUT")) std::filesystem::remove_all(dir);
  if (rank == 0 && std::getenv("POROSEAM_KEEP_TEST_OUTPUT"))
    std::printf("[field_writer] kept %s\n", dir.c_str());
}

PetscErrorCode boxMesh(PetscInt dim, const PetscInt *faces, DM *dm)
{
  const PetscReal lower[3] = {0, 0, 0}, upper[3] = {1, 1, 1};

  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_WORLD, dim, PETSC_FALSE, faces, lower, upper, nullptr,
                                PETSC_TRUE, dm));
  PetscFunctionReturn(0);
}

// Structured simplex mesh of the unit square/cube built on rank 0 from a cell list (this PETSc
// has neither Triangle nor TetGen). Cells are given in PETSc's orientation convention.
PetscErrorCode simplexMesh(PetscInt dim, PetscInt n, DM *dm)
{
  PetscMPIInt rank;
  std::vector<PetscInt> cells;
  std::vector<double> xyz;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  const PetscInt np = n + 1;
  if (rank == 0) {
    const PetscInt nz = dim == 3 ? np : 1;
    for (PetscInt k = 0; k < nz; ++k)
      for (PetscInt j = 0; j < np; ++j)
        for (PetscInt i = 0; i < np; ++i) {
          xyz.push_back((double)i / n);
          xyz.push_back((double)j / n);
          if (dim == 3) xyz.push_back((double)k / n);
        }
    auto id = [&](PetscInt i, PetscInt j, PetscInt k) { return i + np * (j + np * k); };
    auto X = [&](PetscInt v) { return &xyz[dim * v]; };
    for (PetscInt k = 0; k < (dim == 3 ? n : 1); ++k)
      for (PetscInt j = 0; j < n; ++j)
        for (PetscInt i = 0; i < n; ++i) {
          if (dim == 2) {
            const PetscInt a = id(i, j, 0), b = id(i + 1, j, 0), c = id(i + 1, j + 1, 0),
                           d = id(i, j + 1, 0);
            PetscInt t[2][3] = {{a, b, c}, {a, c, d}}; // counterclockwise
            for (auto &tri : t)
              cells.insert(cells.end(), tri, tri + 3);
          } else {
            PetscInt v[8];
            for (int q = 0; q < 8; ++q)
              v[q] = id(i + (q & 1), j + ((q >> 1) & 1), k + (q >> 2));
            // Kuhn triangulation: 6 tetrahedra along the diagonal v0-v7.
            static const int path[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
            for (auto &p : path) {
              PetscInt tet[4] = {v[0], v[p[0]], v[p[1]], v[7]};
              const double o3[3] = {X(tet[0])[0], X(tet[0])[1], X(tet[0])[2]};
              if (triple(X(tet[1]), X(tet[2]), X(tet[3]), o3) < 0) std::swap(tet[2], tet[3]);
              PetscCall(DMPlexInvertCell(DM_POLYTOPE_TETRAHEDRON, tet)); // to PETSc convention
              cells.insert(cells.end(), tet, tet + 4);
            }
          }
        }
  }
  const PetscInt nc = (PetscInt)cells.size() / (dim + 1), nvert = (PetscInt)xyz.size() / dim;
  std::vector<PetscReal> rxyz(xyz.begin(), xyz.end());
  PetscCall(DMPlexCreateFromCellListPetsc(PETSC_COMM_WORLD, dim, nc, nvert, dim + 1, PETSC_TRUE,
                                          cells.data(), dim, rxyz.data(), dm));
  PetscFunctionReturn(0);
}

// Quad box with a vertical fault at x = 0.5 split by cohesive (SEG_PRISM_TENSOR) cells.
PetscErrorCode cohesiveMesh(DM *dm)
{
  const PetscInt faces[2] = {4, 2};
  DMLabel fault, hybridLabel = nullptr, splitLabel = nullptr;
  PetscInt vStart, vEnd;
  PetscSection csec;
  Vec coords;
  const PetscScalar *ca;
  DM interface = nullptr, hybrid = nullptr;

  PetscFunctionBeginUser;
  PetscCall(boxMesh(2, faces, dm));
  PetscCall(DMCreateLabel(*dm, "fault"));
  PetscCall(DMGetLabel(*dm, "fault", &fault));
  PetscCall(DMPlexGetDepthStratum(*dm, 0, &vStart, &vEnd));
  PetscCall(DMGetCoordinateSection(*dm, &csec));
  PetscCall(DMGetCoordinatesLocal(*dm, &coords));
  PetscCall(VecGetArrayRead(coords, &ca));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(csec, v, &off));
    if (std::abs(PetscRealPart(ca[off]) - 0.5) < 1e-12) PetscCall(DMLabelSetValue(fault, v, 1));
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(DMPlexCreateHybridMesh(*dm, fault, nullptr, 1, &hybridLabel, &splitLabel, &interface,
                                   &hybrid));
  PetscCall(DMLabelDestroy(&hybridLabel));
  PetscCall(DMLabelDestroy(&splitLabel));
  PetscCall(DMDestroy(&interface));
  PetscCall(DMDestroy(dm));
  *dm = hybrid;
  PetscFunctionReturn(0);
}

} // namespace

TEST(FieldWriter, Quad2D)
{
  DM dm;
  const PetscInt faces[2] = {4, 3};
  ASSERT_EQ(boxMesh(2, faces, &dm), 0);
  ASSERT_EQ(distribute(&dm, 0), 0);
  checkMesh(dm, "quad", 5 * 4, 12, 4, 1.0 / 12, true);
  DMDestroy(&dm);
}

TEST(FieldWriter, Quad2DWithOverlap)
{
  DM dm;
  const PetscInt faces[2] = {4, 4};
  ASSERT_EQ(boxMesh(2, faces, &dm), 0);
  ASSERT_EQ(distribute(&dm, 1), 0);
  checkMesh(dm, "quad_overlap", 5 * 5, 16, 4, 1.0 / 16, true);
  DMDestroy(&dm);
}

TEST(FieldWriter, Hex3D)
{
  DM dm;
  const PetscInt faces[3] = {3, 2, 2};
  ASSERT_EQ(boxMesh(3, faces, &dm), 0);
  ASSERT_EQ(distribute(&dm, 0), 0);
  checkMesh(dm, "hex", 4 * 3 * 3, 12, 8, 1.0 / 12, true);
  DMDestroy(&dm);
}

TEST(FieldWriter, Triangle2D)
{
  DM dm;
  ASSERT_EQ(simplexMesh(2, 4, &dm), 0);
  ASSERT_EQ(distribute(&dm, 0), 0);
  checkMesh(dm, "tri", 5 * 5, 32, 3, 1.0 / 32, true);
  DMDestroy(&dm);
}

TEST(FieldWriter, Tet3D)
{
  DM dm;
  ASSERT_EQ(simplexMesh(3, 2, &dm), 0);
  ASSERT_EQ(distribute(&dm, 0), 0);
  checkMesh(dm, "tet", 3 * 3 * 3, 48, 4, 1.0 / 48, true);
  DMDestroy(&dm);
}

TEST(FieldWriter, SkipsCohesiveCells)
{
  DM dm;
  ASSERT_EQ(cohesiveMesh(&dm), 0);
  ASSERT_EQ(distribute(&dm, 0), 0);
  PetscInt cStart, cEnd, nCohesive = 0, total = 0;
  ASSERT_EQ(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd), 0);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    ASSERT_EQ(DMPlexGetCellType(dm, c, &ct), 0);
    if (ct == DM_POLYTOPE_SEG_PRISM_TENSOR) ++nCohesive;
  }
  MPI_Allreduce(&nCohesive, &total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  ASSERT_GT(total, 0) << "the test mesh has no cohesive cells";
  // 5x3 vertices plus 3 duplicated fault vertices; 8 quads, the 2 cohesive cells are skipped.
  checkMesh(dm, "cohesive", 5 * 3 + 3, 8, 4, 1.0 / 8, false);
  DMDestroy(&dm);
}

TEST(FieldWriter, DisplacementOnly)
{
  DM dm;
  PetscSection s;
  PetscInt pStart, pEnd, vStart, vEnd;
  const PetscInt faces[2] = {2, 2};
  ASSERT_EQ(boxMesh(2, faces, &dm), 0);
  ASSERT_EQ(distribute(&dm, 0), 0);
  ASSERT_EQ(PetscSectionCreate(PETSC_COMM_WORLD, &s), 0);
  ASSERT_EQ(PetscSectionSetNumFields(s, 1), 0);
  ASSERT_EQ(PetscSectionSetFieldName(s, 0, "displacement"), 0);
  ASSERT_EQ(PetscSectionSetFieldComponents(s, 0, 2), 0);
  ASSERT_EQ(DMPlexGetChart(dm, &pStart, &pEnd), 0);
  ASSERT_EQ(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd), 0);
  ASSERT_EQ(PetscSectionSetChart(s, pStart, pEnd), 0);
  for (PetscInt v = vStart; v < vEnd; ++v) {
    ASSERT_EQ(PetscSectionSetFieldDof(s, v, 0, 2), 0);
    ASSERT_EQ(PetscSectionSetDof(s, v, 2), 0);
  }
  ASSERT_EQ(PetscSectionSetUp(s), 0);
  ASSERT_EQ(DMSetLocalSection(dm, s), 0);
  ASSERT_EQ(PetscSectionDestroy(&s), 0);
  Vec local;
  ASSERT_EQ(fillLocal(dm, 0, false, &local), 0);

  const std::string dir = makeTempDir("disp_only");
  {
    poroseam::FieldWriter writer;
    ASSERT_EQ(writer.open(dm, dir, "fields"), 0);
    ASSERT_EQ(writer.write(3.0, local, nullptr), 0);
    // No close(): the destructor finishes the files.
  }
  ASSERT_EQ(VecDestroy(&local), 0);

  PetscViewer viewer;
  PetscBool hasDisp, hasPres;
  Dataset xyz, disp;
  ASSERT_EQ(
      PetscViewerHDF5Open(PETSC_COMM_SELF, (dir + "/fields.h5").c_str(), FILE_MODE_READ, &viewer),
      0);
  ASSERT_EQ(PetscViewerHDF5HasGroup(viewer, "/fields/displacement", &hasDisp), 0);
  ASSERT_EQ(PetscViewerHDF5HasGroup(viewer, "/fields/pressure", &hasPres), 0);
  EXPECT_TRUE(hasDisp);
  EXPECT_FALSE(hasPres);
  ASSERT_EQ(readVec(viewer, "/geometry", "vertices", &xyz), 0);
  ASSERT_EQ(readVec(viewer, "/fields/displacement", "0", &disp), 0);
  ASSERT_EQ(PetscViewerDestroy(&viewer), 0);
  ASSERT_EQ(xyz.rows, 9);
  ASSERT_EQ(disp.rows, 9);
  for (PetscInt i = 0; i < 9; ++i)
    for (PetscInt d = 0; d < 3; ++d)
      EXPECT_NEAR(disp.values[3 * i + d], dispValue(&xyz.values[2 * i], 2, d, 0), 1e-12);

  std::ifstream in(dir + "/fields.xmf");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_NE(ss.str().find("<Time Value=\"3\""), std::string::npos);
  EXPECT_EQ(ss.str().find("pressure"), std::string::npos);

  MPI_Barrier(PETSC_COMM_WORLD);
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0 && !std::getenv("POROSEAM_KEEP_TEST_OUTPUT")) std::filesystem::remove_all(dir);
  DMDestroy(&dm);
}
