// Linear Lagrange elements (P1 on simplices, Q1 on tensor cells) on PETSc's reference cells,
// with their quadrature rules. Basis functions are numbered like the vertices of the cell's
// DMPlex closure, so a closure read from a vector lines up with them directly.
#pragma once

#include <petscdm.h>
#include <vector>

namespace poroseam {

class ReferenceElement {
public:
  /// Builds the element for a DMPlex cell type (segment, triangle, quadrilateral, tetrahedron,
  /// hexahedron). Vertex coordinates are taken from DMPlexCreateReferenceCell.
  static PetscErrorCode create(DMPolytopeType type, ReferenceElement *element);
  /// The same element with the nodal (Newton-Cotes/Lobatto) rule: one point at every vertex,
  /// equal weights. Exact for linear integrands; lumps interface tractions to the nodes.
  static PetscErrorCode createNodal(DMPolytopeType type, ReferenceElement *element);

  DMPolytopeType type = DM_POLYTOPE_UNKNOWN;
  int dim = 0;
  int num_vertices = 0;
  bool simplex = false;
  std::vector<double> vertex_coords; ///< num_vertices x dim, closure order, in [-1, 1]

  int num_quadrature = 0;
  std::vector<double> quadrature_points;  ///< num_quadrature x dim
  std::vector<double> quadrature_weights; ///< sum = reference cell measure
  /// Shape functions and their reference gradients tabulated at the quadrature points:
  /// basis[q * num_vertices + a], basis_derivatives[(q * num_vertices + a) * dim + d].
  std::vector<double> basis;
  std::vector<double> basis_derivatives;

  /// Shape functions and reference gradients at an arbitrary reference point.
  void evaluate(const double xi[], double phi[], double dphi[]) const;
};

/// Geometry of one quadrature point of a physical cell.
struct PointGeometry {
  double x[3] = {0, 0, 0};   ///< physical coordinates
  double det_jacobian = 0.0; ///< d x / d xi
  double weight = 0.0;       ///< quadrature weight * det_jacobian (measure of the point)
  double grad_phi[8 * 3];    ///< physical gradients, [a * dim + d]
  const double *phi = nullptr;
};

/// Maps quadrature point q of `element` to the physical cell with vertex coordinates
/// `coords` (num_vertices x dim). Returns det J; a non-positive value means an inverted cell.
double mapQuadraturePoint(const ReferenceElement &element, const double *coords, int q,
                          PointGeometry &g);

/// Measure of quadrature point q of a face element (dim - 1) embedded in space of dimension
/// `space`: the quadrature weight times the surface Jacobian.
double surfaceWeight(const ReferenceElement &face, const double *coords, int space, int q);

/// Normal of a face from the order of its vertices (not normalised; Newell's method in 3D,
/// so warped quadrilaterals get their mean normal). coords: nv x space.
void faceNormal(const double *coords, int nv, int space, double n[3]);

/// Inverse map: reference coordinates of physical point x (Newton, exact for affine cells).
/// Returns true when x lies inside the cell (with a small tolerance).
bool locatePoint(const ReferenceElement &element, const double *coords, const double x[],
                 double xi[]);

} // namespace poroseam
