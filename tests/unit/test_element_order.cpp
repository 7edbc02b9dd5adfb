// The elements of both displacement orders (ReferenceElement, from PetscFE / PetscDT):
// - the node basis is nodal at its nodes, sums to one, and its monomial expansion agrees with
//   PETSc's tabulation at the quadrature points;
// - order 2 reproduces a quadratic field exactly (values and gradients) on a straight-sided cell;
// - the quadrature integrates polynomials of degree 2 * order exactly;
// - on distorted meshes (with DMPlex's face and edge orientations), the displacement values a
//   cell's closure returns are in the order of the element's nodes: a vector holding each
//   node's own position, read through DMPlexVecGetClosure, gives the element's node
//   coordinates mapped to the cell, node for node.
#include "poroseam/layout.hpp"
#include "poroseam/reference_element.hpp"
#include "poroseam/scene.hpp"

#include "order_meshes.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <petscdmplex.h>
#include <tuple>

using namespace poroseam;

namespace {

class ElementOrder : public ::testing::TestWithParam<std::tuple<DMPolytopeType, int>> {};

/// A straight-sided (affine) physical cell: x = A xi + b.
void affineCell(const ReferenceElement &e, std::vector<double> &x)
{
  x.resize(e.vertex_coords.size());
  for (int a = 0; a < e.num_vertices; ++a)
    for (int d = 0; d < e.dim; ++d) {
      const double *r = &e.vertex_coords[a * e.dim];
      x[a * e.dim + d] = 1.0 + 0.8 * r[d] + 0.25 * r[(d + 1) % e.dim] + 0.1 * d;
    }
}

TEST_P(ElementOrder, NodalPartitionOfUnityAndPetscTabulation)
{
  const auto [type, order] = GetParam();
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(type, &e, order), 0);
  const int nn = e.num_nodes, dim = e.dim;
  const int expected[2][6] = {{2, 3, 4, 4, 8, 0}, {3, 6, 9, 10, 27, 0}};
  const int which = type == DM_POLYTOPE_SEGMENT         ? 0
                    : type == DM_POLYTOPE_TRIANGLE      ? 1
                    : type == DM_POLYTOPE_QUADRILATERAL ? 2
                    : type == DM_POLYTOPE_TETRAHEDRON   ? 3
                                                        : 4;
  EXPECT_EQ(nn, expected[order - 1][which]);
  std::vector<double> phi(nn), dphi(nn * dim);
  for (int b = 0; b < nn; ++b) {
    e.evaluateNodes(&e.node_coords[b * dim], phi.data(), nullptr);
    for (int a = 0; a < nn; ++a)
      EXPECT_NEAR(phi[a], a == b ? 1.0 : 0.0, 1e-12) << "node " << b << " function " << a;
  }
  // The first vertices-many nodes of the closure order are not the vertices (the closure lists
  // the cell, faces and edges first): the vertices are the last num_vertices nodes, in order.
  for (int a = 0; a < e.num_vertices; ++a)
    for (int d = 0; d < dim; ++d)
      EXPECT_EQ(e.node_coords[(nn - e.num_vertices + a) * dim + d], e.vertex_coords[a * dim + d]);
  for (int q = 0; q < e.num_quadrature; ++q) {
    e.evaluateNodes(&e.quadrature_points[q * dim], phi.data(), dphi.data());
    double sum = 0.0;
    for (int a = 0; a < nn; ++a) {
      sum += phi[a];
      EXPECT_NEAR(phi[a], e.node_basis[q * nn + a], 1e-12);
      for (int d = 0; d < dim; ++d)
        EXPECT_NEAR(dphi[a * dim + d], e.node_basis_derivatives[(q * nn + a) * dim + d], 1e-11);
    }
    EXPECT_NEAR(sum, 1.0, 1e-13);
  }
}

TEST_P(ElementOrder, QuadratureIsExactForDegreeTwiceTheOrder)
{
  const auto [type, order] = GetParam();
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(type, &e, order), 0);
  // The integral over the reference cell of (1 + xi_0)^k, k = 2 * order. Tensor cells:
  // 2^(dim-1) 2^(k+1)/(k+1). Simplices (vertices at -1 and 1): 1 + xi_0 = 2 lambda, lambda the
  // barycentric coordinate of the vertex at xi_0 = 1, and int lambda^k = |T| k! dim! / (k + dim)!.
  const int k = 2 * order, dim = e.dim;
  double integral = 0.0;
  for (int q = 0; q < e.num_quadrature; ++q)
    integral += e.quadrature_weights[q] * std::pow(1.0 + e.quadrature_points[q * dim], k);
  double exact;
  if (!e.simplex || dim == 1)
    exact = std::pow(2.0, dim - 1) * std::pow(2.0, k + 1) / (k + 1);
  else {
    const double measure = dim == 2 ? 2.0 : 4.0 / 3.0;
    double ratio = 1.0; // k! dim! / (k + dim)!
    for (int i = 1; i <= dim; ++i)
      ratio *= (double)i / (k + i);
    exact = std::pow(2.0, k) * measure * ratio;
  }
  EXPECT_NEAR(integral, exact, 1e-12 * exact);
}

TEST_P(ElementOrder, ReproducesPolynomialsOfItsOrder)
{
  const auto [type, order] = GetParam();
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(type, &e, order), 0);
  const int dim = e.dim, nn = e.num_nodes;
  std::vector<double> x;
  affineCell(e, x);
  // f = 0.3 + sum c_d x_d (+ order 2: sum c_d x_d^2 + x_0 x_last): nodal values at the nodes
  // mapped by the vertex basis.
  const double c[3] = {0.7, -1.1, 0.4};
  auto f = [&](const double *p, double *grad) {
    double v = 0.3;
    for (int d = 0; d < dim; ++d) {
      v += c[d] * p[d];
      grad[d] = c[d];
      if (order == 2) v += c[d] * p[d] * p[d], grad[d] += 2.0 * c[d] * p[d];
    }
    if (order == 2) {
      v += p[0] * p[dim - 1];
      grad[0] += p[dim - 1];
      grad[dim - 1] += p[0];
    }
    return v;
  };
  std::vector<double> values(nn), phi(e.num_vertices);
  for (int a = 0; a < nn; ++a) {
    e.evaluate(&e.node_coords[a * dim], phi.data(), nullptr);
    double p[3] = {0, 0, 0}, grad[3];
    for (int v = 0; v < e.num_vertices; ++v)
      for (int d = 0; d < dim; ++d)
        p[d] += phi[v] * x[v * dim + d];
    values[a] = f(p, grad);
  }
  PointGeometry g;
  for (int q = 0; q < e.num_quadrature; ++q) {
    ASSERT_GT(mapQuadraturePoint(e, x.data(), q, g), 0.0);
    double value = 0.0, grad[3] = {0, 0, 0}, exact_grad[3];
    for (int a = 0; a < nn; ++a) {
      value += g.node_phi[a] * values[a];
      for (int d = 0; d < dim; ++d)
        grad[d] += g.grad_node_phi[a * dim + d] * values[a];
    }
    EXPECT_NEAR(value, f(g.x, exact_grad), 1e-12);
    for (int d = 0; d < dim; ++d)
      EXPECT_NEAR(grad[d], exact_grad[d], 1e-11);
  }
}

INSTANTIATE_TEST_SUITE_P(
    CellsAndOrders, ElementOrder,
    ::testing::Combine(::testing::Values(DM_POLYTOPE_SEGMENT, DM_POLYTOPE_TRIANGLE,
                                         DM_POLYTOPE_QUADRILATERAL, DM_POLYTOPE_TETRAHEDRON,
                                         DM_POLYTOPE_HEXAHEDRON),
                       ::testing::Values(1, 2)));

/// (dim, simplex): the closure of every cell lists the displacement nodes in element order.
class ClosureOrder : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(ClosureOrder, ClosureValuesFollowTheElementNodes)
{
  const auto [dim, simplex] = GetParam();
  DM dm;
  ASSERT_EQ(test_support::createOrderMesh(dim, simplex, 3, 0.05, &dm), 0);
  Scene scene;
  scene.dim = dim;
  scene.displacement_order = 2;
  Region r;
  r.name = "solid";
  r.tag = 1;
  r.young = 1.0;
  r.poisson = 0.25;
  scene.regions = {r};
  ASSERT_EQ(markLayoutLabels(dm, scene), 0);
  ASSERT_EQ(createSolutionSection(dm, scene), 0);
  PetscSection s, cs;
  Vec coords, local;
  ASSERT_EQ(DMGetLocalSection(dm, &s), 0);
  ASSERT_EQ(DMGetCoordinateSection(dm, &cs), 0);
  ASSERT_EQ(DMGetCoordinatesLocal(dm, &coords), 0);
  ASSERT_EQ(DMCreateLocalVector(dm, &local), 0);
  // Each displacement node holds its own position (the mean of its point's vertices).
  PetscInt pStart, pEnd;
  ASSERT_EQ(DMPlexGetChart(dm, &pStart, &pEnd), 0);
  PetscScalar *u;
  ASSERT_EQ(VecGetArray(local, &u), 0);
  for (PetscInt pt = pStart; pt < pEnd; ++pt) {
    PetscInt dof = 0, off;
    ASSERT_EQ(PetscSectionGetFieldDof(s, pt, kDisplacementField, &dof), 0);
    if (!dof) continue;
    ASSERT_EQ(dof, dim);
    ASSERT_EQ(PetscSectionGetFieldOffset(s, pt, kDisplacementField, &off), 0);
    PetscScalar *xc = nullptr;
    PetscInt nc = 0;
    ASSERT_EQ(DMPlexVecGetClosure(dm, cs, coords, pt, &nc, &xc), 0);
    for (int d = 0; d < dim; ++d) {
      u[off + d] = 0.0;
      for (PetscInt a = 0; a < nc / dim; ++a)
        u[off + d] += xc[a * dim + d] / (nc / dim);
    }
    ASSERT_EQ(DMPlexVecRestoreClosure(dm, cs, coords, pt, &nc, &xc), 0);
  }
  ASSERT_EQ(VecRestoreArray(local, &u), 0);
  PetscInt cStart, cEnd;
  ASSERT_EQ(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd), 0);
  DMPolytopeType ct;
  ASSERT_EQ(DMPlexGetCellType(dm, cStart, &ct), 0);
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(ct, &e, 2), 0);
  std::vector<double> phi(e.num_vertices);
  double worst = 0.0;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscScalar *xc = nullptr, *x = nullptr;
    PetscInt nc = 0, nx = 0;
    ASSERT_EQ(DMPlexVecGetClosure(dm, cs, coords, c, &nc, &xc), 0);
    ASSERT_EQ(DMPlexVecGetClosure(dm, s, local, c, &nx, &x), 0);
    ASSERT_EQ(nx, e.num_nodes * dim);
    for (int a = 0; a < e.num_nodes; ++a) {
      e.evaluate(&e.node_coords[a * dim], phi.data(), nullptr);
      for (int d = 0; d < dim; ++d) {
        double p = 0.0;
        for (int v = 0; v < e.num_vertices; ++v)
          p += phi[v] * xc[v * dim + d];
        worst = std::max(worst, std::fabs(p - x[a * dim + d]));
      }
    }
    ASSERT_EQ(DMPlexVecRestoreClosure(dm, s, local, c, &nx, &x), 0);
    ASSERT_EQ(DMPlexVecRestoreClosure(dm, cs, coords, c, &nc, &xc), 0);
  }
  EXPECT_LT(worst, 1e-13);
  ASSERT_EQ(VecDestroy(&local), 0);
  ASSERT_EQ(DMDestroy(&dm), 0);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ClosureOrder,
                         ::testing::Combine(::testing::Values(2, 3),
                                            ::testing::Values(false, true)));

} // namespace
