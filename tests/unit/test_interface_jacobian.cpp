// The assembled Jacobian of a mesh with a zero-thickness interface against central finite
// differences of the assembled residual, with the interface in stick, slip and open states,
// and sliding with shear dilation (below and reaching the dilation limit).
// The mesh (a block on a base) is split into cohesive cells exactly as a run does it; the
// block is displaced relative to the base by a gap well inside each regime, plus a small
// random perturbation so that no state is special.
#include "meshed_problem.hpp"

#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <random>

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

using test_support::setOption;

PetscErrorCode compare(const Case &c, double *relative_error, int *states, int *dilated,
                       int *past_limit)
{
  test_support::MeshedProblem b;
  PetscFunctionBeginUser;
  PetscCall(test_support::setBlockOnBaseOptions(c.mesh, false));
  PetscCall(setOption("-interface_contact_integration", c.integration));
  PetscCall(setOption("-interface_contact_dilation_angle", c.dilation_angle));
  if (*c.dilation_limit)
    PetscCall(setOption("-interface_contact_dilation_limit", c.dilation_limit));
  PetscCall(b.create(c.size_factor));
  const int dim = b.dim;

  // State: block vertices (above the contact plane, or on its block side) moved by the gap.
  PetscCall(VecSet(b.rate, 0.0));
  {
    // Side of each vertex: vertices of block cells get the gap.
    PetscSection s;
    PetscCall(DMGetLocalSection(b.dm, &s));
    PetscScalar *u;
    PetscCall(VecSet(b.local, 0.0));
    PetscCall(VecGetArray(b.local, &u));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-1e-9, 1e-9);
    PetscInt pStart, pEnd, vStart, vEnd;
    PetscCall(DMPlexGetChart(b.dm, &pStart, &pEnd));
    PetscCall(DMPlexGetDepthStratum(b.dm, 0, &vStart, &vEnd));
    std::vector<char> inBlock;
    PetscCall(b.markRegion("block", &inBlock));
    for (PetscInt v = vStart; v < vEnd; ++v) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(s, v, &off));
      for (int d = 0; d < dim; ++d)
        u[off + d] = (inBlock[v - pStart] ? c.gap[d] : 0.0) + noise(rng);
    }
    PetscCall(VecRestoreArray(b.local, &u));
    PetscCall(DMLocalToGlobal(b.dm, b.local, INSERT_VALUES, b.X));
  }
  // Every integration point must be in the intended state.
  states[0] = states[1] = states[2] = 0;
  *dilated = *past_limit = 0;
  const double limit = *c.dilation_limit ? std::atof(c.dilation_limit) : HUGE_VAL;
  PetscCall(b.problem.interfaces().visit(b.local, InterfaceRates{},
                                         [&](int, int, PetscInt, const InterfacePointState &st) {
                                           ++states[(int)st.response.state];
                                           *dilated += st.response.dilation > 0.0;
                                           *past_limit += st.response.updated.slip_plastic > limit;
                                         }));

  const ResidualMode mode{1.0, true};
  auto noRates = []() -> PetscErrorCode { return 0; };
  double err = 0.0, ref = 0.0;
  const double h = 1e-11; // gaps are ~1e-6: far from every kink
  PetscCall(b.compareWithDifferences(
      0.0, 0.0, mode, noRates, [&](PetscInt) { return h; },
      [&](PetscInt, PetscInt, double fd, double jij) {
        err = std::max(err, std::fabs(fd - jij));
        ref = std::max(ref, std::fabs(fd));
      }));
  *relative_error = err / ref;
  PetscCall(b.destroy());
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
