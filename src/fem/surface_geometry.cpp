// The geometry of a face element embedded in its cell's space: tangents, the measure of a
// quadrature point, the unit normal (straight or curved faces), and a face's normal from its
// vertex order. Apart from reference_element.cpp (which builds elements) and cell_map.cpp
// (the map of a full-dimensional cell): faces have no square Jacobian to invert.
#include "poroseam/reference_element.hpp"

#include <cmath>

namespace poroseam {

void surfaceTangents(const ReferenceElement &e, const double *coords, int space, int q, bool curved,
                     double t[2][3])
{
  const int nb = curved ? e.num_nodes : e.num_vertices;
  const double *dphi =
      curved ? &e.node_basis_derivatives[q * nb * e.dim] : &e.basis_derivatives[q * nb * e.dim];
  for (int k = 0; k < 2; ++k)
    for (int r = 0; r < 3; ++r)
      t[k][r] = 0.0;
  for (int k = 0; k < e.dim; ++k)
    for (int a = 0; a < nb; ++a)
      for (int r = 0; r < space; ++r)
        t[k][r] += coords[a * space + r] * dphi[a * e.dim + k];
}

double surfaceWeight(const ReferenceElement &e, const double *coords, int space, int q, bool curved)
{
  double t[2][3];
  surfaceTangents(e, coords, space, q, curved, t);
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

void surfaceNormal(const ReferenceElement &e, const double *coords, int space, int q, bool curved,
                   const double side[3], double n[3])
{
  double t[2][3];
  surfaceTangents(e, coords, space, q, curved, t);
  if (space == 2)
    n[0] = t[0][1], n[1] = -t[0][0], n[2] = 0.0;
  else
    n[0] = t[0][1] * t[1][2] - t[0][2] * t[1][1], n[1] = t[0][2] * t[1][0] - t[0][0] * t[1][2],
    n[2] = t[0][0] * t[1][1] - t[0][1] * t[1][0];
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double sign = n[0] * side[0] + n[1] * side[1] + n[2] * side[2] < 0.0 ? -1.0 : 1.0;
  for (int r = 0; r < 3; ++r)
    n[r] *= sign / length;
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

} // namespace poroseam
