#include "poroseam/reference_element.hpp"

#include <cmath>
#include <petscdmplex.h>

namespace poroseam {
namespace {

/// Inverse of a dim x dim matrix (dim <= 3) by cofactors; returns the determinant.
double invert(int dim, const double A[3][3], double inv[3][3])
{
  if (dim == 1) {
    inv[0][0] = 1.0 / A[0][0];
    return A[0][0];
  }
  if (dim == 2) {
    const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    inv[0][0] = A[1][1] / det, inv[0][1] = -A[0][1] / det;
    inv[1][0] = -A[1][0] / det, inv[1][1] = A[0][0] / det;
    return det;
  }
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                     A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  inv[0][0] = (A[1][1] * A[2][2] - A[1][2] * A[2][1]) / det;
  inv[0][1] = (A[0][2] * A[2][1] - A[0][1] * A[2][2]) / det;
  inv[0][2] = (A[0][1] * A[1][2] - A[0][2] * A[1][1]) / det;
  inv[1][0] = (A[1][2] * A[2][0] - A[1][0] * A[2][2]) / det;
  inv[1][1] = (A[0][0] * A[2][2] - A[0][2] * A[2][0]) / det;
  inv[1][2] = (A[0][2] * A[1][0] - A[0][0] * A[1][2]) / det;
  inv[2][0] = (A[1][0] * A[2][1] - A[1][1] * A[2][0]) / det;
  inv[2][1] = (A[0][1] * A[2][0] - A[0][0] * A[2][1]) / det;
  inv[2][2] = (A[0][0] * A[1][1] - A[0][1] * A[1][0]) / det;
  return det;
}

// Barycentric-type linear basis on a simplex: phi_a(xi) = c_a + g_a . xi, found by inverting
// the affine map of the reference vertices (closure order).
void simplexBasis(const ReferenceElement &e, const double xi[], double phi[], double dphi[])
{
  const int d = e.dim;
  // x(lambda) = v0 + sum_k lambda_k (v_k - v0); solve for lambda_1..d.
  double A[3][3] = {{0}};
  for (int r = 0; r < d; ++r)
    for (int k = 0; k < d; ++k)
      A[r][k] = e.vertex_coords[(k + 1) * d + r] - e.vertex_coords[r];
  // invert A (d <= 3)
  double inv[3][3] = {{0}};
  invert(d, A, inv);
  double rel[3];
  for (int r = 0; r < d; ++r)
    rel[r] = xi[r] - e.vertex_coords[r];
  double sum = 0.0;
  for (int k = 0; k < d; ++k) {
    double lambda = 0.0;
    for (int r = 0; r < d; ++r)
      lambda += inv[k][r] * rel[r];
    phi[k + 1] = lambda;
    sum += lambda;
    if (dphi)
      for (int r = 0; r < d; ++r)
        dphi[(k + 1) * d + r] = inv[k][r];
  }
  phi[0] = 1.0 - sum;
  if (dphi)
    for (int r = 0; r < d; ++r) {
      double s = 0.0;
      for (int k = 0; k < d; ++k)
        s += inv[k][r];
      dphi[r] = -s;
    }
}

// Tensor-product linear basis: phi_a = prod_d (1 + xi_d s_ad) / 2 with s_ad the sign of the
// reference vertex coordinate.
void tensorBasis(const ReferenceElement &e, const double xi[], double phi[], double dphi[])
{
  const int d = e.dim;
  for (int a = 0; a < e.num_vertices; ++a) {
    double f[3];
    for (int k = 0; k < d; ++k)
      f[k] = 0.5 * (1.0 + xi[k] * e.vertex_coords[a * d + k]);
    double value = 1.0;
    for (int k = 0; k < d; ++k)
      value *= f[k];
    phi[a] = value;
    if (dphi)
      for (int k = 0; k < d; ++k) {
        double g = 0.5 * e.vertex_coords[a * d + k];
        for (int m = 0; m < d; ++m)
          if (m != k) g *= f[m];
        dphi[a * d + k] = g;
      }
  }
}

void gaussLine(std::vector<double> &pts, std::vector<double> &wts)
{
  const double s = 1.0 / std::sqrt(3.0);
  pts = {-s, s};
  wts = {1.0, 1.0};
}

// Quadrature rules exact for quadratics (mass and stabilisation terms of linear elements),
// written on PETSc's reference cells [-1, 1]^d and the simplex with vertices at -1 and 1.
void setQuadrature(ReferenceElement &e)
{
  std::vector<double> p1, w1;
  gaussLine(p1, w1);
  e.quadrature_points.clear();
  e.quadrature_weights.clear();
  if (!e.simplex) {
    const int n = (int)p1.size();
    const int count = e.dim == 1 ? n : e.dim == 2 ? n * n : n * n * n;
    for (int q = 0; q < count; ++q) {
      int idx[3] = {q % n, (q / n) % n, (q / (n * n)) % n};
      double w = 1.0;
      for (int k = 0; k < e.dim; ++k) {
        e.quadrature_points.push_back(p1[idx[k]]);
        w *= w1[idx[k]];
      }
      e.quadrature_weights.push_back(w);
    }
  } else {
    // Points given in barycentric coordinates of the reference simplex, mapped through its
    // vertices so that the rule does not depend on the vertex numbering.
    std::vector<std::vector<double>> bary;
    std::vector<double> frac;
    if (e.dim == 1) {
      const double s = 0.5 / std::sqrt(3.0);
      bary = {{0.5 + s, 0.5 - s}, {0.5 - s, 0.5 + s}};
      frac = {0.5, 0.5};
    } else if (e.dim == 2) {
      bary = {{2. / 3, 1. / 6, 1. / 6}, {1. / 6, 2. / 3, 1. / 6}, {1. / 6, 1. / 6, 2. / 3}};
      frac = {1. / 3, 1. / 3, 1. / 3};
    } else {
      const double a = 0.5854101966249685, b = 0.1381966011250105;
      bary = {{a, b, b, b}, {b, a, b, b}, {b, b, a, b}, {b, b, b, a}};
      frac = {0.25, 0.25, 0.25, 0.25};
    }
    const double measure = e.dim == 1 ? 2.0 : e.dim == 2 ? 2.0 : 4.0 / 3.0;
    for (size_t q = 0; q < bary.size(); ++q) {
      for (int k = 0; k < e.dim; ++k) {
        double x = 0.0;
        for (int a = 0; a < e.num_vertices; ++a)
          x += bary[q][a] * e.vertex_coords[a * e.dim + k];
        e.quadrature_points.push_back(x);
      }
      e.quadrature_weights.push_back(frac[q] * measure);
    }
  }
  e.num_quadrature = (int)e.quadrature_weights.size();
}

} // namespace

PetscErrorCode ReferenceElement::create(DMPolytopeType type, ReferenceElement *element)
{
  ReferenceElement &e = *element;
  PetscFunctionBeginUser;
  e.type = type;
  switch (type) {
  case DM_POLYTOPE_SEGMENT:
    e.dim = 1, e.num_vertices = 2, e.simplex = true;
    break;
  case DM_POLYTOPE_TRIANGLE:
    e.dim = 2, e.num_vertices = 3, e.simplex = true;
    break;
  case DM_POLYTOPE_QUADRILATERAL:
    e.dim = 2, e.num_vertices = 4, e.simplex = false;
    break;
  case DM_POLYTOPE_TETRAHEDRON:
    e.dim = 3, e.num_vertices = 4, e.simplex = true;
    break;
  case DM_POLYTOPE_HEXAHEDRON:
    e.dim = 3, e.num_vertices = 8, e.simplex = false;
    break;
  default:
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP,
            "poroseam supports segments, triangles, quadrilaterals, "
            "tetrahedra and hexahedra; got cell type %s",
            DMPolytopeTypes[type]);
  }
  // The vertex coordinates of PETSc's reference cell, in closure order.
  DM ref;
  PetscCall(DMPlexCreateReferenceCell(PETSC_COMM_SELF, type, &ref));
  Vec coords;
  PetscCall(DMGetCoordinatesLocal(ref, &coords));
  PetscSection csec;
  PetscCall(DMGetCoordinateSection(ref, &csec));
  PetscScalar *values = nullptr;
  PetscInt n = 0;
  PetscCall(DMPlexVecGetClosure(ref, csec, coords, 0, &n, &values));
  PetscCheck(n == e.num_vertices * e.dim, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "reference cell closure");
  e.vertex_coords.assign(values, values + n);
  PetscCall(DMPlexVecRestoreClosure(ref, csec, coords, 0, &n, &values));
  PetscCall(DMDestroy(&ref));

  setQuadrature(e);
  e.basis.resize(e.num_quadrature * e.num_vertices);
  e.basis_derivatives.resize(e.num_quadrature * e.num_vertices * e.dim);
  for (int q = 0; q < e.num_quadrature; ++q)
    e.evaluate(&e.quadrature_points[q * e.dim], &e.basis[q * e.num_vertices],
               &e.basis_derivatives[q * e.num_vertices * e.dim]);
  PetscFunctionReturn(0);
}

PetscErrorCode ReferenceElement::createNodal(DMPolytopeType type, ReferenceElement *element)
{
  ReferenceElement &e = *element;
  PetscFunctionBeginUser;
  PetscCall(create(type, element));
  double measure = 0.0;
  for (double w : e.quadrature_weights)
    measure += w;
  e.num_quadrature = e.num_vertices;
  e.quadrature_points = e.vertex_coords;
  e.quadrature_weights.assign(e.num_vertices, measure / e.num_vertices);
  e.basis.resize(e.num_quadrature * e.num_vertices);
  e.basis_derivatives.resize(e.num_quadrature * e.num_vertices * e.dim);
  for (int q = 0; q < e.num_quadrature; ++q)
    e.evaluate(&e.quadrature_points[q * e.dim], &e.basis[q * e.num_vertices],
               &e.basis_derivatives[q * e.num_vertices * e.dim]);
  PetscFunctionReturn(0);
}

double surfaceWeight(const ReferenceElement &e, const double *coords, int space, int q)
{
  const double *dphi = &e.basis_derivatives[q * e.num_vertices * e.dim];
  double t[2][3] = {{0, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < e.dim; ++k)
    for (int a = 0; a < e.num_vertices; ++a)
      for (int r = 0; r < space; ++r)
        t[k][r] += coords[a * space + r] * dphi[a * e.dim + k];
  double measure = 1.0;
  if (e.dim == 1)
    measure = std::sqrt(t[0][0] * t[0][0] + t[0][1] * t[0][1] + t[0][2] * t[0][2]);
  else if (e.dim == 2) {
    const double n[3] = {t[0][1] * t[1][2] - t[0][2] * t[1][1],
                         t[0][2] * t[1][0] - t[0][0] * t[1][2],
                         t[0][0] * t[1][1] - t[0][1] * t[1][0]};
    measure = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return e.quadrature_weights[q] * measure;
}

void faceNormal(const double *x, int nv, int space, double n[3])
{
  n[0] = n[1] = n[2] = 0.0;
  if (space == 2) {
    n[0] = x[3] - x[1];
    n[1] = -(x[2] - x[0]);
    return;
  }
  for (int a = 0; a < nv; ++a) {
    const double *p = &x[a * 3], *q = &x[((a + 1) % nv) * 3];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
}

void ReferenceElement::evaluate(const double xi[], double phi[], double dphi[]) const
{
  if (simplex)
    simplexBasis(*this, xi, phi, dphi);
  else
    tensorBasis(*this, xi, phi, dphi);
}

namespace {
// J[r][k] = d x_r / d xi_k for reference gradients dphi at one point; returns det J and
// fills invJ.
double jacobian(int dim, int nv, const double *coords, const double *dphi, double J[3][3],
                double invJ[3][3])
{
  for (int r = 0; r < dim; ++r)
    for (int k = 0; k < dim; ++k) {
      double s = 0.0;
      for (int a = 0; a < nv; ++a)
        s += coords[a * dim + r] * dphi[a * dim + k];
      J[r][k] = s;
    }
  return invert(dim, J, invJ);
}
} // namespace

double mapQuadraturePoint(const ReferenceElement &e, const double *coords, int q, PointGeometry &g)
{
  const int dim = e.dim, nv = e.num_vertices;
  const double *phi = &e.basis[q * nv];
  const double *dphi = &e.basis_derivatives[q * nv * dim];
  double J[3][3], invJ[3][3];
  const double det = jacobian(dim, nv, coords, dphi, J, invJ);
  g.phi = phi;
  g.det_jacobian = det;
  g.weight = e.quadrature_weights[q] * det;
  for (int r = 0; r < 3; ++r)
    g.x[r] = 0.0;
  for (int a = 0; a < nv; ++a)
    for (int r = 0; r < dim; ++r)
      g.x[r] += phi[a] * coords[a * dim + r];
  // grad phi = invJ^T grad_xi phi
  for (int a = 0; a < nv; ++a)
    for (int r = 0; r < dim; ++r) {
      double s = 0.0;
      for (int k = 0; k < dim; ++k)
        s += dphi[a * dim + k] * invJ[k][r];
      g.grad_phi[a * dim + r] = s;
    }
  return det;
}

bool locatePoint(const ReferenceElement &e, const double *coords, const double x[], double xi[])
{
  const int dim = e.dim, nv = e.num_vertices;
  // Start at the reference centroid, Newton on x(xi) = x (one step for affine cells).
  for (int k = 0; k < dim; ++k) {
    xi[k] = 0.0;
    for (int a = 0; a < nv; ++a)
      xi[k] += e.vertex_coords[a * dim + k] / nv;
  }
  double phi[8], dphi[24];
  for (int it = 0; it < 20; ++it) {
    e.evaluate(xi, phi, dphi);
    double J[3][3], invJ[3][3], r[3] = {0, 0, 0};
    jacobian(dim, nv, coords, dphi, J, invJ);
    for (int a = 0; a < nv; ++a)
      for (int k = 0; k < dim; ++k)
        r[k] += phi[a] * coords[a * dim + k];
    double step = 0.0;
    for (int k = 0; k < dim; ++k) {
      double dxi = 0.0;
      for (int m = 0; m < dim; ++m)
        dxi += invJ[k][m] * (x[m] - r[m]);
      xi[k] += dxi;
      step += std::fabs(dxi);
    }
    if (step < 1e-13) break;
  }
  e.evaluate(xi, phi, nullptr);
  const double tol = 1e-8;
  if (e.simplex) {
    for (int a = 0; a < nv; ++a)
      if (phi[a] < -tol) return false;
    return true;
  }
  for (int k = 0; k < dim; ++k)
    if (std::fabs(xi[k]) > 1.0 + tol) return false;
  return true;
}

} // namespace poroseam
