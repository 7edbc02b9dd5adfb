// The assembled Jacobian of a hydro-mechanical interface (three-node flow between two porous
// bodies, with gravity) against central finite differences of the residual, block by block
// over the fields u, p and p3: the mass rows are many orders smaller than the force rows, so a
// single matrix norm would hide them. Rates come from a previous state, as in a time step
// (dx/dt = a (x - x_prev)/dt, shift a/dt; a = 1 is backward Euler, a = 1.5 a BDF2 step whose
// history combination is x_prev), so the storage term dh/dt is live. The gap is open
// (aperture and storage follow the opening) or closed (h = D0), away from the kinks; with
// a = 1.5 the back-dated gap g - dt dg/dt of the storage secant is open or, in the "opens"
// cases, closed while the gap is open. Closed and sliding with shear dilation, h = D0 + d with
// the dilation d following every gap component.
#include "meshed_problem.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace poroseam;

namespace {

struct FlowCase {
  const char *name;
  const char *mesh;
  double size_factor;
  double gap_normal;                ///< block displacement along the last axis (+: opening)
  double t2;                        ///< transmissivity to side 2 (0: impervious)
  double rate_factor = 1.0;         ///< a: dx/dt = a (x - x_prev) / dt, shift a / dt
  double previous_fraction = 0.5;   ///< gap of x_prev as a fraction of gap_normal
  double gap_tangential = 0.0;      ///< block displacement along the first axis (slip)
  const char *dilation_angle = "0"; ///< psi [deg]
};

using test_support::setOption;

struct Result {
  double max_error[3][3] = {{0}};
  double max_entry[3][3] = {{0}};
  int open = 0, closed = 0;
  int back_closed = 0; ///< open points whose back-dated gap g - dt dg/dt is closed
  int dilating = 0;    ///< closed points sliding with dilation (h = D0 + d, d > 0)
};

PetscErrorCode compare(const FlowCase &c, Result *res)
{
  test_support::MeshedProblem b;
  PetscFunctionBeginUser;
  PetscCall(test_support::setBlockOnBaseOptions(c.mesh, true));
  PetscCall(setOption("-gravity", "9.81"));
  PetscCall(setOption("-interface_contact_dilation_angle", c.dilation_angle));
  PetscCall(setOption("-interface_contact_flow", "true"));
  PetscCall(setOption("-interface_contact_D0", "1e-5"));
  PetscCall(setOption("-interface_contact_T1", "1e-8"));
  char t2[32];
  std::snprintf(t2, sizeof(t2), "%g", c.t2); // std::to_string would print 5e-9 as 0.000000
  PetscCall(setOption("-interface_contact_T2", t2));
  PetscCall(b.create(c.size_factor));
  const int dim = b.dim;
  Vec local = b.local, rate = b.rate, previous = b.previous;

  PetscSection s;
  PetscCall(DMGetLocalSection(b.dm, &s));
  // Block vertices (closure of block cells) get the gap; pressures get random values.
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(b.dm, &pStart, &pEnd));
  std::vector<char> inBlock;
  PetscCall(b.markRegion("block", &inBlock));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  const double dt = 0.5;
  std::vector<int> fieldOfLocal;
  {
    PetscScalar *u, *up;
    PetscCall(b.problem.initialState(local));
    PetscCall(VecGetArray(local, &u));
    PetscCall(VecGetArray(previous, &up));
    PetscInt nl;
    PetscCall(VecGetLocalSize(local, &nl));
    fieldOfLocal.assign(nl, 0);
    for (PetscInt pt = pStart; pt < pEnd; ++pt)
      for (int f = 0; f < 3; ++f) {
        PetscInt dof, off;
        PetscCall(PetscSectionGetFieldDof(s, pt, f, &dof));
        if (!dof) continue;
        PetscCall(PetscSectionGetFieldOffset(s, pt, f, &off));
        for (PetscInt k = 0; k < dof; ++k) {
          fieldOfLocal[off + k] = f;
          if (f == 0) {
            const bool last = k == dim - 1;
            const double target = last ? c.gap_normal : k == 0 ? c.gap_tangential : 0.0;
            const double gap = inBlock[pt - pStart] ? target : 0.0;
            u[off + k] = gap + 1e-9 * noise(rng);
            up[off + k] = c.previous_fraction * gap + 1e-9 * noise(rng);
          } else {
            u[off + k] += 1e4 * noise(rng); // hydrostatic plus a random excess
            up[off + k] = u[off + k] - 1e3 * noise(rng);
          }
        }
      }
    PetscCall(VecRestoreArray(previous, &up));
    PetscCall(VecRestoreArray(local, &u));
    PetscCall(DMLocalToGlobal(b.dm, local, INSERT_VALUES, b.X));
  }
  auto rates = [&]() { return b.ratesFromPrevious(c.rate_factor / dt); };
  PetscCall(rates());
  PetscCall(b.problem.interfaces().visit(
      local, InterfaceRates{rate, dt}, [&](int, int, PetscInt, const InterfacePointState &st) {
        (st.opening > 0.0 ? res->open : res->closed)++;
        if (st.opening == 0.0 && st.response.dilation > 0.0 &&
            std::fabs(st.aperture - 1e-5 - st.response.dilation) < 1e-12 * st.aperture)
          res->dilating++;
        // The back-dated gap is closed when the whole opening is stored in this step.
        if (st.opening > 0.0 && std::fabs(st.aperture_rate * dt - st.opening) < 1e-3 * st.opening)
          res->back_closed++;
      }));
  const ResidualMode mode{-dt * b.problem.massBalanceScale(), true, dt};
  // Field of each global dof.
  std::vector<int> field;
  PetscCall(b.globalFields(fieldOfLocal, &field));
  PetscCall(b.compareBlocks(
      0.0, c.rate_factor / dt, mode, rates,
      [&](PetscInt j) {
        return field[j] == 0 ? 1e-11 : 1e-2 /* m, Pa: far below every kink distance */;
      },
      field, res->max_error, res->max_entry));
  PetscCall(b.destroy());
  PetscFunctionReturn(0);
}

} // namespace

class InterfaceFlowJacobian : public ::testing::TestWithParam<FlowCase> {};

TEST_P(InterfaceFlowJacobian, EveryBlockMatchesFiniteDifferences)
{
  const FlowCase c = GetParam();
  Result r;
  ASSERT_EQ(compare(c, &r), 0);
  std::printf("%s: %d open and %d closed points (%d of them sliding with dilation), %d open with "
              "the back-dated gap closed\n",
              c.name, r.open, r.closed, r.dilating, r.back_closed);
  EXPECT_EQ(r.dilating, c.gap_tangential != 0.0 ? r.closed : 0);
  if (c.previous_fraction < 0.0 && c.gap_normal > 0.0)
    EXPECT_EQ(r.back_closed, r.open) << "every point opens in this step";
  else
    EXPECT_EQ(r.back_closed, 0);
  if (c.gap_normal > 0)
    EXPECT_EQ(r.closed, 0);
  else
    EXPECT_EQ(r.open, 0);
  const char *names[3] = {"u", "p", "p3"};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (r.max_entry[i][j] == 0.0) continue; // no coupling (e.g. u-p3 is one way when closed)
      const double rel = r.max_error[i][j] / r.max_entry[i][j];
      std::printf("  block %s-%s: max |J - J_fd| / max |J_fd| = %.2e\n", names[i], names[j], rel);
      EXPECT_LT(rel, 1e-6) << names[i] << "-" << names[j];
    }
  // The couplings the element must have.
  EXPECT_GT(r.max_entry[2][2], 0.0);
  EXPECT_GT(r.max_entry[0][2], 0.0);
  EXPECT_GT(r.max_entry[2][1], 0.0);
  if (c.gap_normal > 0 || c.gap_tangential != 0.0)
    EXPECT_GT(r.max_entry[2][0], 0.0) << "storage and conductivity follow the opening/dilation";
}

INSTANTIATE_TEST_SUITE_P(
    States, InterfaceFlowJacobian,
    ::testing::Values(FlowCase{"open2d", "block_on_base_2d.geo", 2.0, 2e-6, 5e-9},
                      FlowCase{"closed2d", "block_on_base_2d.geo", 2.0, -2e-6, 5e-9},
                      FlowCase{"open2d_impervious_side2", "block_on_base_2d.geo", 2.0, 2e-6, 0.0},
                      FlowCase{"open3d", "block_on_base_3d.geo", 12.0, 2e-6, 5e-9},
                      // BDF2-like rates (shift 1.5/dt): back-dated gap 1.5 g_prev - 0.5 g open...
                      FlowCase{"open2d_bdf2", "block_on_base_2d.geo", 2.0, 2e-6, 5e-9, 1.5, 0.5},
                      FlowCase{"closed2d_bdf2", "block_on_base_2d.geo", 2.0, -2e-6, 5e-9, 1.5, 0.5},
                      // ... and closed while the gap is open (the step in which it opens).
                      FlowCase{"opens2d_bdf2", "block_on_base_2d.geo", 2.0, 2e-6, 5e-9, 1.5, -0.5},
                      FlowCase{"opens3d_bdf2", "block_on_base_3d.geo", 12.0, 2e-6, 5e-9, 1.5, -0.5},
                      FlowCase{"opens2d_be", "block_on_base_2d.geo", 2.0, 2e-6, 5e-9, 1.0, -0.5},
                      // Closed and sliding with shear dilation (psi = 10 deg): h = D0 + d, with d
                      // following the normal and tangential gaps; backward Euler and BDF2 rates.
                      FlowCase{"sliding2d_dilatant", "block_on_base_2d.geo", 2.0, -2e-6, 5e-9, 1.0,
                               0.5, 1e-5, "10"},
                      FlowCase{"sliding2d_dilatant_bdf2", "block_on_base_2d.geo", 2.0, -2e-6, 5e-9,
                               1.5, 0.5, -1e-5, "10"},
                      FlowCase{"sliding3d_dilatant", "block_on_base_3d.geo", 12.0, -2e-6, 5e-9, 1.0,
                               0.5, 1e-5, "10"}),
    [](const auto &info) { return std::string(info.param.name); });
