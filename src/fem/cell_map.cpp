// The map of a physical cell from its reference element, at quadrature points
// (mapQuadraturePoint: position, Jacobian, physical gradients of both bases) and its inverse
// (locatePoint: the reference coordinates of a physical point). Apart from
// reference_element.cpp, which builds the element from PETSc once per cell type: this runs
// per cell and point, from the element's tables and the cell's coordinates.
#include "poroseam/reference_element.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

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

double mapQuadraturePoint(const ReferenceElement &e, const double *coords, int q, PointGeometry &g,
                          bool curved)
{
  const int dim = e.dim, nv = e.num_vertices, nn = e.num_nodes;
  const double *phi = &e.basis[q * nv];
  const double *dphi = &e.basis_derivatives[q * nv * dim];
  // The geometry's basis: the vertex basis (straight-sided), or the node basis (isoparametric:
  // coords are the nodes' places, nn x dim).
  const int ng = curved ? nn : nv;
  const double *gphi = curved ? &e.node_basis[q * nn] : phi;
  const double *gdphi = curved ? &e.node_basis_derivatives[q * nn * dim] : dphi;
  double J[3][3], invJ[3][3];
  const double det = jacobian(dim, ng, coords, gdphi, J, invJ);
  // Gradients of the vertex basis, then (order > 1) of the node basis, in one buffer sized
  // on first use.
  const bool separate = e.order > 1;
  const size_t need = (size_t)(nv + (separate ? nn : 0)) * dim;
  if (g.storage.size() < need) g.storage.resize(need);
  g.phi = phi;
  g.det_jacobian = det;
  g.weight = e.quadrature_weights[q] * det;
  for (int r = 0; r < 3; ++r)
    g.x[r] = 0.0;
  for (int a = 0; a < ng; ++a)
    for (int r = 0; r < dim; ++r)
      g.x[r] += gphi[a] * coords[a * dim + r];
  // grad phi = invJ^T grad_xi phi
  auto physical = [&](int nb, const double *ref, double *out) {
    for (int a = 0; a < nb; ++a)
      for (int r = 0; r < dim; ++r) {
        double s = 0.0;
        for (int k = 0; k < dim; ++k)
          s += ref[a * dim + k] * invJ[k][r];
        out[a * dim + r] = s;
      }
  };
  double *grad = g.storage.data();
  physical(nv, dphi, grad);
  g.grad_phi = grad;
  if (separate) {
    physical(nn, &e.node_basis_derivatives[q * nn * dim], grad + nv * dim);
    g.node_phi = &e.node_basis[q * nn];
    g.grad_node_phi = grad + nv * dim;
  } else {
    g.node_phi = phi;
    g.grad_node_phi = grad;
  }
  return det;
}

bool locatePoint(const ReferenceElement &e, const double *coords, const double x[], double xi[],
                 bool curved)
{
  const int dim = e.dim, nv = e.num_vertices;
  // The map: vertex basis (straight-sided) or node basis (curved: coords are the nodes').
  const int ng = curved ? e.num_nodes : nv;
  // Start at the reference centroid, Newton on x(xi) = x (one step for affine cells).
  for (int k = 0; k < dim; ++k) {
    xi[k] = 0.0;
    for (int a = 0; a < nv; ++a)
      xi[k] += e.vertex_coords[a * dim + k] / nv;
  }
  std::vector<double> phi_(std::max(nv, ng)), dphi_(std::max(nv, ng) * dim);
  double *phi = phi_.data(), *dphi = dphi_.data();
  for (int it = 0; it < 20; ++it) {
    if (curved)
      e.evaluateNodes(xi, phi, dphi);
    else
      e.evaluate(xi, phi, dphi);
    double J[3][3], invJ[3][3], r[3] = {0, 0, 0};
    jacobian(dim, ng, coords, dphi, J, invJ);
    for (int a = 0; a < ng; ++a)
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
