// Stress and strain of a bulk cell for output (fields.h5): averages over the cell's integration
// points of the quantities the cell kernel (cell_kernel.hpp) uses at each point. Kept next to
// the kernel so that both read the same skeleton law: skeletonStress below is the one place
// where the output evaluates it; a law with integration-point history hands its stored stress
// of point q to cellStressAverage instead (the `point_stress` argument).
#pragma once

#include "cell_kernel.hpp"

namespace poroseam {

/// Cell averages, full 3 x 3 tensors, tension positive. Index 2 is the hoop direction when
/// axisymmetric (x = r, y = z), the out-of-plane direction in plane strain.
struct CellStressState {
  double effective_stress[3][3]; ///< sigma' = sigma'_0 + C : eps [Pa] (Biot's effective stress)
  double total_stress[3][3];     ///< sigma = sigma' - alpha p I [Pa]
  double strain[3][3];           ///< eps(u) [-], small strain from the displacements
};

/// The effective stress of the elastic skeleton at one point: sigma' = sigma'_0 + C : eps.
inline void skeletonStress(const CellMaterial &m, const double strain[3][3],
                           const double initial[3][3], double stress[3][3])
{
  physics::elasticStress(m.moduli, strain, stress);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      stress[i][j] += initial[i][j];
}

/// The stresses at every integration point of one cell: visit(q, xq, weight, strain,
/// effective, total) for each point q at position xq with weight `weight` (its measure in the
/// mesh's own space: area in 2D, axisymmetric too; volume in 3D).
///   e, dim, axisymmetric: as CellKernel; m: the cell's material; with_pressure: the closure
///   holds the nv pressures after the nn * dim displacements (CellKernel::with_pressure)
///   coords: vertex coordinates (nv x dim), or with `curved` the nodes' places (nn x dim);
///   x: the closure values (nn: the element's nodes)
///   point_stress(q, xq, strain, stress): the effective stress at point q (position xq)
///   pressure0(xq): the pore pressure of a porous cell without pressure unknowns (drained)
template <class PointStress, class InitialPressure, class Visit>
void forEachStressPoint(const ReferenceElement &e, int dim, bool axisymmetric,
                        const CellMaterial &m, bool with_pressure, const double *coords,
                        const double *x, PointStress &&point_stress, InitialPressure &&pressure0,
                        Visit &&visit, bool curved = false)
{
  const int nv = e.num_vertices, nn = e.num_nodes, nu = nn * dim;
  const double alpha = m.porous ? m.biot.biot_coefficient : 0.0;
  PointGeometry g;
  for (int q = 0; q < e.num_quadrature; ++q) {
    mapQuadraturePoint(e, coords, q, g, curved);
    const double *phi = g.phi, *N = g.node_phi, *dN = g.grad_node_phi;
    // eps = sym(grad u), plus the hoop strain u_r / r when axisymmetric.
    double eps[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) {
          const double v = 0.5 * x[a * dim + i] * dN[a * dim + j];
          eps[i][j] += v;
          eps[j][i] += v;
        }
    if (axisymmetric)
      for (int a = 0; a < nn; ++a)
        eps[2][2] += x[a * dim] * N[a] / g.x[0];
    double stress[3][3], total[3][3];
    point_stress(q, g.x, eps, stress);
    double p = 0.0;
    if (with_pressure)
      for (int a = 0; a < nv; ++a)
        p += phi[a] * x[nu + a];
    else if (m.porous)
      p = pressure0(g.x);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        total[i][j] = stress[i][j] - (i == j ? alpha * p : 0.0);
    visit(q, g.x, g.weight, eps, stress, total);
  }
}

/// Averages over the integration points of one cell, each weighted by its measure, so that a
/// field linear over an affine cell averages to its value at the centroid. Arguments as
/// forEachStressPoint; visit(q, xq, weight, strain, effective, total) sees each point as well.
template <class PointStress, class InitialPressure, class Visit>
CellStressState cellStressAverage(const ReferenceElement &e, int dim, bool axisymmetric,
                                  const CellMaterial &m, bool with_pressure, const double *coords,
                                  const double *x, PointStress &&point_stress,
                                  InitialPressure &&pressure0, Visit &&visit, bool curved = false)
{
  CellStressState out{};
  double measure = 0.0;
  forEachStressPoint(e, dim, axisymmetric, m, with_pressure, coords, x, point_stress, pressure0,
                     [&](int q, const double *xq, double w, const double eps[3][3],
                         const double stress[3][3], const double total[3][3]) {
                       for (int i = 0; i < 3; ++i)
                         for (int j = 0; j < 3; ++j) {
                           out.effective_stress[i][j] += w * stress[i][j];
                           out.total_stress[i][j] += w * total[i][j];
                           out.strain[i][j] += w * eps[i][j];
                         }
                       measure += w;
                       visit(q, xq, w, eps, stress, total);
                     },
                     curved);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      out.effective_stress[i][j] /= measure;
      out.total_stress[i][j] /= measure;
      out.strain[i][j] /= measure;
    }
  return out;
}

template <class PointStress, class InitialPressure>
CellStressState cellStressAverage(const ReferenceElement &e, int dim, bool axisymmetric,
                                  const CellMaterial &m, bool with_pressure, const double *coords,
                                  const double *x, PointStress &&point_stress,
                                  InitialPressure &&pressure0)
{
  return cellStressAverage(e, dim, axisymmetric, m, with_pressure, coords, x, point_stress,
                           pressure0,
                           [](int, const double *, double, const double[3][3],
                              const double[3][3], const double[3][3]) {});
}

} // namespace poroseam
