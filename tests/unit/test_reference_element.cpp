// Linear elements on PETSc's reference cells: partition of unity, nodal interpolation,
// exact gradients of linear fields, quadrature exact for quadratics, point location.
#include "poroseam/reference_element.hpp"

#include <cmath>
#include <gtest/gtest.h>

using poroseam::PointGeometry;
using poroseam::ReferenceElement;

class ReferenceElementTest : public ::testing::TestWithParam<DMPolytopeType> {};

TEST_P(ReferenceElementTest, NodalAndPartitionOfUnity)
{
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(GetParam(), &e), 0);
  for (int a = 0; a < e.num_vertices; ++a) {
    double phi[8];
    e.evaluate(&e.vertex_coords[a * e.dim], phi, nullptr);
    for (int b = 0; b < e.num_vertices; ++b)
      EXPECT_NEAR(phi[b], a == b ? 1.0 : 0.0, 1e-14);
  }
  for (int q = 0; q < e.num_quadrature; ++q) {
    double sum = 0.0, grad[3] = {0, 0, 0};
    for (int a = 0; a < e.num_vertices; ++a) {
      sum += e.basis[q * e.num_vertices + a];
      for (int d = 0; d < e.dim; ++d)
        grad[d] += e.basis_derivatives[(q * e.num_vertices + a) * e.dim + d];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int d = 0; d < e.dim; ++d)
      EXPECT_NEAR(grad[d], 0.0, 1e-14);
  }
}

// A distorted physical cell: reference vertices through an affine map plus, for tensor cells,
// a bilinear perturbation; linear fields must be reproduced exactly either way.
static std::vector<double> physicalCoords(const ReferenceElement &e)
{
  std::vector<double> x(e.vertex_coords.size());
  for (int a = 0; a < e.num_vertices; ++a) {
    const double *r = &e.vertex_coords[a * e.dim];
    for (int d = 0; d < e.dim; ++d) {
      double v = 2.0 + 1.5 * r[d] + 0.3 * r[(d + 1) % e.dim];
      if (!e.simplex) v += 0.1 * r[0] * r[(d + 1) % e.dim] * (d == 0 ? 0.0 : 1.0);
      x[a * e.dim + d] = v;
    }
  }
  return x;
}

TEST_P(ReferenceElementTest, LinearFieldGradientIsExactAndVolumeMatches)
{
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(GetParam(), &e), 0);
  const auto x = physicalCoords(e);
  const double c[3] = {0.7, -1.3, 2.1};
  std::vector<double> f(e.num_vertices);
  for (int a = 0; a < e.num_vertices; ++a) {
    f[a] = 4.0;
    for (int d = 0; d < e.dim; ++d)
      f[a] += c[d] * x[a * e.dim + d];
  }
  double volume = 0.0, moment = 0.0;
  for (int q = 0; q < e.num_quadrature; ++q) {
    PointGeometry g;
    ASSERT_GT(poroseam::mapQuadraturePoint(e, x.data(), q, g), 0.0);
    volume += g.weight;
    moment += g.weight * g.x[0] * g.x[0]; // quadratic: integrated exactly on affine cells
    for (int d = 0; d < e.dim; ++d) {
      double grad = 0.0;
      for (int a = 0; a < e.num_vertices; ++a)
        grad += g.grad_phi[a * e.dim + d] * f[a];
      EXPECT_NEAR(grad, c[d], 1e-12);
    }
  }
  // Reference measure times the (constant) Jacobian of the affine part.
  EXPECT_GT(volume, 0.0);
  if (e.simplex) {
    // Affine cell: compare the quadratic moment with the vertex formula
    // int x^2 = V/((d+1)(d+2)) (sum x_a^2 + (sum x_a)^2).
    double s1 = 0.0, s2 = 0.0;
    for (int a = 0; a < e.num_vertices; ++a) {
      s1 += x[a * e.dim];
      s2 += x[a * e.dim] * x[a * e.dim];
    }
    EXPECT_NEAR(moment, volume / ((e.dim + 1) * (e.dim + 2)) * (s2 + s1 * s1), 1e-12 * moment);
  }
}

TEST_P(ReferenceElementTest, LocatesPointsInsideAndOutside)
{
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(GetParam(), &e), 0);
  const auto x = physicalCoords(e);
  PointGeometry g;
  poroseam::mapQuadraturePoint(e, x.data(), 0, g);
  double xi[3];
  ASSERT_TRUE(poroseam::locatePoint(e, x.data(), g.x, xi));
  for (int d = 0; d < e.dim; ++d)
    EXPECT_NEAR(xi[d], e.quadrature_points[d], 1e-10);
  double far[3] = {100.0, 100.0, 100.0};
  EXPECT_FALSE(poroseam::locatePoint(e, x.data(), far, xi));
}

TEST(ReferenceElement, InvertedCellHasNegativeDeterminant)
{
  ReferenceElement e;
  ASSERT_EQ(ReferenceElement::create(DM_POLYTOPE_TRIANGLE, &e), 0);
  std::vector<double> x = e.vertex_coords;
  std::swap(x[2], x[4]);
  std::swap(x[3], x[5]);
  PointGeometry g;
  EXPECT_LT(poroseam::mapQuadraturePoint(e, x.data(), 0, g), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Cells, ReferenceElementTest,
                         ::testing::Values(DM_POLYTOPE_SEGMENT, DM_POLYTOPE_TRIANGLE,
                                           DM_POLYTOPE_QUADRILATERAL, DM_POLYTOPE_TETRAHEDRON,
                                           DM_POLYTOPE_HEXAHEDRON));
