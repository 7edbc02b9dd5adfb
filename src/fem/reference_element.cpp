// Lagrange elements from PETSc (PetscFECreateLagrange, PetscFECreateTabulation) with
// quadrature from PetscDT, their basis functions put in DMPlex closure order, and their
// evaluation at any reference point. The map of a physical cell and its inverse are in
// cell_map.cpp, the geometry of face elements in surface_geometry.cpp.
// docs/elements.md says why each choice was made.
#include "poroseam/reference_element.hpp"

#include <algorithm>
#include <cmath>
#include <petscdmplex.h>
#include <petscfe.h>

namespace poroseam {
namespace {

/// Monomials of the polynomial space of a Lagrange element of `order`: total degree <= order on
/// simplices (P_k), degree <= order in each variable on tensor cells (Q_k).
std::vector<int> monomialExponents(int dim, bool simplex, int order)
{
  std::vector<int> exps;
  const int n = order + 1;
  const int count = dim == 1 ? n : dim == 2 ? n * n : n * n * n;
  for (int m = 0; m < count; ++m) {
    int e[3] = {m % n, (m / n) % n, (m / (n * n)) % n}, sum = 0;
    for (int d = 0; d < dim; ++d)
      sum += e[d];
    if (simplex && sum > order) continue;
    for (int d = 0; d < dim; ++d)
      exps.push_back(e[d]);
  }
  return exps;
}

/// Values (and gradients, when dmono is not null) of the monomials at xi.
void evaluateMonomials(int dim, const std::vector<int> &exps, const double xi[], double *mono,
                       double *dmono)
{
  const int nm = (int)exps.size() / dim;
  for (int m = 0; m < nm; ++m) {
    const int *e = &exps[m * dim];
    double v = 1.0;
    for (int d = 0; d < dim; ++d)
      v *= std::pow(xi[d], e[d]);
    mono[m] = v;
    if (!dmono) continue;
    for (int k = 0; k < dim; ++k) {
      double g = e[k] == 0 ? 0.0 : e[k] * std::pow(xi[k], e[k] - 1);
      for (int d = 0; d < dim; ++d)
        if (d != k) g *= std::pow(xi[d], e[d]);
      dmono[m * dim + k] = g;
    }
  }
}

void evaluateExpansion(const ReferenceElement::Expansion &x, int dim, int nb, const double xi[],
                       double phi[], double dphi[])
{
  const int nm = x.num_monomials;
  std::vector<double> mono(nm), dmono(dphi ? nm * dim : 0);
  evaluateMonomials(dim, x.exponents, xi, mono.data(), dphi ? dmono.data() : nullptr);
  for (int a = 0; a < nb; ++a) {
    const double *c = &x.coefficients[a * nm];
    double v = 0.0;
    for (int m = 0; m < nm; ++m)
      v += c[m] * mono[m];
    phi[a] = v;
    if (!dphi) continue;
    for (int d = 0; d < dim; ++d) {
      double g = 0.0;
      for (int m = 0; m < nm; ++m)
        g += c[m] * dmono[m * dim + d];
      dphi[a * dim + d] = g;
    }
  }
}

/// Solves A X = B in place (A n x n row-major, B n x r), Gaussian elimination with partial
/// pivoting; n is at most 27 (the Lagrange Q2 hexahedron).
PetscErrorCode solveDense(int n, std::vector<double> A, int r, std::vector<double> &B)
{
  PetscFunctionBeginUser;
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(A[i * n + k]) > std::fabs(A[piv * n + k])) piv = i;
    PetscCheck(std::fabs(A[piv * n + k]) > 1e-12, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "singular Vandermonde matrix of a reference element");
    if (piv != k) {
      for (int j = 0; j < n; ++j)
        std::swap(A[k * n + j], A[piv * n + j]);
      for (int j = 0; j < r; ++j)
        std::swap(B[k * r + j], B[piv * r + j]);
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = A[i * n + k] / A[k * n + k];
      for (int j = k; j < n; ++j)
        A[i * n + j] -= f * A[k * n + j];
      for (int j = 0; j < r; ++j)
        B[i * r + j] -= f * B[k * r + j];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    for (int j = 0; j < r; ++j) {
      double v = B[k * r + j];
      for (int i = k + 1; i < n; ++i)
        v -= A[k * n + i] * B[i * r + j];
      B[k * r + j] = v / A[k * n + k];
    }
  }
  PetscFunctionReturn(0);
}

/// One Lagrange basis from PETSc with its functions put in closure order.
struct Basis {
  int count = 0;
  std::vector<double> nodes; ///< count x dim, closure order
  std::vector<int> petsc_of; ///< petsc_of[a]: PetscFE's index of closure-order function a
  PetscFE fe = nullptr;
};

/// Centroids of the points of the reference cell's closure, in closure order.
PetscErrorCode closureCentroids(DMPolytopeType type, int dim, std::vector<double> &centroids)
{
  DM ref;
  Vec coords;
  PetscSection csec;
  PetscInt n = 0, *points = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateReferenceCell(PETSC_COMM_SELF, type, &ref));
  PetscCall(DMGetCoordinatesLocal(ref, &coords));
  PetscCall(DMGetCoordinateSection(ref, &csec));
  PetscCall(DMPlexGetTransitiveClosure(ref, 0, PETSC_TRUE, &n, &points));
  centroids.assign(n * dim, 0.0);
  for (PetscInt k = 0; k < n; ++k) {
    PetscScalar *x = nullptr;
    PetscInt nx = 0;
    PetscCall(DMPlexVecGetClosure(ref, csec, coords, points[2 * k], &nx, &x));
    for (PetscInt a = 0; a < nx / dim; ++a)
      for (int d = 0; d < dim; ++d)
        centroids[k * dim + d] += x[a * dim + d] / (double)(nx / dim);
    PetscCall(DMPlexVecRestoreClosure(ref, csec, coords, points[2 * k], &nx, &x));
  }
  PetscCall(DMPlexRestoreTransitiveClosure(ref, 0, PETSC_TRUE, &n, &points));
  PetscCall(DMDestroy(&ref));
  PetscFunctionReturn(0);
}

/// PetscFECreateLagrange of `order`, and the closure order of its functions: each function is
/// nodal (a point evaluation), and at order <= 2 every node sits at the centroid of one point
/// of the reference cell's closure (a vertex, an edge's midpoint, a face's or the cell's
/// centre). Closure-order position = position of that point in the closure, so the basis lines
/// up with DMPlexVecGetClosure on a section with one node per point.
PetscErrorCode createBasis(DMPolytopeType type, int dim, bool simplex, int order, Basis &b)
{
  PetscDualSpace sp;
  PetscInt n;
  std::vector<double> centroids;
  PetscFunctionBeginUser;
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, dim, 1, simplex ? PETSC_TRUE : PETSC_FALSE,
                                  order, PETSC_DETERMINE, &b.fe));
  PetscCall(PetscFEGetDualSpace(b.fe, &sp));
  PetscCall(PetscDualSpaceGetDimension(sp, &n));
  PetscCall(closureCentroids(type, dim, centroids));
  const int np = (int)centroids.size() / dim;
  std::vector<int> at_point(np, -1);
  for (PetscInt i = 0; i < n; ++i) {
    PetscQuadrature f;
    const PetscReal *pts;
    PetscInt nf;
    PetscCall(PetscDualSpaceGetFunctional(sp, i, &f));
    PetscCall(PetscQuadratureGetData(f, nullptr, nullptr, &nf, &pts, nullptr));
    PetscCheck(nf == 1, PETSC_COMM_SELF, PETSC_ERR_SUP, "Lagrange functional %d is not a point",
               (int)i);
    int found = -1;
    for (int k = 0; k < np; ++k) {
      double dist = 0.0;
      for (int d = 0; d < dim; ++d)
        dist += std::fabs(pts[d] - centroids[k * dim + d]);
      if (dist < 1e-10) found = k;
    }
    PetscCheck(found >= 0 && at_point[found] < 0, PETSC_COMM_SELF, PETSC_ERR_SUP,
               "order %d on %s: node %d is not alone at a closure point's centre", order,
               DMPolytopeTypes[type], (int)i);
    at_point[found] = (int)i;
  }
  b.count = (int)n;
  b.nodes.clear();
  b.petsc_of.clear();
  for (int k = 0; k < np; ++k) {
    if (at_point[k] < 0) continue;
    b.petsc_of.push_back(at_point[k]);
    for (int d = 0; d < dim; ++d)
      b.nodes.push_back(centroids[k * dim + d]);
  }
  PetscFunctionReturn(0);
}

/// Values and reference gradients of basis b at points (np x dim) by PetscFECreateTabulation,
/// in closure order: phi[p * count + a], dphi[(p * count + a) * dim + d].
PetscErrorCode tabulate(const Basis &b, int dim, const std::vector<double> &points,
                        std::vector<double> &phi, std::vector<double> &dphi)
{
  PetscTabulation T;
  const int np = (int)points.size() / dim, nb = b.count;
  PetscFunctionBeginUser;
  std::vector<PetscReal> pts(points.begin(), points.end());
  PetscCall(PetscFECreateTabulation(b.fe, 1, np, pts.data(), 1, &T));
  phi.resize(np * nb);
  dphi.resize(np * nb * dim);
  for (int p = 0; p < np; ++p)
    for (int a = 0; a < nb; ++a) {
      const int i = b.petsc_of[a];
      phi[p * nb + a] = T->T[0][p * nb + i];
      for (int d = 0; d < dim; ++d)
        dphi[(p * nb + a) * dim + d] = T->T[1][(p * nb + i) * dim + d];
    }
  PetscCall(PetscTabulationDestroy(&T));
  PetscFunctionReturn(0);
}

/// The monomial expansion of basis b: phi_a = sum_m c_am m(xi), from PETSc's values at its
/// nodes (phi_a(node_b), the identity up to round-off) and the monomials there.
PetscErrorCode fitExpansion(const Basis &b, int dim, bool simplex, int order,
                            ReferenceElement::Expansion &x)
{
  std::vector<double> phi, dphi;
  PetscFunctionBeginUser;
  x.exponents = monomialExponents(dim, simplex, order);
  const int nm = (int)x.exponents.size() / dim, nb = b.count;
  PetscCheck(nm == nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%d monomials for %d basis functions", nm,
             nb);
  x.num_monomials = nm;
  PetscCall(tabulate(b, dim, b.nodes, phi, dphi));
  // V[p][m] = m(node p); sum_m c_am V[p][m] = phi_a(node p): V C^T = Phi^T.
  std::vector<double> V(nb * nm), rhs(nb * nb);
  for (int p = 0; p < nb; ++p) {
    evaluateMonomials(dim, x.exponents, &b.nodes[p * dim], &V[p * nm], nullptr);
    for (int a = 0; a < nb; ++a)
      rhs[p * nb + a] = phi[p * nb + a];
  }
  PetscCall(solveDense(nb, V, nb, rhs)); // rhs[m * nb + a] = c_am
  x.coefficients.resize(nb * nm);
  for (int a = 0; a < nb; ++a)
    for (int m = 0; m < nm; ++m)
      x.coefficients[a * nm + m] = rhs[m * nb + a];
  PetscFunctionReturn(0);
}

/// The quadrature rule from PETSc: Gauss-Legendre tensor rules with order + 1 points per
/// direction on segments and tensor cells, the minimal symmetric rule of degree 2 * order on
/// simplices. Points are put in a fixed order (tensor: x fastest; simplices: grouped by their
/// nearest vertex), the order the hand-written rules of the linear elements had, so that
/// integration-point history keeps its layout.
/// Gauss-Legendre rules are symmetric about 0, but PETSc computes them by an eigensolve
/// (Golub-Welsch) that leaves the points and weights symmetric only to the last bit: -x_i and
/// x_(n-1-i) differ by an ulp. A symmetric cell under a symmetric load then has stresses that
/// differ at round-off where they are equal (sigma_2 = sigma_3 of a triaxial element), and a
/// return mapping on a yield surface's edge decides that tie by the last bit (measured: the
/// undrained Mohr-Coulomb element of tests/plasticity/element.py stalled in Newton and was cut
/// back once). Coordinates equal in magnitude to round-off, and weights equal to round-off, are
/// made exactly equal (their mean), as the closed forms are.
void symmetrizeTensorRule(std::vector<double> &points, std::vector<double> &weights)
{
  const double tol = 1e-13;
  std::vector<double> magnitudes;
  for (double x : points) {
    const double m = std::fabs(x);
    bool seen = false;
    for (double &u : magnitudes)
      if (std::fabs(u - m) <= tol) seen = true;
    if (!seen) magnitudes.push_back(m);
  }
  for (double &u : magnitudes) {
    double sum = 0.0;
    int n = 0;
    for (double x : points)
      if (std::fabs(std::fabs(x) - u) <= tol) sum += std::fabs(x), ++n;
    u = sum / n;
  }
  for (double &x : points)
    for (double u : magnitudes)
      if (std::fabs(std::fabs(x) - u) <= tol) x = x < 0.0 ? -u : u;
  const std::vector<double> given = weights;
  for (size_t i = 0; i < weights.size(); ++i) {
    double sum = 0.0;
    int n = 0;
    for (double v : given) // in the same order for every member of a group: the same mean
      if (std::fabs(v - given[i]) <= tol * std::fabs(given[i])) sum += v, ++n;
    weights[i] = sum / n;
  }
}

PetscErrorCode setQuadrature(ReferenceElement &e, int order)
{
  PetscQuadrature q;
  PetscInt nq;
  const PetscReal *pts, *wts;
  PetscFunctionBeginUser;
  if (e.dim == 1 || !e.simplex)
    PetscCall(PetscDTGaussTensorQuadrature(e.dim, 1, order + 1, -1.0, 1.0, &q));
  else
    PetscCall(PetscDTSimplexQuadrature(e.dim, 2 * order, PETSCDTSIMPLEXQUAD_MINSYM, &q));
  PetscCall(PetscQuadratureGetData(q, nullptr, nullptr, &nq, &pts, &wts));
  std::vector<int> perm(nq);
  std::vector<std::vector<double>> key(nq);
  for (PetscInt i = 0; i < nq; ++i) {
    perm[i] = (int)i;
    if (e.dim == 1 || !e.simplex) {
      for (int d = e.dim - 1; d >= 0; --d)
        key[i].push_back(pts[i * e.dim + d]);
    } else {
      int nearest = 0;
      double best = 1e300;
      for (int a = 0; a < e.num_vertices; ++a) {
        double dist = 0.0;
        for (int d = 0; d < e.dim; ++d)
          dist += std::pow(pts[i * e.dim + d] - e.vertex_coords[a * e.dim + d], 2);
        if (dist < best - 1e-12) best = dist, nearest = a;
      }
      key[i].push_back(nearest);
      for (int d = e.dim - 1; d >= 0; --d)
        key[i].push_back(pts[i * e.dim + d]);
    }
  }
  // Keys compared with a tolerance: coordinates that agree to round-off are equal.
  std::stable_sort(perm.begin(), perm.end(), [&](int a, int b) {
    for (size_t k = 0; k < key[a].size(); ++k)
      if (std::fabs(key[a][k] - key[b][k]) > 1e-12) return key[a][k] < key[b][k];
    return false;
  });
  e.quadrature_points.clear();
  e.quadrature_weights.clear();
  for (int i : perm) {
    for (int d = 0; d < e.dim; ++d)
      e.quadrature_points.push_back(pts[i * e.dim + d]);
    e.quadrature_weights.push_back(wts[i]);
  }
  e.num_quadrature = (int)nq;
  if (e.dim == 1 || !e.simplex) symmetrizeTensorRule(e.quadrature_points, e.quadrature_weights);
  PetscCall(PetscQuadratureDestroy(&q));
  PetscFunctionReturn(0);
}

/// The element with both bases, its quadrature rule (Gauss, or with `nodal` one point at each
/// vertex with equal weights) and their tabulation.
PetscErrorCode build(DMPolytopeType type, int order, bool nodal, ReferenceElement &e)
{
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
  PetscCheck(order == 1 || order == 2, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "element order %d: poroseam has orders 1 and 2", order);
  e.order = order;
  Basis vertex, node;
  PetscCall(createBasis(type, e.dim, e.simplex, 1, vertex));
  e.vertex_coords = vertex.nodes;
  PetscCheck((int)vertex.count == e.num_vertices, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "reference cell vertices");
  if (nodal && order == 1) {
    PetscCall(setQuadrature(e, 1));
    double measure = 0.0;
    for (double w : e.quadrature_weights)
      measure += w;
    e.num_quadrature = e.num_vertices;
    e.quadrature_points = e.vertex_coords;
    e.quadrature_weights.assign(e.num_vertices, measure / e.num_vertices);
  } else if (nodal) {
    // One point at every node of the node basis, weighted by the integral of its function
    // (row-sum lumping, computed with the Gauss rule, exact): Simpson on a P2 segment, tensor
    // Simpson (3 x 3 Lobatto) on a Q2 quadrilateral. Exact for the node basis's polynomials,
    // so a uniform traction gives the consistent nodal forces. A P2 triangle's vertices would
    // get weight zero (no contact spring there): refused.
    PetscCheck(e.dim == 1 || !e.simplex, PETSC_COMM_SELF, PETSC_ERR_SUP,
               "a nodal rule at order %d on %s would give its vertices zero weight", order,
               DMPolytopeTypes[type]);
    PetscCall(setQuadrature(e, order));
    PetscCall(createBasis(type, e.dim, e.simplex, order, node));
    std::vector<double> phi, dphi;
    PetscCall(tabulate(node, e.dim, e.quadrature_points, phi, dphi));
    std::vector<double> weights(node.count, 0.0);
    for (int q = 0; q < e.num_quadrature; ++q)
      for (int a = 0; a < node.count; ++a)
        weights[a] += e.quadrature_weights[q] * phi[q * node.count + a];
    PetscCall(PetscFEDestroy(&node.fe));
    e.num_quadrature = node.count;
    e.quadrature_points = node.nodes;
    e.quadrature_weights = weights;
  } else {
    PetscCall(setQuadrature(e, order));
  }
  PetscCall(tabulate(vertex, e.dim, e.quadrature_points, e.basis, e.basis_derivatives));
  PetscCall(fitExpansion(vertex, e.dim, e.simplex, 1, e.vertex_expansion));
  if (order == 1) {
    // The same functions: the node basis is the vertex basis, entry for entry.
    e.num_nodes = e.num_vertices;
    e.node_coords = e.vertex_coords;
    e.node_basis = e.basis;
    e.node_basis_derivatives = e.basis_derivatives;
    e.node_expansion = e.vertex_expansion;
  } else {
    PetscCall(createBasis(type, e.dim, e.simplex, order, node));
    e.num_nodes = node.count;
    e.node_coords = node.nodes;
    PetscCall(tabulate(node, e.dim, e.quadrature_points, e.node_basis, e.node_basis_derivatives));
    PetscCall(fitExpansion(node, e.dim, e.simplex, order, e.node_expansion));
    PetscCall(PetscFEDestroy(&node.fe));
  }
  PetscCall(PetscFEDestroy(&vertex.fe));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ReferenceElement::create(DMPolytopeType type, ReferenceElement *element, int order)
{
  PetscFunctionBeginUser;
  PetscCall(build(type, order, false, *element));
  PetscFunctionReturn(0);
}

PetscErrorCode ReferenceElement::createNodal(DMPolytopeType type, ReferenceElement *element,
                                             int order)
{
  PetscFunctionBeginUser;
  PetscCall(build(type, order, true, *element));
  PetscFunctionReturn(0);
}

void ReferenceElement::evaluate(const double xi[], double phi[], double dphi[]) const
{
  evaluateExpansion(vertex_expansion, dim, num_vertices, xi, phi, dphi);
}

void ReferenceElement::evaluateNodes(const double xi[], double phi[], double dphi[]) const
{
  evaluateExpansion(node_expansion, dim, num_nodes, xi, phi, dphi);
}

} // namespace poroseam