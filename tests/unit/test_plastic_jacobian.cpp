// The assembled Jacobian of a Mohr-Coulomb region (the generic skeleton-law path of the cell
// kernel) against central finite differences of the assembled residual, block by block as in
// test_biot_jacobian, in each regime of the law: elastic, a face, an edge and the apex of the
// cone, with committed plastic history, in plane strain (with pore pressure), axisymmetric and
// 3D (drained). An elastic region beside the plastic one takes the kernel's linear path in the
// same assembly. The displacement is affine plus a small random part, so every integration
// point of the plastic region is in the same regime (checked through the committed yield
// states), away from the kinks where finite differences are meaningless. At displacement order 2
// (Taylor-Hood: P2 / Lagrange Q2, more integration points per cell, each with its own history)
// the same regimes, the quadratic nodes (edges, faces, cells) also on the affine field.
#include "poroseam/layout.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"

#include "central_differences.hpp"
#include <cmath>

#include <gtest/gtest.h>
#include <petscdmplex.h>
#include <random>

using namespace poroseam;

namespace {

enum class Geometry { plane_strain, axisymmetric, three_d };

struct Case {
  const char *name;
  Geometry geometry;
  physics::YieldState expected; ///< the plastic region's state at the evaluated displacement
  double strain[3][3];          ///< affine part of the displacement: u = strain x
  int order = 1;                ///< displacement order
};

Scene plasticScene(const Case &c)
{
  Scene s;
  s.dim = c.geometry == Geometry::three_d ? 3 : 2;
  s.axisymmetric = c.geometry == Geometry::axisymmetric;
  s.displacement_order = c.order;
  s.drained = c.geometry != Geometry::plane_strain;
  Region soil;
  soil.name = "soil";
  soil.tag = 1;
  soil.model = MaterialModel::mohr_coulomb;
  soil.young = 2e7;
  soil.poisson = 0.3;
  soil.solid_density = 2650;
  soil.porosity = 0.36;
  soil.permeability = 1e-11;
  soil.biot_coefficient = 0.9;
  soil.storage = 1e-9;
  soil.k0 = 0.6;
  soil.cohesion = 5e3;
  soil.friction_angle = 30.0;
  soil.dilation_angle = 10.0;
  Region rock = soil;
  rock.name = "rock";
  rock.tag = 2;
  rock.model = MaterialModel::elastic;
  rock.young = 2e9;
  s.regions = {soil, rock};
  s.gravity = 9.81;
  s.geostatic = true;
  s.surface_elevation = 1.0;
  s.water_level = 1.2;
  return s;
}

PetscErrorCode buildMesh(int dim, DM *dm)
{
  PetscInt faces[3] = {3, 2, 2};
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_SELF, dim, PETSC_FALSE, faces, nullptr, nullptr, nullptr,
                                PETSC_TRUE, dm));
  PetscCall(DMCreateLabel(*dm, "Cell Sets"));
  DMLabel cells;
  PetscCall(DMGetLabel(*dm, "Cell Sets", &cells));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscReal vol, centroid[3];
    PetscCall(DMPlexComputeCellGeometryFVM(*dm, c, &vol, centroid, nullptr));
    PetscCall(DMLabelSetValue(cells, c, centroid[0] < 0.6 ? 1 : 2));
  }
  PetscFunctionReturn(0);
}

struct Result {
  double max_error[2][2] = {{0, 0}, {0, 0}};
  double max_entry[2][2] = {{0, 0}, {0, 0}};
  int lowest_state = 99, highest_state = -1; ///< committed states of the plastic cells
  double lowest_plastic_strain = 1e300;      ///< of the committed history
};

/// Local vector `u`: displacement strain * x (+ noise of relative size `noise`), pressure
/// initial + random (1e4 Pa). Every point with displacement unknowns (vertices; at order 2 also
/// edges, faces, cells) at the centroid of its closure's vertices, where its node sits.
PetscErrorCode setState(DM dm, const Problem &problem, int dim, const double strain[3][3],
                        double factor, double noise, std::mt19937 &rng, Vec u)
{
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  PetscSection s, cs;
  Vec coords;
  const double *x;
  PetscScalar *a;
  PetscInt pStart, pEnd, nf;
  PetscFunctionBeginUser;
  PetscCall(problem.initialState(u));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(PetscSectionGetNumFields(s, &nf));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(VecGetArray(u, &a));
  for (PetscInt v = pStart; v < pEnd; ++v) {
    PetscInt off, dof, nc = 0;
    PetscCall(PetscSectionGetFieldDof(s, v, kDisplacementField, &dof));
    if (!dof) continue;
    PetscCall(PetscSectionGetFieldOffset(s, v, kDisplacementField, &off));
    PetscScalar *xc = nullptr;
    double xp[3] = {0, 0, 0};
    PetscCall(DMPlexVecGetClosure(dm, cs, coords, v, &nc, &xc));
    for (PetscInt k = 0; k < nc; ++k)
      xp[k % dim] += xc[k] / (nc / dim);
    PetscCall(DMPlexVecRestoreClosure(dm, cs, coords, v, &nc, &xc));
    x = xp;
    for (int i = 0; i < dim; ++i) {
      double value = 0.0;
      for (int j = 0; j < dim; ++j)
        value += factor * strain[i][j] * x[j];
      a[off + i] = value + noise * 1e-3 * r(rng);
    }
    if (nf <= kPressureField) continue;
    PetscCall(PetscSectionGetFieldDof(s, v, kPressureField, &dof));
    if (!dof) continue;
    PetscCall(PetscSectionGetFieldOffset(s, v, kPressureField, &off));
    a[off] += 1e4 * r(rng);
  }
  PetscCall(VecRestoreArray(u, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode compareJacobian(const Case &c, Result *result)
{
  DM dm;
  Scene scene = plasticScene(c);
  const int dim = scene.dim;
  Problem problem;
  PetscFunctionBeginUser;
  PetscCall(buildMesh(dim, &dm));
  PetscCall(markLayoutLabels(dm, scene));
  PetscCall(createSolutionSection(dm, scene));
  PetscCall(problem.setup(dm, scene));

  const double dt = 0.37, t = 1.0;
  Vec X, Fp, Fm, local, rate, previous, flocal;
  PetscCall(DMCreateGlobalVector(dm, &X));
  PetscCall(VecDuplicate(X, &Fp));
  PetscCall(VecDuplicate(X, &Fm));
  PetscCall(DMCreateLocalVector(dm, &local));
  PetscCall(VecDuplicate(local, &rate));
  PetscCall(VecDuplicate(local, &previous));
  PetscCall(VecDuplicate(local, &flocal));
  std::mt19937 rng(42);

  // History: commit the state at 0.6 of the strain (plastic in the plastic regimes), then
  // evaluate at the full strain (the committed history enters every evaluation below).
  PetscCall(setState(dm, problem, dim, c.strain, 0.6, 0.0, rng, previous));
  PetscCall(problem.commit(previous));
  PetscCall(setState(dm, problem, dim, c.strain, 1.0, 1e-3, rng, local));
  PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, X));

  PetscSection s;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscInt n;
  PetscCall(VecGetLocalSize(X, &n));
  std::vector<int> field(n, 0); // 1: pressure
  {
    Vec marker, g;
    PetscCall(VecDuplicate(local, &marker));
    PetscCall(VecSet(marker, 0.0));
    PetscInt vStart, vEnd, nf;
    PetscCall(PetscSectionGetNumFields(s, &nf));
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    PetscScalar *m;
    PetscCall(VecGetArray(marker, &m));
    for (PetscInt v = vStart; v < vEnd && nf > kPressureField; ++v) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetFieldDof(s, v, kPressureField, &dof));
      PetscCall(PetscSectionGetFieldOffset(s, v, kPressureField, &off));
      if (dof) m[off] = 1.0;
    }
    PetscCall(VecRestoreArray(marker, &m));
    PetscCall(DMGetGlobalVector(dm, &g));
    PetscCall(DMLocalToGlobal(dm, marker, INSERT_VALUES, g));
    const PetscScalar *gm;
    PetscCall(VecGetArrayRead(g, &gm));
    for (PetscInt i = 0; i < n; ++i)
      field[i] = gm[i] > 0.5;
    PetscCall(VecRestoreArrayRead(g, &gm));
    PetscCall(DMRestoreGlobalVector(dm, &g));
    PetscCall(VecDestroy(&marker));
  }
  auto residual = [&](Vec Xg, Vec Fg) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(DMGlobalToLocal(dm, Xg, INSERT_VALUES, local));
    PetscCall(VecWAXPY(rate, -1.0, previous, local));
    PetscCall(VecScale(rate, 1.0 / dt));
    PetscCall(problem.residual(t, local, rate, ResidualMode{-dt, true}, flocal));
    PetscCall(VecSet(Fg, 0.0));
    PetscCall(DMLocalToGlobal(dm, flocal, ADD_VALUES, Fg));
    PetscFunctionReturn(0);
  };
  Mat J;
  PetscCall(DMCreateMatrix(dm, &J));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
  PetscCall(VecWAXPY(rate, -1.0, previous, local));
  PetscCall(VecScale(rate, 1.0 / dt));
  PetscCall(problem.jacobian(t, 1.0 / dt, local, rate, ResidualMode{-dt, true, dt}, J));
  Mat Jd;
  PetscCall(MatConvert(J, MATDENSE, MAT_INITIAL_MATRIX, &Jd));
  const PetscScalar *jd;
  PetscCall(MatDenseGetArrayRead(Jd, &jd));
  PetscCall(poroseam::test_support::centralDifferences(
      X, Fp, Fm, residual, [&](PetscInt j) { return field[j] ? 1e-2 : 1e-9; },
      [&](PetscInt i, PetscInt j, double fd) {
        const double exact = jd[i + j * n]; // column-major
        double &err = result->max_error[field[i]][field[j]];
        double &ref = result->max_entry[field[i]][field[j]];
        err = std::max(err, std::fabs(fd - exact));
        ref = std::max(ref, std::fabs(fd));
      }));
  PetscCall(MatDenseRestoreArrayRead(Jd, &jd));

  // The regime of the evaluated state, from the committed history.
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
  PetscCall(problem.visitSkeletonCells(local, [&](PetscInt, double eqps, int state) {
    result->lowest_state = std::min(result->lowest_state, state);
    result->highest_state = std::max(result->highest_state, state);
    result->lowest_plastic_strain = std::min(result->lowest_plastic_strain, eqps);
  }));
  PetscCall(MatDestroy(&Jd));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&X));
  PetscCall(VecDestroy(&Fp));
  PetscCall(VecDestroy(&Fm));
  PetscCall(VecDestroy(&local));
  PetscCall(VecDestroy(&rate));
  PetscCall(VecDestroy(&previous));
  PetscCall(VecDestroy(&flocal));
  PetscCall(problem.release());
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

using YS = physics::YieldState;
// Strains (tension positive) that put the plastic region in each regime, for E = 20 MPa,
// nu = 0.3, c = 5 kPa, phi = 30, psi = 10 degrees: small (elastic); compression with three
// distinct principal strains (a face); compression with two equal lateral ones (the triaxial
// compression edge); a large dilation (the apex). Axisymmetric: u_r = strain[0][0] r only, so
// that the hoop strain u_r / r is the same everywhere (shear through u_z).
const Case kCases[] = {
    {"plane_strain_elastic",
     Geometry::plane_strain,
     YS::elastic,
     {{-1e-4, 2e-5, 0}, {2e-5, 5e-5, 0}, {0, 0, 0}}},
    {"plane_strain_face",
     Geometry::plane_strain,
     YS::face,
     {{-4e-3, 5e-4, 0}, {5e-4, 1e-3, 0}, {0, 0, 0}}},
    {"plane_strain_apex",
     Geometry::plane_strain,
     YS::apex,
     {{5e-3, 0, 0}, {0, 5e-3, 0}, {0, 0, 0}}},
    {"axisymmetric_elastic",
     Geometry::axisymmetric,
     YS::elastic,
     {{-1e-4, 2e-5, 0}, {2e-5, 5e-5, 0}, {0, 0, 0}}},
    {"axisymmetric_face",
     Geometry::axisymmetric,
     YS::face,
     {{-2e-3, 0, 0}, {8e-3, -2e-3, 0}, {0, 0, 0}}},
    {"axisymmetric_edge",
     Geometry::axisymmetric,
     YS::edge,
     {{1e-3, 0, 0}, {0, -4e-3, 0}, {0, 0, 0}}},
    {"axisymmetric_apex",
     Geometry::axisymmetric,
     YS::apex,
     {{5e-3, 0, 0}, {0, 5e-3, 0}, {0, 0, 0}}},
    {"three_d_elastic",
     Geometry::three_d,
     YS::elastic,
     {{-1e-4, 2e-5, 0}, {2e-5, 5e-5, 1e-5}, {0, 1e-5, -3e-5}}},
    {"three_d_face",
     Geometry::three_d,
     YS::face,
     {{-8e-3, 1e-3, 0}, {1e-3, 2e-3, 0}, {0, 0, -2e-3}}},
    {"three_d_edge", Geometry::three_d, YS::edge, {{1e-3, 0, 0}, {0, 1e-3, 0}, {0, 0, -4e-3}}},
    {"three_d_apex", Geometry::three_d, YS::apex, {{5e-3, 0, 0}, {0, 5e-3, 0}, {0, 0, 5e-3}}},
    {"order2_plane_strain_elastic",
     Geometry::plane_strain,
     YS::elastic,
     {{-1e-4, 2e-5, 0}, {2e-5, 5e-5, 0}, {0, 0, 0}},
     2},
    {"order2_plane_strain_face",
     Geometry::plane_strain,
     YS::face,
     {{-4e-3, 5e-4, 0}, {5e-4, 1e-3, 0}, {0, 0, 0}},
     2},
    {"order2_plane_strain_apex",
     Geometry::plane_strain,
     YS::apex,
     {{5e-3, 0, 0}, {0, 5e-3, 0}, {0, 0, 0}},
     2},
    {"order2_axisymmetric_face",
     Geometry::axisymmetric,
     YS::face,
     {{-2e-3, 0, 0}, {8e-3, -2e-3, 0}, {0, 0, 0}},
     2},
    {"order2_axisymmetric_edge",
     Geometry::axisymmetric,
     YS::edge,
     {{1e-3, 0, 0}, {0, -4e-3, 0}, {0, 0, 0}},
     2},
    {"order2_three_d_face",
     Geometry::three_d,
     YS::face,
     {{-8e-3, 1e-3, 0}, {1e-3, 2e-3, 0}, {0, 0, -2e-3}},
     2},
    {"order2_three_d_edge",
     Geometry::three_d,
     YS::edge,
     {{1e-3, 0, 0}, {0, 1e-3, 0}, {0, 0, -4e-3}},
     2},
};

} // namespace

class PlasticJacobian : public ::testing::TestWithParam<Case> {};

TEST_P(PlasticJacobian, EveryBlockMatchesFiniteDifferences)
{
  const Case &c = GetParam();
  Result r;
  ASSERT_EQ(compareJacobian(c, &r), 0);
  EXPECT_EQ(r.lowest_state, (int)c.expected) << "yield state of some plastic cell";
  EXPECT_EQ(r.highest_state, (int)c.expected) << "yield state of some plastic cell";
  if (c.expected != YS::elastic)
    EXPECT_GT(r.lowest_plastic_strain, 0.0) << "every plastic cell has plastic strain";
  const bool pressure = c.geometry == Geometry::plane_strain;
  const char *names[2] = {"u", "p"};
  for (int row = 0; row < (pressure ? 2 : 1); ++row)
    for (int col = 0; col < (pressure ? 2 : 1); ++col) {
      ASSERT_GT(r.max_entry[row][col], 0.0) << "block " << names[row] << names[col] << " is empty";
      const double rel = r.max_error[row][col] / r.max_entry[row][col];
      std::printf("%s block %s%s: max |J - J_fd| / max |J_fd| = %.2e (states %d..%d)\n", c.name,
                  names[row], names[col], rel, r.lowest_state, r.highest_state);
      EXPECT_LT(rel, 1e-6) << "block " << names[row] << names[col];
    }
}

INSTANTIATE_TEST_SUITE_P(Regimes, PlasticJacobian, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case> &info) {
                           return std::string(info.param.name);
                         });
