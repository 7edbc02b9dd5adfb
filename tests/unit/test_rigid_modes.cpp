// The near null space the fieldsplit solver hands to algebraic multigrid
// (displacementRigidBodyModes, src/solve/nullspace.cpp) is made of exact rigid-body modes at both
// displacement orders: K r = 0 to round-off for the elastic stiffness K assembled without
// supports, on distorted meshes of triangles, quadrilaterals, tetrahedra and hexahedra. At
// order 2 the modes must cover the edge, face and cell nodes as well as the vertices; modes on
// the vertices alone leave K r of the order of K itself.
#include "poroseam/layout.hpp"
#include "poroseam/nullspace.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"

#include "order_meshes.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <tuple>

using namespace poroseam;

namespace {

Scene elasticScene(int dim, int order)
{
  Scene s;
  s.dim = dim;
  s.displacement_order = order;
  Region rock;
  rock.name = "rock";
  rock.tag = 1;
  rock.model = MaterialModel::elastic;
  rock.young = 3e8;
  rock.poisson = 0.27;
  rock.solid_density = 2650;
  s.regions = {rock};
  return s;
}

/// Largest |K r|_inf / (|K|_inf |r|_inf) over the modes, and the number of modes.
PetscErrorCode rigidResidual(int dim, bool simplex, int order, double *worst, PetscInt *count)
{
  DM dm;
  Scene scene = elasticScene(dim, order);
  Problem problem;
  PetscFunctionBeginUser;
  PetscCall(test_support::createOrderMesh(dim, simplex, 3, 0.3 / 3.0, &dm));
  PetscCall(markLayoutLabels(dm, scene));
  PetscCall(createSolutionSection(dm, scene));
  PetscCall(problem.setup(dm, scene));
  Vec local, rate;
  Mat K;
  PetscCall(DMCreateLocalVector(dm, &local));
  PetscCall(VecDuplicate(local, &rate));
  PetscCall(VecSet(local, 0.0));
  PetscCall(VecSet(rate, 0.0));
  PetscCall(DMCreateMatrix(dm, &K));
  PetscCall(problem.jacobian(0.0, 1.0, local, rate, ResidualMode{-1.0, true, 1.0}, K));
  PetscInt nf;
  char **names;
  IS *fields;
  PetscCall(DMCreateFieldIS(dm, &nf, &names, &fields));
  MatNullSpace space;
  PetscCall(displacementRigidBodyModes(dm, dim, false, fields[kDisplacementField], &space));
  PetscBool has_constant;
  const Vec *modes;
  PetscCall(MatNullSpaceGetVecs(space, &has_constant, count, &modes));
  PetscReal knorm;
  PetscCall(MatNorm(K, NORM_INFINITY, &knorm));
  Vec Kr;
  PetscCall(MatCreateVecs(K, nullptr, &Kr));
  *worst = 0.0;
  for (PetscInt m = 0; m < *count; ++m) {
    PetscReal rnorm, krnorm;
    PetscCall(MatMult(K, modes[m], Kr));
    PetscCall(VecNorm(modes[m], NORM_INFINITY, &rnorm));
    PetscCall(VecNorm(Kr, NORM_INFINITY, &krnorm));
    *worst = std::max(*worst, (double)(krnorm / (knorm * rnorm)));
  }
  PetscCall(VecDestroy(&Kr));
  PetscCall(MatNullSpaceDestroy(&space));
  for (PetscInt f = 0; f < nf; ++f) {
    PetscCall(PetscFree(names[f]));
    PetscCall(ISDestroy(&fields[f]));
  }
  PetscCall(PetscFree(names));
  PetscCall(PetscFree(fields));
  PetscCall(MatDestroy(&K));
  PetscCall(VecDestroy(&rate));
  PetscCall(VecDestroy(&local));
  PetscCall(problem.release());
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

} // namespace

// (dimension, simplex, displacement order)
class RigidModes : public ::testing::TestWithParam<std::tuple<int, bool, int>> {};

TEST_P(RigidModes, StiffnessAnnihilatesEveryMode)
{
  const int dim = std::get<0>(GetParam()), order = std::get<2>(GetParam());
  const bool simplex = std::get<1>(GetParam());
  double worst = 1.0;
  PetscInt count = 0;
  ASSERT_EQ(rigidResidual(dim, simplex, order, &worst, &count), 0);
  std::printf("dim %d %s order %d: %d modes, max |K r| / (|K| |r|) = %.2e\n", dim,
              simplex ? "simplices" : "tensor cells", order, (int)count, worst);
  EXPECT_EQ(count, dim == 2 ? 3 : 6);
  EXPECT_LT(worst, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(CellsAndOrders, RigidModes,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Values(false, true),
                                            ::testing::Values(1, 2)));
