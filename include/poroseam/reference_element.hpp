// Lagrange elements of any order on PETSc's reference cells, with their quadrature rules, both
// taken from PETSc (PetscFE / PetscDT, src/fem/reference_element.cpp). Two bases live on one
// element: the vertex basis (linear: P1 on simplices, Q1 on tensor cells) that maps the
// straight-sided cell and carries the pressure, and the node basis of the displacement
// (order 1: the vertex basis again; order 2: P2 / Lagrange Q2). Basis functions are numbered
// like the dofs of the cell's DMPlex closure (the cell itself, then its faces, edges and
// vertices, one node per point at order <= 2), so a closure read from a vector lines up with
// them directly; at order 1 this is the closure's vertex order. docs/elements.md says why.
#pragma once

#include <petscdm.h>
#include <vector>

namespace poroseam {

class ReferenceElement {
public:
  /// Builds the element for a DMPlex cell type (segment, triangle, quadrilateral, tetrahedron,
  /// hexahedron) with displacement basis of `order` (1 or 2). Vertex coordinates are taken from
  /// DMPlexCreateReferenceCell, the bases from PetscFECreateLagrange, the quadrature from
  /// PetscDTSimplexQuadrature / PetscDTGaussTensorQuadrature, exact for polynomials of degree
  /// 2 * order on affine cells (the mass matrices of both bases).
  static PetscErrorCode create(DMPolytopeType type, ReferenceElement *element, int order = 1);
  /// The element with the nodal (Newton-Cotes/Lobatto) rule: one point at every node, lumping
  /// interface tractions to the nodes. Order 1: the vertices, equal weights (exact for linear
  /// integrands). Order 2 (segments and quadrilaterals only): the nodes of P2 / Q2 with the
  /// integrals of their functions as weights (Simpson, tensor Simpson).
  static PetscErrorCode createNodal(DMPolytopeType type, ReferenceElement *element, int order = 1);

  DMPolytopeType type = DM_POLYTOPE_UNKNOWN;
  int dim = 0;
  int num_vertices = 0;
  bool simplex = false;
  std::vector<double> vertex_coords; ///< num_vertices x dim, closure order, in [-1, 1]

  int num_quadrature = 0;
  std::vector<double> quadrature_points;  ///< num_quadrature x dim
  std::vector<double> quadrature_weights; ///< sum = reference cell measure
  /// Vertex (linear) shape functions and their reference gradients tabulated at the quadrature
  /// points: basis[q * num_vertices + a], basis_derivatives[(q * num_vertices + a) * dim + d].
  std::vector<double> basis;
  std::vector<double> basis_derivatives;

  /// The displacement basis: `order`, its number of nodes (= num_vertices at order 1), the
  /// nodes' reference coordinates (num_nodes x dim, closure order) and its tabulation at the
  /// quadrature points, laid out like `basis`.
  int order = 1;
  int num_nodes = 0;
  std::vector<double> node_coords;
  std::vector<double> node_basis;
  std::vector<double> node_basis_derivatives;

  /// Vertex shape functions and reference gradients at an arbitrary reference point
  /// (dphi may be null).
  void evaluate(const double xi[], double phi[], double dphi[]) const;
  /// Node (displacement) shape functions and reference gradients at an arbitrary point.
  void evaluateNodes(const double xi[], double phi[], double dphi[]) const;

  /// Monomial expansions of both bases (for evaluation away from the quadrature points):
  /// exponents[m * dim + d] of monomial m, coefficients [a * num_monomials + m]. Fitted to
  /// PETSc's tabulation at set-up; the unit test checks both agree at the quadrature points.
  struct Expansion {
    int num_monomials = 0;
    std::vector<int> exponents;
    std::vector<double> coefficients;
  };
  Expansion vertex_expansion, node_expansion;
};

/// Geometry of one quadrature point of a physical cell. Keep one across the points and cells
/// of a loop: its storage is sized for the element on first use and reused.
struct PointGeometry {
  double x[3] = {0, 0, 0};          ///< physical coordinates
  double det_jacobian = 0.0;        ///< d x / d xi
  double weight = 0.0;              ///< quadrature weight * det_jacobian (measure of the point)
  const double *phi = nullptr;      ///< vertex basis values (pressure, geometry)
  const double *grad_phi = nullptr; ///< vertex basis physical gradients, [a * dim + d]
  const double *node_phi = nullptr; ///< node (displacement) basis values
  const double *grad_node_phi = nullptr; ///< node basis physical gradients, [a * dim + d]
  std::vector<double> storage;           ///< holds the gradients
};

/// Maps quadrature point q of `element` to the physical cell with vertex coordinates
/// `coords` (num_vertices x dim). Returns det J; a non-positive value means an inverted cell.
/// `curved`: the cell is isoparametric, `coords` holds its nodes' places (num_nodes x dim, the
/// node basis maps it; -mesh_geometry_order 2).
double mapQuadraturePoint(const ReferenceElement &element, const double *coords, int q,
                          PointGeometry &g, bool curved = false);

/// Tangents d x / d xi_k (k < e.dim) of a face element at its point q: through the vertex
/// basis (straight face, coords nv x space) or, curved, the node basis (coords nn x space).
/// t[k][r] for r >= space and k >= e.dim are zero.
void surfaceTangents(const ReferenceElement &e, const double *coords, int space, int q,
                     bool curved, double t[2][3]);

/// Measure of quadrature point q of a face element (dim - 1) embedded in space of dimension
/// `space`: the quadrature weight times the surface Jacobian (`curved`: coords are the nodes').
double surfaceWeight(const ReferenceElement &face, const double *coords, int space, int q,
                     bool curved = false);

/// Unit normal of a face element at its point q, on the side of `side` (a normal of the face,
/// e.g. faceNormal's): the curved face's own normal where it is curved.
void surfaceNormal(const ReferenceElement &face, const double *coords, int space, int q,
                   bool curved, const double side[3], double n[3]);

/// Normal of a face from the order of its vertices (not normalised; Newell's method in 3D,
/// so warped quadrilaterals get their mean normal). coords: nv x space.
void faceNormal(const double *coords, int nv, int space, double n[3]);

/// Inverse map: reference coordinates of physical point x (Newton, exact for affine cells).
/// Returns true when x lies inside the cell (with a small tolerance). `curved`: coords are the
/// nodes' places and the node basis maps the cell.
bool locatePoint(const ReferenceElement &element, const double *coords, const double x[],
                 double xi[], bool curved = false);

} // namespace poroseam
