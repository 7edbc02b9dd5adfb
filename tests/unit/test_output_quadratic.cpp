// FieldWriter at displacement order 2: the fields are written on XDMF's quadratic cells
// (Triangle_6, Quadrilateral_9, Tetrahedron_10, Hexahedron_27) whose nodes are the mesh points
// carrying displacement unknowns. On distorted meshes of the four cell types, a P2 / Q2 layout
// (unknowns on vertices and edges; on tensor cells also faces and cells) is filled with a
// quadratic displacement and a linear pressure evaluated at each node; the files read back must
// have
//  - every cell's extra nodes where VTK's node order puts them (the table below, typed from
//    the documentation of vtkQuadraticTriangle, vtkBiQuadraticQuad, vtkQuadraticTetra and
//    vtkTriQuadraticHexahedron): an edge node at its edge's midpoint, a face or cell node at the
//    mean of its corners;
//  - the displacement at every node equal to the field at the node's coordinates (so the
//    values and the geometry are in the same order), the pressure likewise (the linear field,
//    interpolated at nodes that are not vertices);
//  - corners of positive VTK orientation, and one node per mesh point with displacement.
#include "order_meshes.hpp"

#include "poroseam/field_writer.hpp"

#include <gtest/gtest.h>
#include <petscdmplex.h>
#include <petscviewerhdf5.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using poroseam::test_support::createOrderMesh;

std::array<double, 3> displacementAt(const double *x)
{
  return {x[0] * x[0] + 0.5 * x[1] * x[2], 2.0 * x[1] * x[1] - x[0] * x[1] + 0.25,
          x[2] * x[0] - 3.0 * x[2] * x[2]};
}
double pressureAt(const double *x) { return 3.0 + x[0] - 2.0 * x[1] + 0.5 * x[2]; }

// VTK's extra nodes (after the corners), each the mean of the listed corners.
std::vector<std::vector<int>> vtkExtraNodes(int dim, bool simplex)
{
  if (dim == 2 && simplex) return {{0, 1}, {1, 2}, {2, 0}};
  if (dim == 2) return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 1, 2, 3}};
  if (simplex) return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  return {{0, 1},       {1, 2},       {2, 3},       {3, 0},       {4, 5},
          {5, 6},       {6, 7},       {7, 4},       {0, 4},       {1, 5},
          {2, 6},       {3, 7},       {0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4},
          {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}};
}

// The vertices in the closure of p.
std::vector<PetscInt> closureVertices(DM dm, PetscInt p)
{
  PetscInt vStart, vEnd, n, *closure = nullptr;
  std::vector<PetscInt> v;
  DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd);
  DMPlexGetTransitiveClosure(dm, p, PETSC_TRUE, &n, &closure);
  for (PetscInt i = 0; i < 2 * n; i += 2)
    if (closure[i] >= vStart && closure[i] < vEnd) v.push_back(closure[i]);
  DMPlexRestoreTransitiveClosure(dm, p, PETSC_TRUE, &n, &closure);
  return v;
}

struct Written {
  std::vector<double> xyz, disp, pres;
  std::vector<PetscInt> cells;
  PetscInt cdim = 0, nodesPerCell = 0, nodesWithDisplacement = 0;
};

PetscErrorCode readReals(PetscViewer viewer, const char *group, const char *name,
                         std::vector<double> &out, PetscInt *bs)
{
  Vec v;
  PetscInt n;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecCreate(PETSC_COMM_SELF, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group));
  PetscCall(VecLoad(v, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCall(VecGetSize(v, &n));
  PetscCall(VecGetBlockSize(v, bs));
  PetscCall(VecGetArrayRead(v, &a));
  out.assign(a, a + n);
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode writeAndRead(int dim, bool simplex, Written &w)
{
  DM dm;
  PetscSection s;
  PetscInt pStart, pEnd, vStart, vEnd;
  PetscFunctionBeginUser;
  PetscCall(createOrderMesh(dim, simplex, 3, 0.04, &dm));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  // P2 (simplices): unknowns on vertices and edges; Lagrange Q2: on every point.
  PetscCall(PetscSectionCreate(PETSC_COMM_SELF, &s));
  PetscCall(PetscSectionSetNumFields(s, 2));
  PetscCall(PetscSectionSetFieldName(s, 0, "displacement"));
  PetscCall(PetscSectionSetFieldName(s, 1, "pressure"));
  PetscCall(PetscSectionSetFieldComponents(s, 0, dim));
  PetscCall(PetscSectionSetFieldComponents(s, 1, 1));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt depth;
    PetscCall(DMPlexGetPointDepth(dm, p, &depth));
    const bool node = simplex ? depth <= 1 : true;
    const bool vertex = depth == 0;
    const PetscInt nd = node ? dim : 0, np = vertex ? 1 : 0;
    if (node) ++w.nodesWithDisplacement;
    PetscCall(PetscSectionSetFieldDof(s, p, 0, nd));
    PetscCall(PetscSectionSetFieldDof(s, p, 1, np));
    PetscCall(PetscSectionSetDof(s, p, nd + np));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(dm, s));
  PetscCall(PetscSectionDestroy(&s));

  // The fields at each node (its position: the mean of its corners).
  Vec local, coords;
  PetscSection csec;
  const PetscScalar *ca;
  PetscScalar *a;
  PetscCall(DMCreateLocalVector(dm, &local));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(VecGetArrayRead(coords, &ca));
  PetscCall(VecGetArray(local, &a));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, off;
    PetscSection ls;
    PetscCall(DMGetLocalSection(dm, &ls));
    PetscCall(PetscSectionGetFieldDof(ls, p, 0, &dof));
    if (!dof) continue;
    double x[3] = {0, 0, 0};
    const std::vector<PetscInt> corners = closureVertices(dm, p);
    for (PetscInt v : corners) {
      PetscInt coff;
      PetscCall(PetscSectionGetOffset(csec, v, &coff));
      for (int d = 0; d < dim; ++d)
        x[d] += PetscRealPart(ca[coff + d]) / corners.size();
    }
    const std::array<double, 3> u = displacementAt(x);
    PetscCall(PetscSectionGetFieldOffset(ls, p, 0, &off));
    for (int d = 0; d < dim; ++d)
      a[off + d] = u[d];
    PetscCall(PetscSectionGetFieldDof(ls, p, 1, &dof));
    if (dof) {
      PetscCall(PetscSectionGetFieldOffset(ls, p, 1, &off));
      a[off] = pressureAt(x);
    }
  }
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(VecRestoreArrayRead(coords, &ca));

  char dirTemplate[] = "/tmp/poroseam_quadratic_out_XXXXXX";
  const std::string dir = mkdtemp(dirTemplate);
  {
    poroseam::FieldWriter writer;
    PetscCall(writer.open(dm, dir, "fields"));
    PetscCall(writer.write(1.0, local, nullptr));
    PetscCall(writer.close());
  }
  PetscViewer viewer;
  PetscInt bs;
  PetscCall(PetscViewerHDF5Open(PETSC_COMM_SELF, (dir + "/fields.h5").c_str(), FILE_MODE_READ,
                                &viewer));
  PetscCall(readReals(viewer, "/geometry", "vertices", w.xyz, &w.cdim));
  PetscCall(readReals(viewer, "/fields/displacement", "0", w.disp, &bs));
  PetscCall(readReals(viewer, "/fields/pressure", "0", w.pres, &bs));
  {
    IS is;
    PetscInt n;
    const PetscInt *idx;
    PetscCall(ISCreate(PETSC_COMM_SELF, &is));
    PetscCall(PetscObjectSetName((PetscObject)is, "cells"));
    PetscCall(PetscViewerHDF5PushGroup(viewer, "/topology"));
    PetscCall(ISLoad(is, viewer));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetBlockSize(is, &w.nodesPerCell));
    PetscCall(ISGetIndices(is, &idx));
    w.cells.assign(idx, idx + n);
    PetscCall(ISRestoreIndices(is, &idx));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(VecDestroy(&local));
  PetscCall(DMDestroy(&dm));
  std::filesystem::remove_all(dir);
  PetscFunctionReturn(0);
}

// Signed measure of the corners in VTK order: positive for a valid VTK cell.
double signedMeasure(const Written &w, const PetscInt *c, int dim, bool simplex)
{
  auto X = [&](int k, int d) { return w.xyz[c[k] * w.cdim + d]; };
  auto cross2 = [&](int o, int a, int b) {
    return (X(a, 0) - X(o, 0)) * (X(b, 1) - X(o, 1)) - (X(a, 1) - X(o, 1)) * (X(b, 0) - X(o, 0));
  };
  auto triple = [&](int o, int a, int b, int q) {
    double e[3][3];
    const int k[3] = {a, b, q};
    for (int r = 0; r < 3; ++r)
      for (int d = 0; d < 3; ++d)
        e[r][d] = X(k[r], d) - X(o, d);
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  if (dim == 2) return simplex ? cross2(0, 1, 2) : cross2(0, 1, 3);
  return simplex ? triple(0, 1, 2, 3) : triple(0, 1, 3, 4); // hexahedron: corner 0's edges
}

void check(int dim, bool simplex)
{
  Written w;
  ASSERT_EQ(writeAndRead(dim, simplex, w), 0);
  const std::vector<std::vector<int>> extra = vtkExtraNodes(dim, simplex);
  const int corners = simplex ? dim + 1 : (dim == 2 ? 4 : 8);
  ASSERT_EQ(w.nodesPerCell, corners + (PetscInt)extra.size());
  ASSERT_EQ(w.cdim, dim);
  const size_t nodes = w.xyz.size() / dim;
  EXPECT_EQ((PetscInt)nodes, w.nodesWithDisplacement);
  ASSERT_EQ(w.disp.size(), nodes * 3);
  ASSERT_EQ(w.pres.size(), nodes);
  double posError = 0.0, dispError = 0.0, presError = 0.0, minMeasure = 1e300;
  std::vector<int> used(nodes, 0);
  for (size_t c = 0; c < w.cells.size(); c += w.nodesPerCell) {
    const PetscInt *row = &w.cells[c];
    minMeasure = std::min(minMeasure, signedMeasure(w, row, dim, simplex));
    for (size_t k = 0; k < extra.size(); ++k) {
      const PetscInt node = row[corners + k];
      for (int d = 0; d < dim; ++d) {
        double mean = 0.0;
        for (int q : extra[k])
          mean += w.xyz[row[q] * dim + d] / extra[k].size();
        posError = std::max(posError, std::abs(w.xyz[node * dim + d] - mean));
      }
    }
    for (PetscInt k = 0; k < w.nodesPerCell; ++k)
      used[row[k]] = 1;
  }
  for (size_t i = 0; i < nodes; ++i) {
    double x[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d)
      x[d] = w.xyz[i * dim + d];
    const std::array<double, 3> u = displacementAt(x);
    for (int d = 0; d < dim; ++d)
      dispError = std::max(dispError, std::abs(w.disp[3 * i + d] - u[d]));
    presError = std::max(presError, std::abs(w.pres[i] - pressureAt(x)));
  }
  EXPECT_LT(posError, 1e-14) << "extra nodes away from VTK's places";
  EXPECT_LT(dispError, 1e-13) << "displacement not the field at its node";
  EXPECT_LT(presError, 1e-13) << "pressure not the linear field at its node";
  EXPECT_GT(minMeasure, 0.0) << "corners not in VTK orientation";
  for (size_t i = 0; i < nodes; ++i)
    EXPECT_TRUE(used[i]) << "node " << i << " belongs to no cell";
}

TEST(QuadraticOutput, Triangle6) { check(2, true); }
TEST(QuadraticOutput, Quadrilateral9) { check(2, false); }
TEST(QuadraticOutput, Tetrahedron10) { check(3, true); }
TEST(QuadraticOutput, Hexahedron27) { check(3, false); }

} // namespace
