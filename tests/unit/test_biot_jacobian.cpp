// The assembled Jacobian of every bulk term against central finite differences of the
// assembled residual, block by block (uu, up, pu, pp): the pressure rows are scaled by dt and
// are many orders smaller than the elastic ones, so a single matrix norm would hide them.
// All terms are on: elasticity, initial (K0) stress, gravity, Biot coupling, storage 1/M,
// Darcy flow with gravity, pressure stabilisation (order 1), an elastic region beside a porous
// one; at displacement orders 1 (Q1/Q1) and 2 (Q2/Q1 Taylor-Hood).
#include "poroseam/layout.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"

#include "central_differences.hpp"
#include <cmath>

#include <gtest/gtest.h>
#include <petscdmplex.h>
#include <random>
#include <tuple>

using namespace poroseam;

namespace {

Scene twoRegionScene(int dim, int order)
{
  Scene s;
  s.dim = dim;
  s.displacement_order = order;
  Region soil;
  soil.name = "soil";
  soil.tag = 1;
  soil.model = MaterialModel::biot;
  soil.young = 2e7;
  soil.poisson = 0.3;
  soil.solid_density = 2650;
  soil.porosity = 0.36;
  soil.permeability = 1e-11;
  soil.biot_coefficient = 0.9;
  soil.storage = 1e-9;
  soil.k0 = 0.6;
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

struct Blocks {
  double max_error[2][2] = {{0, 0}, {0, 0}};
  double max_entry[2][2] = {{0, 0}, {0, 0}};
};

PetscErrorCode compareJacobian(int dim, int order, Blocks *blocks)
{
  DM dm;
  Scene scene = twoRegionScene(dim, order);
  Problem problem;
  PetscFunctionBeginUser;
  PetscCall(buildMesh(dim, &dm));
  PetscCall(markLayoutLabels(dm, scene));
  PetscCall(createSolutionSection(dm, scene));
  PetscCall(problem.setup(dm, scene));

  const double dt = 0.37, t = 1.0;
  Vec X, F, Fp, Fm, local, rate, previous, flocal;
  PetscCall(DMCreateGlobalVector(dm, &X));
  PetscCall(VecDuplicate(X, &F));
  PetscCall(VecDuplicate(X, &Fp));
  PetscCall(VecDuplicate(X, &Fm));
  PetscCall(DMCreateLocalVector(dm, &local));
  PetscCall(VecDuplicate(local, &rate));
  PetscCall(VecDuplicate(local, &previous));
  PetscCall(VecDuplicate(local, &flocal));

  // Field of every global dof, and a random state of physical size.
  PetscSection s;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscInt n;
  PetscCall(VecGetLocalSize(X, &n));
  std::vector<int> field(n, 0);
  {
    Vec marker;
    PetscCall(VecDuplicate(local, &marker));
    PetscInt vStart, vEnd;
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    PetscScalar *m;
    PetscCall(VecGetArray(marker, &m));
    for (PetscInt v = vStart; v < vEnd; ++v) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetFieldDof(s, v, kPressureField, &dof));
      PetscCall(PetscSectionGetFieldOffset(s, v, kPressureField, &off));
      if (dof) m[off] = 1.0;
    }
    PetscCall(VecRestoreArray(marker, &m));
    Vec g;
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
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> scale(n);
  {
    PetscScalar *x;
    PetscCall(VecGetArray(X, &x));
    for (PetscInt i = 0; i < n; ++i) {
      scale[i] = field[i] ? 1e4 : 1e-3; // Pa and m
      x[i] = scale[i] * u(rng);
    }
    PetscCall(VecRestoreArray(X, &x));
    PetscCall(problem.initialState(previous));
    PetscScalar *p;
    PetscCall(VecGetArray(previous, &p));
    PetscInt nl;
    PetscCall(VecGetLocalSize(previous, &nl));
    for (PetscInt i = 0; i < nl; ++i)
      p[i] += 1e-4 * u(rng);
    PetscCall(VecRestoreArray(previous, &p));
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
  // The Jacobian of cells without history is kept between assemblies with the same shift and
  // mass scale (Problem::jacobian). Assembled first with another shift, then at another state,
  // the Jacobian compared below comes from that copy, after one change of shift: a copy kept
  // across the change, or anything of the state in it, would show against the differences.
  {
    Vec other_local, other_rate;
    PetscCall(VecDuplicate(local, &other_local));
    PetscCall(VecDuplicate(local, &other_rate));
    PetscCall(VecCopy(previous, other_local));
    PetscCall(VecScale(other_local, 3.0));
    PetscCall(VecWAXPY(other_rate, -1.0, previous, other_local));
    PetscCall(VecScale(other_rate, 1.0 / dt));
    PetscCall(problem.jacobian(t, 2.0 / dt, local, rate, ResidualMode{-dt, true, dt}, J));
    PetscCall(
        problem.jacobian(t, 1.0 / dt, other_local, other_rate, ResidualMode{-dt, true, dt}, J));
    PetscCall(VecDestroy(&other_local));
    PetscCall(VecDestroy(&other_rate));
  }
  PetscCall(problem.jacobian(t, 1.0 / dt, local, rate, ResidualMode{-dt, true, dt}, J));
  Mat Jd;
  PetscCall(MatConvert(J, MATDENSE, MAT_INITIAL_MATRIX, &Jd));
  const PetscScalar *jd;
  PetscCall(MatDenseGetArrayRead(Jd, &jd));
  PetscCall(poroseam::test_support::centralDifferences(
      X, Fp, Fm, residual, [&](PetscInt j) { return 1e-6 * scale[j]; },
      [&](PetscInt i, PetscInt j, double fd) {
        const double exact = jd[i + j * n]; // column-major
        double &err = blocks->max_error[field[i]][field[j]];
        double &ref = blocks->max_entry[field[i]][field[j]];
        err = std::max(err, std::fabs(fd - exact));
        ref = std::max(ref, std::fabs(fd));
      }));
  PetscCall(MatDenseRestoreArrayRead(Jd, &jd));
  PetscCall(MatDestroy(&Jd));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&X));
  PetscCall(VecDestroy(&F));
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

} // namespace

// (dimension, displacement order): order 2 is Q2/Q1 Taylor-Hood (no stabilisation term).
class BiotJacobian : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(BiotJacobian, EveryBlockMatchesFiniteDifferences)
{
  Blocks b;
  const int dim = std::get<0>(GetParam()), order = std::get<1>(GetParam());
  ASSERT_EQ(compareJacobian(dim, order, &b), 0);
  const char *names[2] = {"u", "p"};
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      ASSERT_GT(b.max_entry[r][c], 0.0) << "block " << names[r] << names[c] << " is empty";
      const double rel = b.max_error[r][c] / b.max_entry[r][c];
      std::printf("dim %d order %d block %s%s: max |J - J_fd| / max |J_fd| = %.2e\n", dim, order,
                  names[r], names[c], rel);
      EXPECT_LT(rel, 1e-6) << "block " << names[r] << names[c];
    }
}

INSTANTIATE_TEST_SUITE_P(DimensionsAndOrders, BiotJacobian,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Values(1, 2)));
