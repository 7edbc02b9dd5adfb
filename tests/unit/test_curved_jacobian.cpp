// The assembled Jacobian of the bulk cells on curved cells (-mesh_geometry_order 2: the
// isoparametric Q2 / P2 map, docs/elements.md "Curved geometry") against central finite
// differences of the assembled residual, block by block (uu, up, pu, pp) as in
// test_biot_jacobian and test_plastic_jacobian. The bodies are the quarter annulus
// 1 <= r <= 2 m (meshes/thick_cylinder_plane.geo, _tri: triangles) and a slab of it in 3D
// (meshes/thick_cylinder_slab_3d.geo, _tet: tetrahedra), 2 cells through the wall: every cell
// has an edge (in 3D a face) on a circle or cylinder, so its map is genuinely curved (checked:
// second-order nodes up to 0.038 m off the straight-sided places). The tangent's weights,
// Jacobian inverse (the physical gradients of both bases) and the point's place (the
// axisymmetric radius) must be the curved cell's, as in the residual. By hand (not kept): the
// tangent's weight from the straight map fails every quadrilateral and hexahedral case by 3e-2
// to 8e-2, its gradients from the straight map by 1e-2 to 1e-1 (block uu or pp).
// Biot (gravity, Darcy flow, storage, coupling) in plane strain (quadrilaterals, triangles),
// axisymmetric and 3D (hexahedra, tetrahedra); Mohr-Coulomb (the skeleton law's tangent) on a
// face (plane strain, 3D) and the triaxial edge (axisymmetric), with committed plastic
// history: the displacement is affine in the nodes' curved places (so the strain is uniform
// on the isoparametric cells) plus a small random part, and every integration point is in one
// regime (checked through the committed yield states). Not the apex: a single region at the
// apex has a zero tangent, its uu block is round-off. One region, no initial stress:
// -initial_state geostatic refuses the annulus's sloping upper boundary.
#include "meshed_problem.hpp"
#include "poroseam/curved_nodes.hpp"
#include "poroseam/mesh_points.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>

using namespace poroseam;

namespace {

struct CurvedCase {
  const char *name;
  const char *mesh;     ///< in meshes/, meshed at -mesh_size_factor 2 (2 cells through the wall)
  const char *material; ///< biot or mohr_coulomb (region "ring")
  bool axisymmetric;    ///< x = r: the quarter annulus is the section of a ring around y
  int expected;         ///< physics::YieldState of every point (mohr_coulomb); -1: biot
  double strain[3][3];  ///< mohr_coulomb: u = strain x at every node's place
};

using test_support::setOption;

struct Result {
  double max_error[2][2] = {{0, 0}, {0, 0}};
  double max_entry[2][2] = {{0, 0}, {0, 0}};
  double curvature = 0.0; ///< max distance of a curved node from its straight-sided place [m]
  int cells = 0, lowest_state = 99, highest_state = -1;
  double lowest_plastic_strain = 1e300;
};

/// `u` = the initial state plus a displacement affine in the nodes' (curved) places,
/// `factor` strain x, and random parts of `noise` m (displacement) and `excess` Pa (pressure).
PetscErrorCode setState(DM dm, const Problem &problem, const std::vector<double> &places,
                        const std::vector<int> &field_of_local, const double strain[3][3], int dim,
                        double factor, double noise, double excess, std::mt19937 &rng, Vec u)
{
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(problem.initialState(u));
  PetscCall(VecGetArray(u, &a));
  for (size_t k = 0; k < field_of_local.size(); ++k)
    if (field_of_local[k] != kDisplacementField) a[k] += excess * r(rng);
  PetscSection s;
  PetscInt pStart, pEnd;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  for (PetscInt pt = pStart; pt < pEnd; ++pt) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetFieldDof(s, pt, kDisplacementField, &dof));
    if (!dof) continue;
    PetscCall(PetscSectionGetFieldOffset(s, pt, kDisplacementField, &off));
    for (int i = 0; i < dim; ++i) {
      double value = 0.0;
      for (int j = 0; j < dim; ++j)
        value += factor * strain[i][j] * places[off + j];
      a[off + i] += value + noise * r(rng);
    }
  }
  PetscCall(VecRestoreArray(u, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode compare(const CurvedCase &c, Result *res)
{
  test_support::MeshedProblem b;
  const bool plastic = c.expected >= 0;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  const std::string src = POROSEAM_SOURCE_DIR;
  PetscCall(setOption("-mesh", src + "/meshes/" + c.mesh));
  PetscCall(setOption("-displacement_order", "2"));
  PetscCall(setOption("-mesh_geometry_order", "2"));
  PetscCall(setOption("-regions", "ring"));
  if (c.axisymmetric) PetscCall(setOption("-axisymmetric", "true"));
  PetscCall(setOption("-region_ring_material", c.material));
  PetscCall(setOption("-region_ring_E", "2e7"));
  PetscCall(setOption("-region_ring_nu", "0.3"));
  PetscCall(setOption("-region_ring_rho_s", "2650"));
  PetscCall(setOption("-region_ring_porosity", "0.36"));
  PetscCall(setOption("-region_ring_permeability", "1e-11"));
  PetscCall(setOption("-region_ring_biot_alpha", "0.9"));
  PetscCall(setOption("-region_ring_storage", "1e-9"));
  PetscCall(setOption("-gravity", "9.81"));
  if (plastic) {
    PetscCall(setOption("-region_ring_cohesion", "5e3"));
    PetscCall(setOption("-region_ring_friction_angle", "30"));
    PetscCall(setOption("-region_ring_dilation_angle", "10"));
  }
  PetscCall(b.create(2.0));
  DM dm = b.dm;
  const int dim = b.dim;
  Problem &problem = b.problem;
  Vec local = b.local, previous = b.previous;
  {
    const CurvedNodes *nodes = curvedNodes(dm);
    PetscCheck(nodes, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no curved nodes on the mesh");
    const std::vector<double> &e = nodes->packed();
    for (size_t k = 0; k + CurvedNodes::kStride <= e.size(); k += CurvedNodes::kStride)
      res->curvature = std::max(res->curvature, std::hypot(e[k + 4] - e[k + 1], e[k + 5] - e[k + 2],
                                                           e[k + 6] - e[k + 3]));
    PetscInt cStart, cEnd;
    PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
    res->cells = (int)(cEnd - cStart);
  }

  // The field of every local and global dof.
  PetscSection s;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscInt nl, pStart, pEnd, numFields;
  PetscCall(VecGetLocalSize(local, &nl));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(PetscSectionGetNumFields(s, &numFields));
  std::vector<int> fieldOfLocal(nl, 0), field;
  for (PetscInt pt = pStart; pt < pEnd; ++pt)
    for (PetscInt f = 0; f < numFields; ++f) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetFieldDof(s, pt, f, &dof));
      PetscCall(PetscSectionGetFieldOffset(s, pt, f, &off));
      for (PetscInt k = 0; k < dof; ++k)
        fieldOfLocal[off + k] = (int)f;
    }
  PetscCall(b.globalFields(fieldOfLocal, &field));

  // The state: Biot random (displacements of 1e-3 m, pressures 1e4 Pa); Mohr-Coulomb
  // committed at 0.6 of the strain, evaluated at the full strain.
  std::vector<double> places;
  PetscCall(displacementNodePlaces(dm, places));
  std::mt19937 rng(42);
  const double dt = 0.37, t = 1.0;
  if (plastic) {
    PetscCall(
        setState(dm, problem, places, fieldOfLocal, c.strain, dim, 0.6, 0.0, 1e4, rng, previous));
    PetscCall(problem.commit(previous));
    PetscCall(
        setState(dm, problem, places, fieldOfLocal, c.strain, dim, 1.0, 1e-6, 1e4, rng, local));
  } else {
    const double zero[3][3] = {{0}};
    PetscCall(
        setState(dm, problem, places, fieldOfLocal, zero, dim, 0.0, 1e-7, 1e3, rng, previous));
    PetscCall(setState(dm, problem, places, fieldOfLocal, zero, dim, 0.0, 1e-3, 1e4, rng, local));
  }
  PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, b.X));
  const ResidualMode mode{-dt, true, dt};
  auto rates = [&]() { return b.ratesFromPrevious(1.0 / dt); };
  PetscCall(b.compareBlocks(
      t, 1.0 / dt, mode, rates,
      [&](PetscInt j) {
        return field[j] == kDisplacementField ? 1e-9 : 1e-2; /* m, Pa */
      },
      field, res->max_error, res->max_entry));
  if (plastic) {
    PetscCall(DMGlobalToLocal(dm, b.X, INSERT_VALUES, local));
    PetscCall(problem.visitSkeletonCells(local, [&](PetscInt, double eqps, int state) {
      res->lowest_state = std::min(res->lowest_state, state);
      res->highest_state = std::max(res->highest_state, state);
      res->lowest_plastic_strain = std::min(res->lowest_plastic_strain, eqps);
    }));
  }
  PetscCall(b.destroy());
  PetscFunctionReturn(0);
}

} // namespace

class CurvedJacobian : public ::testing::TestWithParam<CurvedCase> {};

TEST_P(CurvedJacobian, EveryBlockMatchesFiniteDifferences)
{
  const CurvedCase &c = GetParam();
  Result r;
  ASSERT_EQ(compare(c, &r), 0);
  std::printf("%s: %d curved cells, nodes up to %.3f m off the straight-sided places\n", c.name,
              r.cells, r.curvature);
  // The sagitta of a quarter circle of radius 1 m in 4 chords is 1 - cos(11.25 deg) = 0.019 m.
  EXPECT_GT(r.curvature, 0.015) << "the cells are not curved";
  if (c.expected >= 0) {
    EXPECT_EQ(r.lowest_state, c.expected) << "yield state of some integration point";
    EXPECT_EQ(r.highest_state, c.expected) << "yield state of some integration point";
    if (c.expected != (int)physics::YieldState::elastic)
      EXPECT_GT(r.lowest_plastic_strain, 0.0) << "every point has plastic strain";
  }
  const char *names[2] = {"u", "p"};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col) {
      ASSERT_GT(r.max_entry[row][col], 0.0) << "block " << names[row] << names[col] << " is empty";
      const double rel = r.max_error[row][col] / r.max_entry[row][col];
      std::printf("  block %s%s: max |J - J_fd| / max |J_fd| = %.2e (max |J_fd| %.3e)\n",
                  names[row], names[col], rel, r.max_entry[row][col]);
      EXPECT_LT(rel, 1e-6) << "block " << names[row] << names[col];
    }
}

using YS = physics::YieldState;
// Mohr-Coulomb (E = 20 MPa, nu = 0.3, c = 5 kPa, phi = 30, psi = 10 degrees, no initial
// stress): the strains of test_plastic_jacobian for a face and the triaxial edge.
INSTANTIATE_TEST_SUITE_P(
    Order2Curved, CurvedJacobian,
    ::testing::Values(
        CurvedCase{"biot_plane_strain_quad", "thick_cylinder_plane.geo", "biot", false, -1, {}},
        CurvedCase{"biot_plane_strain_tri", "thick_cylinder_plane_tri.geo", "biot", false, -1, {}},
        CurvedCase{"biot_axisymmetric_quad", "thick_cylinder_plane.geo", "biot", true, -1, {}},
        CurvedCase{"biot_3d_hex", "thick_cylinder_slab_3d.geo", "biot", false, -1, {}},
        CurvedCase{"biot_3d_tet", "thick_cylinder_slab_3d_tet.geo", "biot", false, -1, {}},
        CurvedCase{"mohr_coulomb_plane_strain_face",
                   "thick_cylinder_plane.geo",
                   "mohr_coulomb",
                   false,
                   (int)YS::face,
                   {{-4e-3, 5e-4, 0}, {5e-4, 1e-3, 0}, {0, 0, 0}}},
        CurvedCase{"mohr_coulomb_axisymmetric_edge",
                   "thick_cylinder_plane.geo",
                   "mohr_coulomb",
                   true,
                   (int)YS::edge,
                   {{1e-3, 0, 0}, {0, -4e-3, 0}, {0, 0, 0}}},
        CurvedCase{"mohr_coulomb_3d_face",
                   "thick_cylinder_slab_3d.geo",
                   "mohr_coulomb",
                   false,
                   (int)YS::face,
                   {{-8e-3, 1e-3, 0}, {1e-3, 2e-3, 0}, {0, 0, -2e-3}}}),
    [](const auto &info) { return std::string(info.param.name); });
