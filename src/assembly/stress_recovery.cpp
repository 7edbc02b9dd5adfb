// Superconvergent patch recovery of stresses at the vertices (stress_recovery.hpp).
#include "poroseam/stress_recovery.hpp"

#include <petscdmplex.h>
#include <petscsf.h>

#include <algorithm>
#include <cmath>

namespace poroseam {

PetscErrorCode PatchRecovery::reset(DM dm)
{
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart_, &vEnd_));
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCheck(pStart == 0, PETSC_COMM_SELF, PETSC_ERR_SUP, "PatchRecovery: chart must start at 0");
  sums_.assign((size_t)pEnd * stride(), 0.0);
  scale_.assign((size_t)pEnd, 0.0);
  PetscFunctionReturn(0);
}

void PatchRecovery::add(PetscInt vertex, const double *xv, const double *xq, double scale,
                        const double *values)
{
  const int n = dim_ + 1;
  if (scale_[vertex] == 0.0) scale_[vertex] = scale;
  double P[4] = {1.0, 0.0, 0.0, 0.0};
  for (int d = 0; d < dim_; ++d)
    P[d + 1] = (xq[d] - xv[d]) / scale_[vertex];
  double *M = &sums_[(size_t)vertex * stride()], *r = M + n * n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      M[i * n + j] += P[i] * P[j];
    for (int c = 0; c < nc_; ++c)
      r[i * nc_ + c] += P[i] * values[c];
  }
}

void PatchRecovery::solve(int n, int components, const double *M, const double *r, double *value)
{
  // Gaussian elimination with partial pivoting on [M | r]; only a_0 is wanted.
  std::vector<double> A(M, M + n * n), B(r, r + n * components);
  double largest = 0.0;
  for (int i = 0; i < n; ++i)
    largest = std::max(largest, std::abs(A[i * n + i]));
  bool singular = largest == 0.0;
  for (int k = 0; k < n && !singular; ++k) {
    int pivot = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(A[i * n + k]) > std::abs(A[pivot * n + k])) pivot = i;
    // Relative to the patch's own scale: points in a line leave a pivot at round-off.
    if (std::abs(A[pivot * n + k]) <= 1e-10 * largest) {
      singular = true;
      break;
    }
    if (pivot != k) {
      for (int j = 0; j < n; ++j)
        std::swap(A[k * n + j], A[pivot * n + j]);
      for (int c = 0; c < components; ++c)
        std::swap(B[k * components + c], B[pivot * components + c]);
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = A[i * n + k] / A[k * n + k];
      for (int j = k; j < n; ++j)
        A[i * n + j] -= f * A[k * n + j];
      for (int c = 0; c < components; ++c)
        B[i * components + c] -= f * B[k * components + c];
    }
  }
  if (singular) {
    for (int c = 0; c < components; ++c)
      value[c] = M[0] > 0.0 ? r[c] / M[0] : 0.0;
    return;
  }
  // Back substitution for every unknown (a_0 needs the others).
  std::vector<double> a(n * components, 0.0);
  for (int i = n - 1; i >= 0; --i)
    for (int c = 0; c < components; ++c) {
      double s = B[i * components + c];
      for (int j = i + 1; j < n; ++j)
        s -= A[i * n + j] * a[j * components + c];
      a[i * components + c] = s / A[i * n + i];
    }
  for (int c = 0; c < components; ++c)
    value[c] = a[c];
}

PetscErrorCode PatchRecovery::finish(DM dm, std::vector<double> &at_vertices)
{
  PetscSF sf;
  MPI_Datatype unit, result;
  const int n = dim_ + 1;
  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(dm, &sf));
  // A patch that spans ranks is summed by the vertex's owner. Each rank built its part with
  // its own scale (the fit does not depend on it, only its conditioning): the parts are first
  // brought to the owner's scale.
  std::vector<double> ownerScale(scale_);
  PetscCall(PetscSFBcastBegin(sf, MPI_DOUBLE, scale_.data(), ownerScale.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPI_DOUBLE, scale_.data(), ownerScale.data(), MPI_REPLACE));
  for (PetscInt v = vStart_; v < vEnd_; ++v) {
    if (scale_[v] == 0.0 || ownerScale[v] == 0.0 || ownerScale[v] == scale_[v]) continue;
    // P_i = (x - xv) / s; with s' : P'_i = P_i s / s'. M'_ij = f_i f_j M_ij, r'_i = f_i r_i.
    const double f = scale_[v] / ownerScale[v];
    double *M = &sums_[(size_t)v * stride()], *r = M + n * n;
    for (int i = 0; i < n; ++i) {
      const double fi = i ? f : 1.0;
      for (int j = 0; j < n; ++j)
        M[i * n + j] *= fi * (j ? f : 1.0);
      for (int c = 0; c < nc_; ++c)
        r[i * nc_ + c] *= fi;
    }
  }
  PetscCallMPI(MPI_Type_contiguous(stride(), MPI_DOUBLE, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  std::vector<double> reduced(sums_);
  PetscCall(PetscSFReduceBegin(sf, unit, sums_.data(), reduced.data(), MPI_SUM));
  PetscCall(PetscSFReduceEnd(sf, unit, sums_.data(), reduced.data(), MPI_SUM));
  PetscCallMPI(MPI_Type_free(&unit));
  // Leaves' sums were added to their roots; a leaf's own entry in `reduced` is its part only,
  // overwritten below by the owner's result.
  std::vector<double> values((sums_.size() / stride()) * nc_, 0.0);
  for (PetscInt v = vStart_; v < vEnd_; ++v) {
    const double *M = &reduced[(size_t)v * stride()];
    solve(n, nc_, M, M + n * n, &values[(size_t)v * nc_]);
  }
  PetscCallMPI(MPI_Type_contiguous(nc_, MPI_DOUBLE, &result));
  PetscCallMPI(MPI_Type_commit(&result));
  std::vector<double> shared(values);
  PetscCall(PetscSFBcastBegin(sf, result, values.data(), shared.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, result, values.data(), shared.data(), MPI_REPLACE));
  PetscCallMPI(MPI_Type_free(&result));
  at_vertices.assign(shared.begin() + (size_t)vStart_ * nc_, shared.begin() + (size_t)vEnd_ * nc_);
  PetscFunctionReturn(0);
}

} // namespace poroseam
