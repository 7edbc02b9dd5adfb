// The assembled Jacobian of a mesh with a zero-thickness interface against central finite
// differences of the assembled residual, with the interface in stick, slip and open states,
// and sliding with shear dilation (below and reaching the dilation limit).
// The mesh (a block on a base) is split into cohesive cells exactly as a run does it; the
// block is displaced relative to the base by a gap well inside each regime, plus a small
// random perturbation so that no state is special.
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"

#include "central_differences.hpp"
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>
#include <random>
#include <string>
#include <unistd.h> // getpid: a mesh directory per test process (ctest runs them in parallel)

using namespace poroseam;

namespace {

struct Case {
  const char *name;
  const char *mesh;
  const char *integration;
  double gap[3]; // block displacement relative to the base (x, y[, z]); normal is the last axis
  physics::ContactState expected;
  double size_factor = 1.0;         // gmsh -clscale: coarse in 3D, where the dense check costs n^2
  const char *dilation_angle = "0"; // psi [deg]
  const char *dilation_limit = "";  // plastic slip [m] after which dilation stops ("": none)
};

PetscErrorCode setOption(const char *name, const std::string &value)
{
  return PetscOptionsSetValue(nullptr, name, value.c_str());
}

PetscErrorCode compare(const Case &c, double *relative_error, int *states, int *dilated,
                       int *past_limit)
{
  DM dm;
  Scene scene;
  std::vector<PhysicalName> names;
  int dim;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  const std::string src = POROSEAM_SOURCE_DIR;
  PetscCall(setOption("-mesh", src + "/meshes/" + c.mesh));
  PetscCall(setOption("-regions", "base,block"));
  for (const char *r : {"base", "block"}) {
    const std::string p = std::string("-region_") + r + "_";
    PetscCall(setOption((p + "material").c_str(), "elastic"));
    PetscCall(setOption((p + "E").c_str(), "1e8"));
    PetscCall(setOption((p + "nu").c_str(), "0.25"));
  }
  PetscCall(setOption("-interfaces", "contact"));
  PetscCall(setOption("-interface_contact_side1", "base"));
  PetscCall(setOption("-interface_contact_KN", "1e10"));
  PetscCall(setOption("-interface_contact_KT", "5e9"));
  PetscCall(setOption("-interface_contact_friction", "0.5"));
  PetscCall(setOption("-interface_contact_integration", c.integration));
  PetscCall(setOption("-interface_contact_dilation_angle", c.dilation_angle));
  if (*c.dilation_limit)
    PetscCall(setOption("-interface_contact_dilation_limit", c.dilation_limit));
  PetscCall(readMeshOptions(PETSC_COMM_WORLD, scene));
  PetscCall(loadGmshMesh(PETSC_COMM_SELF, scene.mesh_file, c.size_factor,
                         testing::TempDir() + "poroseam_mesh_" + std::to_string(getpid()), &dm,
                         &names, &dim));
  PetscCall(readSceneOptions(PETSC_COMM_SELF, names, dim, scene));
  PetscCall(splitInterfaces(&dm, scene));
  PetscCall(markLayoutLabels(dm, scene));
  PetscCall(createSolutionSection(dm, scene));
  Problem problem;
  PetscCall(problem.setup(dm, scene));

  // State: block vertices (above the contact plane, or on its block side) moved by the gap.
  Vec local, rate, flocal, X, Fp, Fm;
  PetscCall(DMCreateLocalVector(dm, &local));
  PetscCall(VecDuplicate(local, &rate));
  PetscCall(VecDuplicate(local, &flocal));
  PetscCall(DMCreateGlobalVector(dm, &X));
  PetscCall(VecDuplicate(X, &Fp));
  PetscCall(VecDuplicate(X, &Fm));
  PetscCall(VecSet(rate, 0.0));
  {
    // Side of each vertex: vertices of block cells get the gap.
    PetscSection s;
    PetscCall(DMGetLocalSection(dm, &s));
    DMLabel cellSets;
    PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
    int blockTag = 0;
    for (const auto &n : names)
      if (n.name == "block") blockTag = n.tag;
    PetscScalar *u;
    PetscCall(VecSet(local, 0.0));
    PetscCall(VecGetArray(local, &u));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-1e-9, 1e-9);
    PetscInt cStart, cEnd, vStart, vEnd;
    PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    std::vector<char> inBlock(vEnd - vStart, 0);
    for (PetscInt cell = cStart; cell < cEnd; ++cell) {
      PetscInt tag;
      PetscCall(DMLabelGetValue(cellSets, cell, &tag));
      if (tag != blockTag) continue;
      PetscInt n, *pts = nullptr;
      PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &pts));
      for (PetscInt k = 0; k < n; ++k)
        if (pts[2 * k] >= vStart && pts[2 * k] < vEnd) inBlock[pts[2 * k] - vStart] = 1;
      PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &pts));
    }
    for (PetscInt v = vStart; v < vEnd; ++v) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(s, v, &off));
      for (int d = 0; d < dim; ++d)
        u[off + d] = (inBlock[v - vStart] ? c.gap[d] : 0.0) + noise(rng);
    }
    PetscCall(VecRestoreArray(local, &u));
    PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, X));
  }
  // Every integration point must be in the intended state.
  states[0] = states[1] = states[2] = 0;
  *dilated = *past_limit = 0;
  const double limit = *c.dilation_limit ? std::atof(c.dilation_limit) : HUGE_VAL;
  PetscCall(problem.interfaces().visit(local, InterfaceRates{},
                                       [&](int, int, PetscInt, const InterfacePointState &st) {
                                         ++states[(int)st.response.state];
                                         *dilated += st.response.dilation > 0.0;
                                         *past_limit += st.response.updated.slip_plastic > limit;
                                       }));

  auto residual = [&](Vec Xg, Vec Fg) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(DMGlobalToLocal(dm, Xg, INSERT_VALUES, local));
    PetscCall(problem.residual(0.0, local, rate, ResidualMode{1.0, true}, flocal));
    PetscCall(VecSet(Fg, 0.0));
    PetscCall(DMLocalToGlobal(dm, flocal, ADD_VALUES, Fg));
    PetscFunctionReturn(0);
  };
  Mat J, Jd;
  PetscCall(DMCreateMatrix(dm, &J));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
  PetscCall(problem.jacobian(0.0, 0.0, local, rate, ResidualMode{1.0, true}, J));
  PetscCall(MatConvert(J, MATDENSE, MAT_INITIAL_MATRIX, &Jd));
  const PetscScalar *jd;
  PetscCall(MatDenseGetArrayRead(Jd, &jd));
  PetscInt n;
  PetscCall(VecGetLocalSize(X, &n));
  double err = 0.0, ref = 0.0;
  const double h = 1e-11; // gaps are ~1e-6: far from every kink
  PetscCall(poroseam::test_support::centralDifferences(
      X, Fp, Fm, residual, [&](PetscInt j) { return h; },
      [&](PetscInt i, PetscInt j, double fd) {
        err = std::max(err, std::fabs(fd - jd[i + j * n]));
        ref = std::max(ref, std::fabs(fd));
      }));
  *relative_error = err / ref;
  PetscCall(MatDenseRestoreArrayRead(Jd, &jd));
  PetscCall(MatDestroy(&Jd));
  PetscCall(MatDestroy(&J));
  for (Vec *v : {&local, &rate, &flocal, &X, &Fp, &Fm})
    PetscCall(VecDestroy(v));
  PetscCall(problem.release());
  PetscCall(DMDestroy(&dm));
  PetscCall(PetscOptionsClear(nullptr));
  PetscFunctionReturn(0);
}

} // namespace

class InterfaceJacobian : public ::testing::TestWithParam<Case> {};

TEST_P(InterfaceJacobian, MatchesFiniteDifferences)
{
  const Case c = GetParam();
  double rel = 1.0;
  int states[3], dilated, past_limit;
  ASSERT_EQ(compare(c, &rel, states, &dilated, &past_limit), 0);
  std::printf("%s: open %d, stick %d, slip %d points; max |J - J_fd| / max |J_fd| = %.2e\n", c.name,
              states[0], states[1], states[2], rel);
  EXPECT_EQ(states[(int)c.expected], states[0] + states[1] + states[2])
      << "not every integration point is in the intended state";
  EXPECT_LT(rel, 1e-6);
  const int all = states[0] + states[1] + states[2];
  EXPECT_EQ(dilated, std::atof(c.dilation_angle) > 0.0 ? all : 0) << "points that dilate";
  EXPECT_EQ(past_limit, *c.dilation_limit ? all : 0) << "points past the dilation limit";
}

// Contact pressure K_N 1e-6 = 1e4 Pa, friction limit 5e3 Pa; stick: K_T g_T = 500 Pa;
// slip: K_T g_T = 5e4 Pa; open: gap +1e-6.
INSTANTIATE_TEST_SUITE_P(States, InterfaceJacobian,
                         ::testing::Values(Case{"stick2d_gauss",
                                                "block_on_base_2d.geo",
                                                "gauss",
                                                {1e-7, -1e-6, 0},
                                                physics::ContactState::stick},
                                           Case{"slip2d_gauss",
                                                "block_on_base_2d.geo",
                                                "gauss",
                                                {1e-5, -1e-6, 0},
                                                physics::ContactState::slip},
                                           Case{"slip2d_nodal",
                                                "block_on_base_2d.geo",
                                                "nodal",
                                                {-1e-5, -1e-6, 0},
                                                physics::ContactState::slip},
                                           Case{"open2d_gauss",
                                                "block_on_base_2d.geo",
                                                "gauss",
                                                {1e-5, 1e-6, 0},
                                                physics::ContactState::open},
                                           // 3D on a coarse mesh: the dense check costs n^2.
                                           Case{"stick3d_gauss",
                                                "block_on_base_3d.geo",
                                                "gauss",
                                                {1e-7, -5e-8, -1e-6},
                                                physics::ContactState::stick,
                                                12.0},
                                           Case{"slip3d_gauss",
                                                "block_on_base_3d.geo",
                                                "gauss",
                                                {1e-5, -7e-6, -1e-6},
                                                physics::ContactState::slip,
                                                12.0},
                                           Case{"slip3d_nodal_tet",
                                                "block_on_base_3d_tet.geo",
                                                "nodal",
                                                {-6e-6, 9e-6, -1e-6},
                                                physics::ContactState::slip,
                                                12.0},
                                           Case{"open3d_gauss",
                                                "block_on_base_3d.geo",
                                                "gauss",
                                                {1e-5, 2e-6, 1e-6},
                                                physics::ContactState::open,
                                                12.0},
                                           // Shear dilation, psi = 10 deg: the slip of the step
                                           // (7.7e-6 m in 2D) lifts the pressure; with a limit
                                           // of 3e-6 m it is reached within the step.
                                           Case{"slip2d_gauss_dilatant",
                                                "block_on_base_2d.geo",
                                                "gauss",
                                                {1e-5, -1e-6, 0},
                                                physics::ContactState::slip,
                                                1.0,
                                                "10"},
                                           Case{"slip2d_nodal_dilatant",
                                                "block_on_base_2d.geo",
                                                "nodal",
                                                {-1e-5, -1e-6, 0},
                                                physics::ContactState::slip,
                                                1.0,
                                                "10"},
                                           Case{"slip2d_gauss_dilation_limit",
                                                "block_on_base_2d.geo",
                                                "gauss",
                                                {1e-5, -1e-6, 0},
                                                physics::ContactState::slip,
                                                1.0,
                                                "10",
                                                "3e-6"},
                                           Case{"slip3d_gauss_dilatant",
                                                "block_on_base_3d.geo",
                                                "gauss",
                                                {1e-5, -7e-6, -1e-6},
                                                physics::ContactState::slip,
                                                12.0,
                                                "10"},
                                           Case{"slip3d_nodal_tet_dilatant",
                                                "block_on_base_3d_tet.geo",
                                                "nodal",
                                                {-6e-6, 9e-6, -1e-6},
                                                physics::ContactState::slip,
                                                12.0,
                                                "25"}),
                         [](const auto &info) { return std::string(info.param.name); });
