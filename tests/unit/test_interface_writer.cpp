// InterfaceWriter: builds a block-on-base model the way src/solve/simulation.cpp does (2D quads
// with Gauss and nodal integration, 3D hexahedra and tetrahedra), moves the block rigidly by a
// known vector relative to the base, writes two times, reads the HDF5 file back and checks
// geometry, counts and every field; then validates the directory with
// tests/support/interface_reader.py. With interface flow (2D): a known opening and a linear
// interface pressure p3, checks the hydraulic fields (p3, aperture, cubic-law flux, ...).
// Runs on 1 and 2 ranks.
#include "poroseam/interface_writer.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/problem.hpp"

#include <gtest/gtest.h>
#include <petscviewerhdf5.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

const std::string kSource =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();

constexpr double kKN = 1e10, kKT = 1e10, kFriction = 0.5;

std::string makeTempDir(const std::string &tag)
{
  char buf[4096] = {0};
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    std::string templ =
        (std::filesystem::temp_directory_path() / ("poroseam_iw_" + tag + "_XXXXXX")).string();
    std::vector<char> t(templ.begin(), templ.end());
    t.push_back('\0');
    if (mkdtemp(t.data())) std::snprintf(buf, sizeof(buf), "%s", t.data());
  }
  MPI_Bcast(buf, sizeof(buf), MPI_CHAR, 0, PETSC_COMM_WORLD);
  return buf;
}

// A 3D block on a base: base [0,1]^2 x [0,0.5], block [0,1]^2 x [0.5,1], contact z = 0.5.
std::string write3dGeo(const std::string &dir, bool hex)
{
  const std::string path = dir + (hex ? "/block_on_base_hex.geo" : "/block_on_base_tet.geo");
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    std::ofstream f(path);
    f << "SetFactory(\"OpenCASCADE\");\n"
         "Box(1) = {0, 0, 0, 1, 1, 0.5};\n"
         "Box(2) = {0, 0, 0.5, 1, 1, 0.5};\n"
         "v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };\n"
         "e = 1e-6;\n"
         "Physical Volume(\"base\") = Volume In BoundingBox{-e, -e, -e, 1+e, 1+e, 0.5+e};\n"
         "Physical Volume(\"block\") = Volume In BoundingBox{-e, -e, 0.5-e, 1+e, 1+e, 1+e};\n"
         "Physical Surface(\"contact\") = Surface In BoundingBox{-e, -e, 0.5-e, 1+e, 1+e, "
         "0.5+e};\n"
         "Physical Surface(\"bottom\") = Surface In BoundingBox{-e, -e, -e, 1+e, 1+e, e};\n"
         "Mesh.CharacteristicLengthMax = 0.4;\n";
    if (hex)
      f << "Transfinite Curve{:} = 3;\nTransfinite Surface{:};\nRecombine Surface{:};\n"
           "Transfinite Volume{:};\n";
  }
  return path;
}

struct Model {
  poroseam::Scene scene;
  DM dm = nullptr;
  poroseam::Problem problem;
  ~Model() { DMDestroy(&dm); }
};

// The set-up of src/solve/simulation.cpp. Sets the options, builds, clears the options.
PetscErrorCode buildModel(const Options &options, const std::string &work, Model &m)
{
  MPI_Comm comm = PETSC_COMM_WORLD;
  std::vector<poroseam::PhysicalName> names;
  int dim;

  PetscFunctionBeginUser;
  for (const auto &o : options)
    PetscCall(PetscOptionsSetValue(nullptr, o.first.c_str(), o.second.c_str()));
  PetscCall(poroseam::readMeshOptions(comm, m.scene));
  PetscCall(poroseam::loadGmshMesh(comm, m.scene.mesh_file, m.scene.mesh_size_factor,
                                   work + "/mesh", &m.dm, &names, &dim));
  PetscCall(poroseam::readSceneOptions(comm, names, dim, m.scene));
  for (const auto &o : options)
    PetscCall(PetscOptionsClearValue(nullptr, o.first.c_str()));
  PetscCall(poroseam::splitInterfaces(&m.dm, m.scene));
  PetscCall(poroseam::markLayoutLabels(m.dm, m.scene));
  PetscCall(poroseam::distributeMesh(&m.dm));
  PetscCall(poroseam::createSolutionSection(m.dm, m.scene));
  PetscCall(m.problem.setup(m.dm, m.scene));
  PetscFunctionReturn(0);
}

Options sceneOptions(const std::string &mesh, int dim, const std::string &integration,
                     bool interfaces = true)
{
  Options o = {{"-mesh", mesh},
               {"-regions", "base,block"},
               {"-region_base_material", "elastic"},
               {"-region_base_E", "1e8"},
               {"-region_base_nu", "0.0"},
               {"-region_block_material", "elastic"},
               {"-region_block_E", "1e8"},
               {"-region_block_nu", "0.0"},
               {"-boundaries", "bottom"},
               {"-bc_bottom_ux", "0"},
               {"-bc_bottom_uy", "0"}};
  if (dim == 3) o.push_back({"-bc_bottom_uz", "0"});
  if (interfaces) {
    o.push_back({"-interfaces", "contact"});
    o.push_back({"-interface_contact_side1", "base"});
    o.push_back({"-interface_contact_KN", "1e10"});
    o.push_back({"-interface_contact_KT", "1e10"});
    o.push_back({"-interface_contact_friction", "0.5"});
    o.push_back({"-interface_contact_integration", integration});
  }
  return o;
}

// Local vector: the block (closure of its bulk cells and the side-2 faces of cohesive cells)
// displaced by `shift`, the base at rest.
PetscErrorCode blockShift(const Model &m, const double shift[3], Vec *local)
{
  PetscSection s;
  PetscInt cStart, cEnd, vStart, vEnd;
  DMLabel cellSets, side;
  PetscScalar *a;
  int blockTag = -1;

  PetscFunctionBeginUser;
  for (const auto &r : m.scene.regions)
    if (r.name == "block") blockTag = r.tag;
  PetscCall(DMCreateLocalVector(m.dm, local));
  PetscCall(VecSet(*local, 0.0));
  PetscCall(DMGetLocalSection(m.dm, &s));
  PetscCall(DMGetLabel(m.dm, "Cell Sets", &cellSets));
  PetscCall(DMGetLabel(m.dm, poroseam::kInterfaceSideLabel, &side));
  PetscCall(DMPlexGetHeightStratum(m.dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetDepthStratum(m.dm, 0, &vStart, &vEnd));
  std::vector<PetscInt> roots;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType t;
    PetscInt value;
    PetscCall(DMPlexGetCellType(m.dm, c, &t));
    if (poroseam::isCohesive(t)) {
      const PetscInt *cone;
      PetscCall(DMLabelGetValue(side, c, &value));
      PetscCall(DMPlexGetCone(m.dm, c, &cone));
      roots.push_back(cone[2 - value]); // the side-2 face
    } else {
      PetscCall(DMLabelGetValue(cellSets, c, &value));
      if (value == blockTag) roots.push_back(c);
    }
  }
  PetscCall(VecGetArray(*local, &a));
  for (PetscInt r : roots) {
    PetscInt n, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(m.dm, r, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt v = pts[2 * i];
      if (v < vStart || v >= vEnd) continue;
      PetscInt off;
      PetscCall(PetscSectionGetFieldOffset(s, v, poroseam::kDisplacementField, &off));
      for (int d = 0; d < m.scene.dim; ++d)
        a[off + d] = shift[d];
    }
    PetscCall(DMPlexRestoreTransitiveClosure(m.dm, r, PETSC_TRUE, &n, &pts));
  }
  PetscCall(VecRestoreArray(*local, &a));
  PetscFunctionReturn(0);
}

PetscInt cohesiveCells(DM dm)
{
  PetscInt cStart, cEnd, n = 0, total = 0;
  DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType t;
    DMPlexGetCellType(dm, c, &t);
    if (poroseam::isCohesive(t)) ++n;
  }
  MPIU_Allreduce(&n, &total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  return total;
}

struct Dataset {
  std::vector<double> v;
  PetscInt rows = 0, cols = 0;
  double time = -1;
  double operator()(PetscInt i, PetscInt j = 0) const { return v[i * cols + j]; }
};

PetscErrorCode readReal(PetscViewer viewer, const std::string &group, const std::string &name,
                        Dataset *out, bool withTime = false)
{
  Vec v;
  PetscInt n, bs;
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(PETSC_COMM_SELF, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, name.c_str()));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group.c_str()));
  PetscCall(VecLoad(v, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCall(VecGetSize(v, &n));
  PetscCall(VecGetBlockSize(v, &bs));
  PetscCall(VecGetArrayRead(v, &a));
  out->v.assign(a, a + n);
  PetscCall(VecRestoreArrayRead(v, &a));
  out->cols = bs;
  out->rows = n / bs;
  PetscCall(VecDestroy(&v));
  if (withTime) {
    PetscReal t;
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, (group + "/" + name).c_str(), "time", PETSC_REAL,
                                           nullptr, &t));
    out->time = t;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readInt(PetscViewer viewer, const std::string &group, const std::string &name,
                       Dataset *out)
{
  IS is;
  PetscInt n, bs;
  const PetscInt *idx;

  PetscFunctionBeginUser;
  PetscCall(ISCreate(PETSC_COMM_SELF, &is));
  PetscCall(ISSetType(is, ISGENERAL));
  PetscCall(PetscObjectSetName((PetscObject)is, name.c_str()));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group.c_str()));
  PetscCall(ISLoad(is, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetBlockSize(is, &bs));
  PetscCall(ISGetIndices(is, &idx));
  out->v.assign(idx, idx + n);
  PetscCall(ISRestoreIndices(is, &idx));
  out->cols = bs;
  out->rows = n / bs;
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

// Polygon area of nodes x[0..n) (3D: via the cross-product sum).
double polygonArea(const Dataset &xyz, PetscInt first, PetscInt n, int dim)
{
  if (dim == 2) {
    const double dx = xyz(first + 1, 0) - xyz(first, 0), dy = xyz(first + 1, 1) - xyz(first, 1);
    return std::sqrt(dx * dx + dy * dy);
  }
  double s[3] = {0, 0, 0};
  for (PetscInt k = 0; k < n; ++k) {
    const PetscInt i = first + k, j = first + (k + 1) % n;
    s[0] += xyz(i, 1) * xyz(j, 2) - xyz(i, 2) * xyz(j, 1);
    s[1] += xyz(i, 2) * xyz(j, 0) - xyz(i, 0) * xyz(j, 2);
    s[2] += xyz(i, 0) * xyz(j, 1) - xyz(i, 1) * xyz(j, 0);
  }
  return 0.5 * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
}

// Checks the fields of one grid ("cells" or "points") at one step for shift k * base.
void checkFields(PetscViewer viewer, const std::string &grid, int step, double time, int dim,
                 PetscInt rows, const double base[3], double k)
{
  const std::string g = "/" + grid + "/fields/", s = std::to_string(step);
  const int t = dim - 1;
  const double gn = k * base[dim - 1]; // normal e1 = +y (2D) or +z (3D)
  double tang[3] = {0, 0, 0}, slip = 0;
  for (int d = 0; d < dim - 1; ++d)
    tang[d] = k * base[d], slip += tang[d] * tang[d];
  slip = std::sqrt(slip);
  const double p = -kKN * gn, tau = kFriction * p; // slipping: |tau| = mu p'_N
  Dataset a;
  auto near = [](double x, double y, double scale) { return std::abs(x - y) <= 1e-9 * scale; };
  int bad = 0;

  ASSERT_EQ(readReal(viewer, g + "gap_normal", s, &a, true), 0);
  EXPECT_DOUBLE_EQ(a.time, time);
  ASSERT_EQ(a.rows, rows);
  ASSERT_EQ(a.cols, 1);
  for (PetscInt i = 0; i < rows; ++i)
    bad += !near(a(i), gn, std::abs(gn));
  EXPECT_EQ(bad, 0) << grid << " gap_normal != " << gn;

  ASSERT_EQ(readReal(viewer, g + "opening", s, &a), 0);
  for (PetscInt i = 0; i < rows; ++i)
    bad += a(i) != 0.0;
  ASSERT_EQ(readReal(viewer, g + "slip", s, &a), 0);
  ASSERT_EQ(a.cols, t);
  ASSERT_EQ(a.rows, rows);
  for (PetscInt i = 0; i < rows; ++i) {
    double m = 0;
    for (int c = 0; c < t; ++c)
      m += a(i, c) * a(i, c);
    bad += !near(std::sqrt(m), slip, slip);
  }
  EXPECT_EQ(bad, 0) << grid << " |slip| != " << slip;
  ASSERT_EQ(readReal(viewer, g + "slip_vector", s, &a), 0);
  ASSERT_EQ(a.cols, 3);
  for (PetscInt i = 0; i < rows; ++i)
    for (int d = 0; d < 3; ++d)
      bad += !near(a(i, d), tang[d], slip);
  EXPECT_EQ(bad, 0) << grid << " slip_vector";
  ASSERT_EQ(readReal(viewer, g + "contact_pressure_effective", s, &a), 0);
  for (PetscInt i = 0; i < rows; ++i)
    bad += !near(a(i), p, p);
  EXPECT_EQ(bad, 0) << grid << " contact_pressure_effective != " << p;
  ASSERT_EQ(readReal(viewer, g + "shear_stress", s, &a), 0);
  ASSERT_EQ(a.cols, t);
  for (PetscInt i = 0; i < rows; ++i) {
    double m = 0;
    for (int c = 0; c < t; ++c)
      m += a(i, c) * a(i, c);
    bad += !near(std::sqrt(m), tau, tau);
  }
  EXPECT_EQ(bad, 0) << grid << " |shear_stress| != " << tau;
  // Side 2 moves along +tang relative to side 1: friction drags side 1 along +tang; side 2
  // presses side 1 along -e1.
  Dataset st, tr;
  ASSERT_EQ(readReal(viewer, g + "shear_traction", s, &st), 0);
  ASSERT_EQ(readReal(viewer, g + "traction", s, &tr), 0);
  ASSERT_EQ(st.cols, 3);
  for (PetscInt i = 0; i < rows; ++i)
    for (int d = 0; d < 3; ++d) {
      const double expect = d < dim - 1 ? tau * tang[d] / slip : 0.0;
      bad += !near(st(i, d), expect, tau);
      bad += !near(tr(i, d), d == dim - 1 ? -p : expect, p);
    }
  EXPECT_EQ(bad, 0) << grid << " shear_traction / traction";
  ASSERT_EQ(readReal(viewer, g + "mobilised_friction", s, &a), 0);
  for (PetscInt i = 0; i < rows; ++i)
    bad += !near(a(i), kFriction, 1.0);
  EXPECT_EQ(bad, 0) << grid << " mobilised_friction != " << kFriction;
  ASSERT_EQ(readInt(viewer, g + "state", s, &a), 0);
  ASSERT_EQ(a.rows, rows);
  for (PetscInt i = 0; i < rows; ++i)
    bad += a(i) != 2;
  EXPECT_EQ(bad, 0) << grid << " state != slip";
}

// The Python reader validates the XDMF index against the HDF5 file (and reports whether the
// hydraulic fields are there).
void runReader(const std::string &out, const std::string &dir, bool flow)
{
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  int status = 0;
  if (rank == 0) {
    const std::string log = dir + "/reader.log";
    const std::string cmd =
        "/usr/bin/python3 '" + kSource + "/tests/support/interface_reader.py' '" + out + "' > '" +
        log + "' 2>&1 && grep -q 'hydraulic fields: " + (flow ? "yes" : "no") + "' '" + log + "'";
    status = std::system(cmd.c_str());
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  EXPECT_EQ(status, 0) << "interface_reader.py failed, see " << dir << "/reader.log";
}

void runCase(const std::string &tag, const std::string &mesh, int dim,
             const std::string &integration)
{
  const std::string dir = makeTempDir(tag);
  ASSERT_FALSE(dir.empty());
  const std::string meshFile = mesh.empty() ? write3dGeo(dir, integration == "hex") : mesh;
  Model m;
  ASSERT_EQ(
      buildModel(sceneOptions(meshFile, dim, integration == "nodal" ? "nodal" : "gauss"), dir, m),
      0);
  ASSERT_EQ(m.scene.dim, dim);
  const PetscInt expectCells = cohesiveCells(m.dm);
  ASSERT_GT(expectCells, 0);

  const double base[3] = {1e-4, dim == 3 ? 2e-5 : -1e-6, -1e-6};
  double shift1[3], shift2[3];
  for (int d = 0; d < 3; ++d)
    shift1[d] = base[d], shift2[d] = 2 * base[d];
  Vec u1, u2;
  ASSERT_EQ(blockShift(m, shift1, &u1), 0);
  ASSERT_EQ(blockShift(m, shift2, &u2), 0);
  const std::string out = dir + "/out";
  {
    poroseam::InterfaceWriter w;
    ASSERT_EQ(w.open(PETSC_COMM_WORLD, m.scene, out), 0);
    ASSERT_EQ(w.write(0.5, m.problem.interfaces(), u1), 0);
    ASSERT_EQ(w.write(1.25, m.problem.interfaces(), u2), 0);
    ASSERT_EQ(w.close(), 0);
    ASSERT_EQ(w.close(), 0); // idempotent
  }
  VecDestroy(&u1);
  VecDestroy(&u2);

  PetscViewer viewer;
  ASSERT_EQ(PetscViewerHDF5Open(PETSC_COMM_SELF, (out + "/interfaces.h5").c_str(), FILE_MODE_READ,
                                &viewer),
            0);
  Dataset xyz, topo, npc, area, px, pcell, weight;
  ASSERT_EQ(readReal(viewer, "/cells", "geometry", &xyz), 0);
  ASSERT_EQ(readInt(viewer, "/cells", "topology", &topo), 0);
  ASSERT_EQ(readInt(viewer, "/cells", "nodes_per_cell", &npc), 0);
  ASSERT_EQ(readReal(viewer, "/cells", "area", &area), 0);
  ASSERT_EQ(readReal(viewer, "/points", "geometry", &px), 0);
  ASSERT_EQ(readInt(viewer, "/points", "cell", &pcell), 0);
  ASSERT_EQ(readReal(viewer, "/points", "weight", &weight), 0);
  const PetscInt nc = npc.rows, np = px.rows;
  EXPECT_EQ(nc, expectCells);
  ASSERT_EQ(xyz.cols, dim);
  ASSERT_EQ(area.rows, nc);
  const PetscInt npe = (PetscInt)npc(0);
  ASSERT_EQ(topo.rows, nc);
  ASSERT_EQ(topo.cols, npe);
  EXPECT_EQ(xyz.rows, nc * npe);
  int bad = 0;
  double total = 0;
  for (PetscInt c = 0; c < nc; ++c) {
    bad += npc(c) != npe;
    for (PetscInt k = 0; k < npe; ++k)
      bad += topo(c, k) != c * npe + k; // nodes duplicated per cell, in cell order
    // The node polygon has the area of the integration weights: valid (non-crossed) order.
    bad += std::abs(polygonArea(xyz, c * npe, npe, dim) - area(c)) > 1e-12;
    total += area(c);
  }
  for (PetscInt i = 0; i < xyz.rows; ++i)
    bad += std::abs(xyz(i, dim - 1) - 0.5) > 1e-12;
  EXPECT_EQ(bad, 0) << "cell geometry";
  EXPECT_NEAR(total, 1.0, 1e-12);
  // Points: on the interface, inside the cell's bounding box, weights summing to the areas.
  ASSERT_EQ(pcell.rows, np);
  ASSERT_EQ(weight.rows, np);
  std::vector<double> wsum(nc, 0.0);
  for (PetscInt i = 0; i < np; ++i) {
    const PetscInt c = (PetscInt)pcell(i);
    ASSERT_TRUE(c >= 0 && c < nc);
    wsum[c] += weight(i);
    bad += std::abs(px(i, dim - 1) - 0.5) > 1e-12;
    for (int d = 0; d < dim - 1; ++d) {
      double lo = 1e300, hi = -1e300;
      for (PetscInt k = 0; k < npe; ++k)
        lo = std::min(lo, xyz(c * npe + k, d)), hi = std::max(hi, xyz(c * npe + k, d));
      bad += px(i, d) < lo - 1e-12 || px(i, d) > hi + 1e-12;
    }
  }
  for (PetscInt c = 0; c < nc; ++c)
    bad += std::abs(wsum[c] - area(c)) > 1e-12;
  EXPECT_EQ(bad, 0) << "integration points";
  if (integration == "nodal") {
    EXPECT_EQ(np, nc * npe);
  }

  // No interface has flow: no hydraulic fields.
  for (const char *f : {"/cells/fields/interface_pressure", "/points/fields/aperture"}) {
    PetscBool has = PETSC_TRUE;
    ASSERT_EQ(PetscViewerHDF5HasGroup(viewer, f, &has), 0);
    EXPECT_FALSE(has) << f;
  }

  checkFields(viewer, "cells", 0, 0.5, dim, nc, base, 1.0);
  checkFields(viewer, "cells", 1, 1.25, dim, nc, base, 2.0);
  checkFields(viewer, "points", 0, 0.5, dim, np, base, 1.0);
  checkFields(viewer, "points", 1, 1.25, dim, np, base, 2.0);
  // Both faces' displacements: the base (side 1) stays, the block (side 2) moved by k * base,
  // at every node of the cell grid and every integration point.
  for (const char *grid : {"cells", "points"})
    for (int step = 0; step < 2; ++step) {
      const std::string g = std::string("/") + grid + "/fields/";
      const PetscInt rows = std::string(grid) == "cells" ? xyz.rows : np;
      Dataset minus, plus;
      ASSERT_EQ(readReal(viewer, g + "displacement_minus", std::to_string(step), &minus), 0);
      ASSERT_EQ(readReal(viewer, g + "displacement_plus", std::to_string(step), &plus), 0);
      ASSERT_EQ(minus.rows, rows);
      ASSERT_EQ(plus.rows, rows);
      ASSERT_EQ(plus.cols, 3);
      int wrong = 0;
      for (PetscInt i = 0; i < rows; ++i)
        for (int d = 0; d < 3; ++d) {
          const double want = d < dim ? (step + 1.0) * base[d] : 0.0;
          wrong += std::abs(minus(i, d)) > 1e-15 || std::abs(plus(i, d) - want) > 1e-15;
        }
      EXPECT_EQ(wrong, 0) << grid << " step " << step << ": displacement_minus / _plus";
    }
  PetscViewerDestroy(&viewer);
  runReader(out, dir, false);
}

TEST(InterfaceWriter, Quads2dGauss)
{
  runCase("2d_gauss", kSource + "/meshes/block_on_base_2d.geo", 2, "gauss");
}

TEST(InterfaceWriter, Quads2dNodal)
{
  runCase("2d_nodal", kSource + "/meshes/block_on_base_2d.geo", 2, "nodal");
}

TEST(InterfaceWriter, Hexahedra3d)
{
  runCase("3d_hex", "", 3, "hex");
}

TEST(InterfaceWriter, Tetrahedra3d)
{
  runCase("3d_tet", "", 3, "tet");
}

// Sets p3 = f(x) on every lateral edge carrying an interface pressure dof (x: its cone[0]
// vertex); returns the number of such edges on all ranks (each counted on its owner).
PetscErrorCode setInterfacePressure(const Model &m, Vec local, double (*f)(double), PetscInt *count)
{
  PetscSection s, gs, cs;
  Vec coords;
  PetscInt pStart, pEnd, n = 0;
  PetscScalar *a;
  const PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(m.dm, &s));
  PetscCall(DMGetGlobalSection(m.dm, &gs));
  PetscCall(DMGetCoordinateSection(m.dm, &cs));
  PetscCall(DMGetCoordinatesLocal(m.dm, &coords));
  PetscCall(DMPlexGetChart(m.dm, &pStart, &pEnd));
  PetscCall(VecGetArray(local, &a));
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt pt = pStart; pt < pEnd; ++pt) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(m.dm, pt, &t));
    if (t != DM_POLYTOPE_POINT_PRISM_TENSOR) continue;
    PetscInt dof, off, coff;
    PetscCall(PetscSectionGetFieldDof(s, pt, poroseam::kInterfacePressureField, &dof));
    if (dof == 0) continue;
    PetscCall(PetscSectionGetFieldOffset(s, pt, poroseam::kInterfacePressureField, &off));
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(m.dm, pt, &cone));
    PetscCall(PetscSectionGetOffset(cs, cone[0], &coff));
    a[off] = f(PetscRealPart(x[coff]));
    PetscInt gdof;
    PetscCall(PetscSectionGetDof(gs, pt, &gdof));
    if (gdof > 0) ++n; // negative on ghosts
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(MPIU_Allreduce(&n, count, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

double linearP3(double x)
{
  return 2e4 - 1e4 * x;
}

// 2D block on base, elastic bodies, an interface with flow (D0 = 1e-5, impervious sides): the
// block lifted by 1e-5 (opening 1e-5, aperture 2e-5) and p3 = 2e4 - 1e4 x. Step 0 is written
// with rates (zero rate, dt = 1), step 1 without (hydraulic fields 0).
TEST(InterfaceWriter, Flow2d)
{
  const std::string dir = makeTempDir("flow");
  ASSERT_FALSE(dir.empty());
  Options o = sceneOptions(kSource + "/meshes/block_on_base_2d.geo", 2, "gauss");
  o.push_back({"-interface_contact_flow", "1"});
  o.push_back({"-interface_contact_D0", "1e-5"});
  o.push_back({"-interface_contact_T1", "1e-9"});
  o.push_back({"-interface_contact_T2", "0"});
  Model m;
  ASSERT_EQ(buildModel(o, dir, m), 0);
  ASSERT_TRUE(m.scene.hasInterfacePressure());
  ASSERT_FALSE(m.scene.hasPressure());
  const PetscInt expectCells = cohesiveCells(m.dm);
  ASSERT_GT(expectCells, 0);

  const double opening = 1e-5, D0 = 1e-5, h = D0 + opening, mu = 1e-3;
  const double shift[3] = {0.0, opening, 0.0};
  Vec u, rate;
  PetscInt edges = 0;
  ASSERT_EQ(blockShift(m, shift, &u), 0);
  ASSERT_EQ(setInterfacePressure(m, u, linearP3, &edges), 0);
  EXPECT_EQ(edges, expectCells + 1); // one per split vertex pair of the contact line
  ASSERT_EQ(VecDuplicate(u, &rate), 0);
  ASSERT_EQ(VecSet(rate, 0.0), 0);
  const std::string out = dir + "/out";
  {
    poroseam::InterfaceWriter w;
    ASSERT_EQ(w.open(PETSC_COMM_WORLD, m.scene, out), 0);
    ASSERT_EQ(w.write(1.0, m.problem.interfaces(), u, poroseam::InterfaceRates{rate, 1.0}), 0);
    ASSERT_EQ(w.write(2.0, m.problem.interfaces(), u), 0);
    ASSERT_EQ(w.close(), 0);
  }
  VecDestroy(&u);
  VecDestroy(&rate);

  PetscViewer viewer;
  ASSERT_EQ(PetscViewerHDF5Open(PETSC_COMM_SELF, (out + "/interfaces.h5").c_str(), FILE_MODE_READ,
                                &viewer),
            0);
  Dataset xyz, px;
  ASSERT_EQ(readReal(viewer, "/cells", "geometry", &xyz), 0);
  ASSERT_EQ(readReal(viewer, "/points", "geometry", &px), 0);
  const PetscInt nc = xyz.rows / 2, np = px.rows;
  EXPECT_EQ(nc, expectCells);
  const double q = h * h * h / (12.0 * mu) * 1e4; // -k dp3/dx, dp3/dx = -1e4
  auto near = [](double x, double y, double scale) { return std::abs(x - y) <= 1e-9 * scale; };
  for (const std::string grid : {"cells", "points"}) {
    const PetscInt rows = grid == "cells" ? nc : np;
    // Position of each row: the segment midpoint (the weighted mean of a linear function) or
    // the point.
    std::vector<double> xr(rows);
    for (PetscInt i = 0; i < rows; ++i)
      xr[i] = grid == "cells" ? 0.5 * (xyz(2 * i, 0) + xyz(2 * i + 1, 0)) : px(i, 0);
    const std::string g = "/" + grid + "/fields/";
    for (int step = 0; step < 2; ++step) {
      const std::string s = std::to_string(step);
      const bool with = step == 0; // rates given
      Dataset a;
      int bad = 0;
      ASSERT_EQ(readReal(viewer, g + "interface_pressure", s, &a, true), 0);
      EXPECT_DOUBLE_EQ(a.time, step == 0 ? 1.0 : 2.0);
      ASSERT_EQ(a.rows, rows);
      ASSERT_EQ(a.cols, 1);
      for (PetscInt i = 0; i < rows; ++i)
        bad += !near(a(i), with ? linearP3(xr[i]) : 0.0, 2e4);
      EXPECT_EQ(bad, 0) << grid << " step " << step << " interface_pressure";
      ASSERT_EQ(readReal(viewer, g + "aperture", s, &a), 0);
      ASSERT_EQ(a.rows, rows);
      for (PetscInt i = 0; i < rows; ++i)
        bad += !near(a(i), with ? h : 0.0, h);
      EXPECT_EQ(bad, 0) << grid << " step " << step << " aperture != " << h;
      ASSERT_EQ(readReal(viewer, g + "longitudinal_flux", s, &a), 0);
      ASSERT_EQ(a.rows, rows);
      ASSERT_EQ(a.cols, 3);
      for (PetscInt i = 0; i < rows; ++i) {
        bad += !near(a(i, 0), with ? q : 0.0, q);
        bad += !near(a(i, 1), 0.0, q) || a(i, 2) != 0.0;
      }
      EXPECT_EQ(bad, 0) << grid << " step " << step << " longitudinal_flux != (" << q << ", 0, 0)";
      for (const char *f : {"aperture_rate", "transversal_flux1", "transversal_flux2"}) {
        ASSERT_EQ(readReal(viewer, g + f, s, &a), 0);
        ASSERT_EQ(a.rows, rows);
        ASSERT_EQ(a.cols, 1);
        for (PetscInt i = 0; i < rows; ++i)
          bad += a(i) != 0.0;
        EXPECT_EQ(bad, 0) << grid << " step " << step << " " << f << " != 0";
      }
      // The mechanics of the open interface.
      ASSERT_EQ(readReal(viewer, g + "opening", s, &a), 0);
      for (PetscInt i = 0; i < rows; ++i)
        bad += !near(a(i), opening, opening);
      ASSERT_EQ(readInt(viewer, g + "state", s, &a), 0);
      for (PetscInt i = 0; i < rows; ++i)
        bad += a(i) != 0;
      EXPECT_EQ(bad, 0) << grid << " step " << step << " opening / open state";
    }
  }
  PetscViewerDestroy(&viewer);
  runReader(out, dir, true);
}

TEST(InterfaceWriter, NoInterfacesWritesNothing)
{
  const std::string dir = makeTempDir("none");
  ASSERT_FALSE(dir.empty());
  Model m;
  ASSERT_EQ(
      buildModel(sceneOptions(kSource + "/meshes/block_on_base_2d.geo", 2, "gauss", false), dir, m),
      0);
  Vec u;
  ASSERT_EQ(DMCreateLocalVector(m.dm, &u), 0);
  poroseam::InterfaceWriter w;
  ASSERT_EQ(w.open(PETSC_COMM_WORLD, m.scene, dir + "/out"), 0);
  ASSERT_EQ(w.write(1.0, m.problem.interfaces(), u), 0);
  ASSERT_EQ(w.close(), 0);
  VecDestroy(&u);
  MPI_Barrier(PETSC_COMM_WORLD);
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/interfaces.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/interface_cells.xmf"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/interface_points.xmf"));
}

} // namespace
