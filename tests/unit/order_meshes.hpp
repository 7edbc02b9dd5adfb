// Meshes for the element-order tests: the unit square or cube cut into n^dim squares or cubes,
// kept as quadrilaterals / hexahedra or split into triangles (2 per square) / tetrahedra (6 per
// cube, Kuhn), with the vertices moved by a smooth map so that cells are neither uniform nor
// (tensor cells) affine. "Cell Sets" = 1 on every cell, "Face Sets" = 1 on every boundary face.
// With an interface (n even): "Cell Sets" = 2 beyond the plane x = 1/2, which the map keeps
// straight, and "Face Sets" = 2 on the faces in that plane.
// With a jitter j > 0 every interior vertex first moves by a pseudo-random amount (seeded,
// so the same mesh every run) of up to j h in each component (vertices on the interface only
// along it), so that cells stay non-affine and irregular at every h, not only on the coarse
// meshes; every simplex keeps its orientation (checked).
// Built with DMPlexCreateFromCellListPetsc (PETSc 3.18 has no simplex generator here).
#pragma once

#include <cmath>
#include <petscdmplex.h>
#include <random>
#include <vector>

namespace poroseam::test_support {

/// x -> x + amplitude * prod sin(2 pi x_d) e (all components): fixes the boundary of the unit
/// box, moves interior vertices by up to `amplitude`.
inline void distort(int dim, double amplitude, double *x)
{
  double s = 1.0;
  for (int d = 0; d < dim; ++d)
    s *= std::sin(2.0 * M_PI * x[d]);
  for (int d = 0; d < dim; ++d)
    x[d] += amplitude * s * (d == 0 ? 1.0 : -0.7);
}

inline PetscErrorCode createOrderMesh(int dim, bool simplex, int n, double amplitude, DM *dm,
                                      bool interface = false, double jitter = 0.0)
{
  PetscFunctionBeginUser;
  const int nv1 = n + 1;
  const int nverts = dim == 2 ? nv1 * nv1 : nv1 * nv1 * nv1;
  std::vector<double> coords(nverts * dim), regular(nverts * dim);
  auto vid = [&](int i, int j, int k) { return i + nv1 * (j + nv1 * k); };
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < (dim == 3 ? nv1 : 1); ++k)
    for (int j = 0; j < nv1; ++j)
      for (int i = 0; i < nv1; ++i) {
        double *x = &coords[vid(i, j, k) * dim];
        const int index[3] = {i, j, k};
        bool interior = true;
        for (int d = 0; d < dim; ++d) {
          x[d] = (double)index[d] / n;
          regular[vid(i, j, k) * dim + d] = x[d];
          interior = interior && index[d] > 0 && index[d] < n;
        }
        for (int d = 0; d < dim && jitter > 0.0; ++d) {
          const double move = jitter * unit(rng) / n; // drawn for every vertex: a fixed sequence
          if (interior && !(interface && d == 0 && 2 * i == n)) x[d] += move;
        }
        distort(dim, amplitude, x);
      }
  std::vector<PetscInt> cells;
  int corners = 0;
  auto volumeSign = [&](const std::vector<PetscInt> &c, const std::vector<double> &xs) {
    // Sign of the simplex volume (det of edge vectors).
    const double *a = &xs[c[0] * dim];
    double e[3][3] = {{0}};
    for (int r = 1; r <= dim; ++r)
      for (int d = 0; d < dim; ++d)
        e[r - 1][d] = xs[c[r] * dim + d] - a[d];
    if (dim == 2) return e[0][0] * e[1][1] - e[0][1] * e[1][0];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  // The orientation of PETSc's reference simplex: counter-clockwise triangle, and a
  // tetrahedron whose edge vectors from vertex 0 have a negative determinant.
  bool inverted = false;
  auto addSimplex = [&](std::vector<PetscInt> c) {
    if (volumeSign(c, regular) * (dim == 2 ? 1.0 : -1.0) < 0) std::swap(c[0], c[1]);
    inverted = inverted || volumeSign(c, coords) * volumeSign(c, regular) <= 0.0;
    cells.insert(cells.end(), c.begin(), c.end());
  };
  // A tensor cell is valid (its multilinear map one-to-one) when the signed edge vectors at
  // every corner keep the reference orientation: checked at the 4 or 8 corners.
  auto tensorCellValid = [&](int i, int j, int k) {
    for (int corner = 0; corner < (1 << dim); ++corner) {
      const int at[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
      const double *x = &coords[vid(i + at[0], j + at[1], k + at[2]) * dim];
      double e[3][3] = {{0}};
      for (int r = 0; r < dim; ++r) {
        int to[3] = {at[0], at[1], at[2]};
        to[r] = 1 - to[r];
        const double *y = &coords[vid(i + to[0], j + to[1], k + to[2]) * dim];
        for (int d = 0; d < dim; ++d)
          e[r][d] = (at[r] ? -1.0 : 1.0) * (y[d] - x[d]);
      }
      const double det = dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0]
                                  : e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                        e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                        e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
      if (det <= 0.0) return false;
    }
    return true;
  };
  for (int k = 0; k < (dim == 3 ? n : 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (!simplex) inverted = inverted || !tensorCellValid(i, j, k);
        if (dim == 2) {
          const PetscInt v00 = vid(i, j, 0), v10 = vid(i + 1, j, 0), v11 = vid(i + 1, j + 1, 0),
                         v01 = vid(i, j + 1, 0);
          if (simplex) {
            // Alternate the diagonal so the mesh has no preferred direction.
            if ((i + j) % 2) {
              addSimplex({v00, v10, v11});
              addSimplex({v00, v11, v01});
            } else {
              addSimplex({v00, v10, v01});
              addSimplex({v10, v11, v01});
            }
            corners = 3;
          } else {
            cells.insert(cells.end(), {v00, v10, v11, v01});
            corners = 4;
          }
        } else {
          auto v = [&](int a, int b, int c) { return (PetscInt)vid(i + a, j + b, k + c); };
          if (simplex) {
            // Kuhn: the 6 paths from corner 000 to 111 along the axes.
            const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                     {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
            for (const auto &p : perms) {
              int at[3] = {0, 0, 0};
              std::vector<PetscInt> c{v(0, 0, 0)};
              for (int s = 0; s < 3; ++s) {
                at[p[s]] = 1;
                c.push_back(v(at[0], at[1], at[2]));
              }
              addSimplex(c);
            }
            corners = 4;
          } else {
            // DMPlex hexahedron: bottom face clockwise seen from outside, then top.
            cells.insert(cells.end(), {v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0), v(0, 0, 1),
                                       v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)});
            corners = 8;
          }
        }
      }
  PetscCheck(!inverted, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "createOrderMesh: the distortion (amplitude %g, jitter %g) inverts a cell", amplitude,
             jitter);
  const PetscInt ncells = (PetscInt)(cells.size() / corners);
  PetscCall(DMPlexCreateFromCellListPetsc(PETSC_COMM_SELF, dim, ncells, nverts, corners, PETSC_TRUE,
                                          cells.data(), dim, coords.data(), dm));
  PetscCall(DMCreateLabel(*dm, "Cell Sets"));
  PetscCall(DMCreateLabel(*dm, "Face Sets"));
  DMLabel cellSets, faceSets;
  PetscCall(DMGetLabel(*dm, "Cell Sets", &cellSets));
  PetscCall(DMGetLabel(*dm, "Face Sets", &faceSets));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
  // The mean x of a point's vertices, and whether they all lie on the plane x = 1/2.
  Vec xv;
  PetscSection cs;
  PetscCall(DMGetCoordinatesLocal(*dm, &xv));
  PetscCall(DMGetCoordinateSection(*dm, &cs));
  auto meanX = [&](PetscInt point, double *mean, bool *onPlane) -> PetscErrorCode {
    PetscScalar *xc = nullptr;
    PetscInt nc = 0;
    PetscFunctionBeginUser;
    PetscCall(DMPlexVecGetClosure(*dm, cs, xv, point, &nc, &xc));
    *mean = 0.0, *onPlane = true;
    for (PetscInt a = 0; a < nc / dim; ++a) {
      *mean += xc[a * dim] / (nc / dim);
      *onPlane = *onPlane && std::fabs(xc[a * dim] - 0.5) < 1e-12;
    }
    PetscCall(DMPlexVecRestoreClosure(*dm, cs, xv, point, &nc, &xc));
    PetscFunctionReturn(0);
  };
  for (PetscInt c = cStart; c < cEnd; ++c) {
    double x;
    bool on;
    PetscCall(meanX(c, &x, &on));
    PetscCall(DMLabelSetValue(cellSets, c, interface && x > 0.5 ? 2 : 1));
  }
  PetscCall(DMPlexMarkBoundaryFaces(*dm, 1, faceSets));
  if (interface) {
    PetscCheck(n % 2 == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
               "an interface at x = 1/2 needs an even n, not %d", n);
    PetscInt fStart, fEnd;
    PetscCall(DMPlexGetHeightStratum(*dm, 1, &fStart, &fEnd));
    for (PetscInt f = fStart; f < fEnd; ++f) {
      double x;
      bool on;
      PetscCall(meanX(f, &x, &on));
      if (on) PetscCall(DMLabelSetValue(faceSets, f, 2));
    }
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam::test_support
