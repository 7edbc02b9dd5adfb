// Continuous stresses at the vertices, recovered from the integration points (superconvergent
// patch recovery after Zienkiewicz and Zhu, 1992): for each vertex, a linear polynomial is fitted
// by least squares to the values at the integration points of the cells around it (its patch)
// and evaluated at the vertex. The fit reproduces a stress field that is linear over the patch
// exactly, at interior and boundary vertices alike, which is what an engineer needs to read a
// stress at a boundary, a skirt or a fault: the cell values (averages over a cell) sit half a
// cell away from it. A patch whose points do not span the space (too few, or in a line) falls
// back to their mean. Patches end at interfaces (the two faces have their own vertices) and
// run across region boundaries (where the tangential stress jumps: use the cell values there).
#pragma once

#include <petscdm.h>
#include <vector>

namespace poroseam {

class PatchRecovery {
public:
  /// `dim`: of the mesh; `components`: values per integration point.
  PatchRecovery(int dim, int components) : dim_(dim), nc_(components) {}

  /// Clears the patches of every local point of `dm` (call before the cells' add()).
  PetscErrorCode reset(DM dm);
  /// Adds one integration point at xq with `values` to the patch of `vertex` (a local point),
  /// which sits at xv; `scale` is a length of the cells around it (the fit's conditioning).
  void add(PetscInt vertex, const double *xv, const double *xq, double scale,
           const double *values);
  /// Sums the patches over the ranks (a vertex's patch may span several), fits, and gives the
  /// values at every local vertex (ghosts included), `components` each, in vertex order from
  /// the start of the depth-0 stratum. Collective.
  PetscErrorCode finish(DM dm, std::vector<double> &at_vertices);

  /// The fit of one patch: the normal equations M a = r of size n = dim + 1 (M n x n, r n x
  /// components, row-major), solved for the constant term a_0 (the value at the vertex) into
  /// `value`; the mean r_0 / M_00 when M is singular. Pure, for the unit test.
  static void solve(int n, int components, const double *M, const double *r, double *value);

private:
  int dim_, nc_;
  PetscInt vStart_ = 0, vEnd_ = 0;
  std::vector<double> sums_;  // per local point: M (n x n), r (n x nc)
  std::vector<double> scale_; // per vertex: the first scale seen (0: none yet)
  int stride() const { return (dim_ + 1) * (dim_ + 1 + nc_); }
};

} // namespace poroseam
