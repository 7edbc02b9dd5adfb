// Quadratic interfaces (-displacement_order 2): the assembled Jacobian of a mesh with a
// zero-thickness interface between P2 / Q2 bodies against central finite differences of the
// assembled residual, block by block over the fields u, p and p3 (the mass rows are many orders
// smaller than the force rows). The cohesive cells take the faces' node basis (3 nodes on a
// segment, 6 on a triangle, 9 on a quadrilateral) for the gap; the pressures and p3 stay
// linear. Mechanics: stick, slip (with and without shear dilation) and open, Gauss and nodal
// rules, 2D and 3D (hexahedra and tetrahedra). Flow: open and closed, with rates from a
// previous state as in a backward Euler or BDF2 step, so that storage is live.
// The block is displaced relative to the base by a gap inside each regime, at every point that
// carries a displacement node (vertices, edges, faces), plus a small random perturbation.
#include "meshed_problem.hpp"
#include "poroseam/mesh_points.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace poroseam;

namespace {

struct QuadCase {
  const char *name;
  const char *mesh;
  double size_factor;
  const char *integration;
  double gap[3]; ///< block displacement (x, y[, z]); the normal is the last axis
  int expected;  ///< physics::ContactState of every point; -1: open (flow) or closed (flow)
  bool flow = false;
  double rate_factor = 1.0;         ///< a: dx/dt = a (x - x_prev) / dt (flow cases)
  const char *dilation_angle = "0"; ///< psi [deg]
  bool axisymmetric = false;        ///< x = r: ring weights 2 pi r (the left side is the axis)
  const char *geometry_order = "1"; ///< -mesh_geometry_order (2: curved faces and cells)
};

using test_support::setOption;

struct Result {
  double max_error[3][3] = {{0}};
  double max_entry[3][3] = {{0}};
  int states[3] = {0, 0, 0};
  int dilated = 0, points = 0, nodes = 0, dim = 0;
};

PetscErrorCode compare(const QuadCase &c, Result *res)
{
  test_support::MeshedProblem b;
  PetscFunctionBeginUser;
  PetscCall(test_support::setBlockOnBaseOptions(c.mesh, c.flow));
  PetscCall(setOption("-displacement_order", "2"));
  PetscCall(setOption("-mesh_geometry_order", c.geometry_order));
  if (c.axisymmetric) PetscCall(setOption("-axisymmetric", "true"));
  PetscCall(setOption("-interface_contact_integration", c.integration));
  PetscCall(setOption("-interface_contact_dilation_angle", c.dilation_angle));
  if (c.flow) {
    PetscCall(setOption("-gravity", "9.81"));
    PetscCall(setOption("-interface_contact_flow", "true"));
    PetscCall(setOption("-interface_contact_D0", "1e-5"));
    PetscCall(setOption("-interface_contact_T1", "1e-8"));
    PetscCall(setOption("-interface_contact_T2", "5e-9"));
  }
  PetscCall(b.create(c.size_factor));
  res->dim = b.dim;
  Vec local = b.local, rate = b.rate, previous = b.previous;

  PetscSection s;
  PetscCall(DMGetLocalSection(b.dm, &s));
  // Every point of the closure of the block's cells (vertices, edges, faces, cells) that
  // carries displacement gets the gap; pressures random values.
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(b.dm, &pStart, &pEnd));
  std::vector<char> inBlock;
  PetscCall(b.markRegion("block", &inBlock));
  std::mt19937 rng(13);
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
    PetscInt numFields;
    PetscCall(PetscSectionGetNumFields(s, &numFields));
    for (PetscInt pt = pStart; pt < pEnd; ++pt)
      for (int f = 0; f < numFields; ++f) {
        PetscInt dof, off;
        PetscCall(PetscSectionGetFieldDof(s, pt, f, &dof));
        if (!dof) continue;
        PetscCall(PetscSectionGetFieldOffset(s, pt, f, &off));
        if (f == 0) ++res->nodes;
        for (PetscInt k = 0; k < dof; ++k) {
          fieldOfLocal[off + k] = f;
          if (f == 0) {
            const double gap = inBlock[pt - pStart] ? c.gap[k] : 0.0;
            u[off + k] = gap + 1e-9 * noise(rng);
            up[off + k] = 0.5 * gap + 1e-9 * noise(rng);
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
  PetscCall(b.problem.interfaces().visit(local, InterfaceRates{c.flow ? rate : nullptr, dt},
                                         [&](int, int, PetscInt, const InterfacePointState &st) {
                                           ++res->states[(int)st.response.state];
                                           res->dilated += st.response.dilation > 0.0;
                                           ++res->points;
                                         }));
  const double mass_scale = c.flow ? -dt * b.problem.massBalanceScale() : 1.0;
  const ResidualMode mode{mass_scale, true, dt};
  std::vector<int> field;
  PetscCall(b.globalFields(fieldOfLocal, &field));
  PetscCall(b.compareBlocks(
      0.0, c.rate_factor / dt, mode, rates,
      [&](PetscInt j) {
        return field[j] == 0 ? 1e-11 : 1e-2; /* m, Pa: far from every kink */
      },
      field, res->max_error, res->max_entry));
  PetscCall(b.destroy());
  PetscFunctionReturn(0);
}

} // namespace

class QuadInterfaceJacobian : public ::testing::TestWithParam<QuadCase> {};

TEST_P(QuadInterfaceJacobian, EveryBlockMatchesFiniteDifferences)
{
  const QuadCase c = GetParam();
  Result r;
  ASSERT_EQ(compare(c, &r), 0);
  std::printf("%s: %d displacement nodes; open %d, stick %d, slip %d of %d points, %d dilating\n",
              c.name, r.nodes, r.states[0], r.states[1], r.states[2], r.points, r.dilated);
  ASSERT_GT(r.points, 0);
  if (c.expected >= 0)
    EXPECT_EQ(r.states[c.expected], r.points) << "not every point is in the intended state";
  EXPECT_EQ(r.dilated, std::atof(c.dilation_angle) > 0.0 ? r.points : 0);
  const char *names[3] = {"u", "p", "p3"};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (r.max_entry[i][j] == 0.0) continue;
      const double rel = r.max_error[i][j] / r.max_entry[i][j];
      std::printf("  block %s-%s: max |J - J_fd| / max |J_fd| = %.2e\n", names[i], names[j], rel);
      EXPECT_LT(rel, 1e-6) << names[i] << "-" << names[j];
    }
  if (c.flow) {
    EXPECT_GT(r.max_entry[2][2], 0.0);
    EXPECT_GT(r.max_entry[0][2], 0.0);
    EXPECT_GT(r.max_entry[2][1], 0.0);
    if (c.gap[r.dim - 1] > 0.0)
      EXPECT_GT(r.max_entry[2][0], 0.0) << "storage and conductivity follow the opening";
  }
}

using S = physics::ContactState;
// Contact pressure K_N 1e-6 = 1e4 Pa, friction limit 5e3 Pa; stick: K_T g_T = 500 Pa;
// slip: K_T g_T = 5e4 Pa; open: gap +1e-6. 3D on coarse meshes: the dense check costs n^2.
INSTANTIATE_TEST_SUITE_P(
    Order2, QuadInterfaceJacobian,
    ::testing::Values(
        QuadCase{
            "stick2d_gauss", "block_on_base_2d.geo", 2.0, "gauss", {1e-7, -1e-6, 0}, (int)S::stick},
        QuadCase{
            "slip2d_gauss", "block_on_base_2d.geo", 2.0, "gauss", {1e-5, -1e-6, 0}, (int)S::slip},
        QuadCase{
            "slip2d_nodal", "block_on_base_2d.geo", 2.0, "nodal", {-1e-5, -1e-6, 0}, (int)S::slip},
        QuadCase{
            "open2d_gauss", "block_on_base_2d.geo", 2.0, "gauss", {1e-5, 1e-6, 0}, (int)S::open},
        QuadCase{"slip2d_tri_nodal_dilatant",
                 "block_on_base_2d_tri.geo",
                 2.0,
                 "nodal",
                 {1e-5, -1e-6, 0},
                 (int)S::slip,
                 false,
                 1.0,
                 "10"},
        QuadCase{"stick3d_nodal",
                 "block_on_base_3d.geo",
                 12.0,
                 "nodal",
                 {1e-7, -5e-8, -1e-6},
                 (int)S::stick},
        QuadCase{"slip3d_gauss_dilatant",
                 "block_on_base_3d.geo",
                 12.0,
                 "gauss",
                 {1e-5, -7e-6, -1e-6},
                 (int)S::slip,
                 false,
                 1.0,
                 "10"},
        QuadCase{"open3d_gauss",
                 "block_on_base_3d.geo",
                 12.0,
                 "gauss",
                 {1e-5, 2e-6, 1e-6},
                 (int)S::open},
        QuadCase{"slip3d_tet_gauss",
                 "block_on_base_3d_tet.geo",
                 12.0,
                 "gauss",
                 {-6e-6, 9e-6, -1e-6},
                 (int)S::slip},
        // Flow: open (storage and conductivity follow the opening) and closed, sliding with
        // dilation; backward Euler and BDF2 rates.
        QuadCase{"flow_open2d", "block_on_base_2d.geo", 2.0, "gauss", {0, 2e-6, 0}, -1, true},
        QuadCase{"flow_open2d_bdf2_nodal",
                 "block_on_base_2d.geo",
                 2.0,
                 "nodal",
                 {0, 2e-6, 0},
                 -1,
                 true,
                 1.5},
        QuadCase{"flow_sliding2d_dilatant",
                 "block_on_base_2d.geo",
                 2.0,
                 "gauss",
                 {1e-5, -2e-6, 0},
                 (int)S::slip,
                 true,
                 1.0,
                 "10"},
        QuadCase{"flow_open3d", "block_on_base_3d.geo", 12.0, "gauss", {0, 0, 2e-6}, -1, true},
        QuadCase{
            "flow_open3d_tet", "block_on_base_3d_tet.geo", 12.0, "gauss", {0, 0, 2e-6}, -1, true},
        // Axisymmetric (x = r, the block's and the base's left sides on the axis): the same
        // terms with the ring weights 2 pi r, Gauss points and the lumped nodal weights (the
        // axis vertex's is zero at order 2). Stick, slip, open; flow open and sliding.
        QuadCase{"axi_stick_gauss",
                 "block_on_base_2d.geo",
                 2.0,
                 "gauss",
                 {1e-7, -1e-6, 0},
                 (int)S::stick,
                 false,
                 1.0,
                 "0",
                 true},
        QuadCase{"axi_slip_nodal",
                 "block_on_base_2d.geo",
                 2.0,
                 "nodal",
                 {-1e-5, -1e-6, 0},
                 (int)S::slip,
                 false,
                 1.0,
                 "0",
                 true},
        QuadCase{"axi_slip_tri_gauss_dilatant",
                 "block_on_base_2d_tri.geo",
                 2.0,
                 "gauss",
                 {1e-5, -1e-6, 0},
                 (int)S::slip,
                 false,
                 1.0,
                 "10",
                 true},
        QuadCase{"axi_open_nodal",
                 "block_on_base_2d.geo",
                 2.0,
                 "nodal",
                 {1e-5, 1e-6, 0},
                 (int)S::open,
                 false,
                 1.0,
                 "0",
                 true},
        QuadCase{"axi_flow_open_bdf2_nodal",
                 "block_on_base_2d.geo",
                 2.0,
                 "nodal",
                 {0, 2e-6, 0},
                 -1,
                 true,
                 1.5,
                 "0",
                 true},
        QuadCase{"axi_flow_sliding_dilatant",
                 "block_on_base_2d.geo",
                 2.0,
                 "gauss",
                 {1e-5, -2e-6, 0},
                 (int)S::slip,
                 true,
                 1.0,
                 "10",
                 true},
        QuadCase{"axi_flow_closed_nodal",
                 "block_on_base_2d.geo",
                 2.0,
                 "nodal",
                 {1e-7, -2e-6, 0},
                 (int)S::stick,
                 true,
                 1.0,
                 "0",
                 true},
        // Curved faces (-mesh_geometry_order 2): the contact is a circular arc, each point with
        // its own frame; sliding (nodal rule) and open with flow.
        QuadCase{"slip2d_curved_nodal",
                 "block_on_arc_2d.geo",
                 2.0,
                 "nodal",
                 {2.5e-5, -1e-5, 0},
                 (int)S::slip,
                 false,
                 1.0,
                 "0",
                 false,
                 "2"},
        QuadCase{"flow_open2d_curved",
                 "block_on_arc_2d.geo",
                 2.0,
                 "gauss",
                 {0, 2e-6, 0},
                 (int)S::open,
                 true,
                 1.0,
                 "0",
                 false,
                 "2"}),
    [](const auto &info) { return std::string(info.param.name); });

// Patch test of the kinematics: each body is given a quadratic displacement field at every
// displacement node (the P2 / Q2 interpolant of a quadratic is the quadratic itself on these
// straight-sided meshes), so the jump across the interface is a quadratic opening and slip.
// Every integration point must see exactly that jump (round-off) in its local frame, and be in
// the intended state: stick, slip, open.
namespace {

struct JumpCase {
  const char *name;
  const char *mesh;
  double size_factor;
  const char *integration;
  double normal; ///< mean normal gap [m] (negative: contact)
  double slip;   ///< mean slip along the first tangent axis [m]
  int expected;  ///< physics::ContactState
};

/// A quadratic field of the position with mean `mean` and amplitude `amp` (quadratic terms in
/// every in-plane coordinate and their products), different per component k.
double quadratic(const double x[3], int dim, int k, double mean, double amp)
{
  const double a = x[0] - 0.5, b = dim == 3 ? x[1] - 0.5 : 0.0;
  return mean + amp * (0.7 * a * a - 0.4 * a * b + 0.3 * b * b + (0.2 + 0.1 * k) * a - 0.1 * b);
}

PetscErrorCode jumps(const JumpCase &c, double *max_error, double *max_gap, int states[3],
                     int *points)
{
  test_support::MeshedProblem b;
  PetscFunctionBeginUser;
  PetscCall(test_support::setBlockOnBaseOptions(c.mesh, false));
  PetscCall(setOption("-displacement_order", "2"));
  PetscCall(setOption("-interface_contact_integration", c.integration));
  PetscCall(b.create(c.size_factor));
  DM dm = b.dm;
  const int dim = b.dim;
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  std::vector<char> inBlock;
  PetscCall(b.markRegion("block", &inBlock));
  // The base moves by a quadratic field too, so that the jump is a difference of two.
  const int normal_axis = dim - 1;
  auto field = [&](const double x[3], bool block, int k) {
    const double base = quadratic(x, dim, k + 3, 0.0, 1e-6);
    if (!block) return base;
    const double mean = k == normal_axis ? c.normal : k == 0 ? c.slip : 0.2 * c.slip;
    return base + quadratic(x, dim, k, mean, 0.5 * std::fabs(k == normal_axis ? c.normal : c.slip));
  };
  Vec local = b.local, coords;
  PetscSection s, cs;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  {
    PetscScalar *u;
    const PetscScalar *xa;
    PetscCall(VecSet(local, 0.0));
    PetscCall(VecGetArray(local, &u));
    PetscCall(VecGetArrayRead(coords, &xa));
    for (PetscInt pt = pStart; pt < pEnd; ++pt) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetFieldDof(s, pt, 0, &dof));
      if (!dof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, pt, 0, &off));
      double x[3];
      PetscCall(poroseam::displacementNodeLocation(dm, cs, xa, pt, dim, x));
      for (int k = 0; k < dim; ++k)
        u[off + k] = field(x, inBlock[pt - pStart], k);
    }
    PetscCall(VecRestoreArrayRead(coords, &xa));
    PetscCall(VecRestoreArray(local, &u));
  }
  *max_error = *max_gap = 0.0;
  states[0] = states[1] = states[2] = 0;
  *points = 0;
  PetscCall(b.problem.interfaces().visit(
      local, InterfaceRates{}, [&](int, int, PetscInt, const InterfacePointState &st) {
        double jump[3] = {0, 0, 0}, exact[3] = {0, 0, 0};
        for (int k = 0; k < dim; ++k)
          jump[k] = field(st.x, true, k) - field(st.x, false, k);
        for (int i = 0; i < dim; ++i)
          for (int k = 0; k < dim; ++k)
            exact[i] += st.frame[i][k] * jump[k];
        const double got[3] = {st.gap_normal, st.gap_tangential[0], st.gap_tangential[1]};
        for (int i = 0; i < dim; ++i) {
          *max_error = std::max(*max_error, std::fabs(got[i] - exact[i]));
          *max_gap = std::max(*max_gap, std::fabs(exact[i]));
        }
        ++states[(int)st.response.state];
        ++*points;
      }));
  PetscCall(b.destroy());
  PetscFunctionReturn(0);
}

} // namespace

class QuadInterfaceJumps : public ::testing::TestWithParam<JumpCase> {};

TEST_P(QuadInterfaceJumps, QuadraticOpeningAndSlipReproduced)
{
  const JumpCase c = GetParam();
  double err = 1.0, gap = 0.0;
  int states[3], points = 0;
  ASSERT_EQ(jumps(c, &err, &gap, states, &points), 0);
  std::printf("%s: open %d, stick %d, slip %d of %d points; max |g - g_exact| / max |g| = %.2e\n",
              c.name, states[0], states[1], states[2], points, err / gap);
  ASSERT_GT(points, 0);
  EXPECT_EQ(states[c.expected], points) << "not every point is in the intended state";
  EXPECT_LT(err / gap, 1e-12);
}

// Contact pressure about K_N 1e-6 = 1e4 Pa, friction limit 5e3 Pa: stick at K_T 1e-7 = 500 Pa,
// slip at K_T 1e-5 = 5e4 Pa; open at +1e-6 m.
INSTANTIATE_TEST_SUITE_P(
    Order2, QuadInterfaceJumps,
    ::testing::Values(
        JumpCase{"stick2d_gauss", "block_on_base_2d.geo", 1.0, "gauss", -1e-6, 1e-7, (int)S::stick},
        JumpCase{"slip2d_nodal", "block_on_base_2d.geo", 1.0, "nodal", -1e-6, 1e-5, (int)S::slip},
        JumpCase{"open2d_gauss", "block_on_base_2d.geo", 1.0, "gauss", 1e-6, 1e-5, (int)S::open},
        JumpCase{"slip2d_tri_gauss", "block_on_base_2d_tri.geo", 1.0, "gauss", -1e-6, 1e-5,
                 (int)S::slip},
        JumpCase{"stick3d_gauss", "block_on_base_3d.geo", 4.0, "gauss", -1e-6, 1e-7, (int)S::stick},
        JumpCase{"slip3d_nodal", "block_on_base_3d.geo", 4.0, "nodal", -1e-6, 1e-5, (int)S::slip},
        JumpCase{"open3d_tet_gauss", "block_on_base_3d_tet.geo", 4.0, "gauss", 1e-6, 1e-5,
                 (int)S::open},
        JumpCase{"slip3d_tet_gauss", "block_on_base_3d_tet.geo", 4.0, "gauss", -1e-6, 1e-5,
                 (int)S::slip}),
    [](const auto &info) { return std::string(info.param.name); });
