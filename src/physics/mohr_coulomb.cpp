// Mohr-Coulomb perfect plasticity with non-associated flow and tension cut-off, integrated by a
// return mapping in principal stresses. The yield surface is written in the ordered principal
// stresses s1 >= s2 >= s3 (tension positive) as a few planes with constant gradients, so every
// return (to a face, to the triaxial compression or extension edge, to the apex, to the tension
// cut-off and its edges and corner) is the same small linear solve for the plastic multipliers
// of the planes taken as active (Clausen, Damkilde and Andersen's multi-plane return, here
// with the flow directions of the plastic potential). The active set is the smallest one that
// satisfies the Kuhn-Tucker conditions. The consistent tangent is the principal-space tangent
// rotated back with the spin term of an isotropic tensor function (de Souza Neto, Peric and
// Owen, Computational Methods for Plasticity, sections 8.3 and A.3).
#include "poroseam/mohr_coulomb.hpp"

#include <cmath>
#include <sstream>
#include <utility>

namespace poroseam::physics {

namespace {

/// One plane of the yield surface in ordered principal stress space: f = a . s - k <= 0, with
/// plastic strain increment dlambda * b (b the gradient of the plastic potential).
struct Plane {
  double a[3];
  double b[3];
  double k;
  bool tension;
};

constexpr double kPi = 3.14159265358979323846;

/// Relative tolerance of the yield and multiplier checks: the return itself is exact up to
/// round-off (about 1e-15 of the stress scale), so 1e-11 only absorbs round-off and decides
/// the active set on region boundaries, where neighbouring sets give the same stress.
constexpr double kRelativeTolerance = 1e-11;

/// The tension cut-off is active if set below the apex (above it the Mohr-Coulomb planes
/// already keep every principal stress below the apex).
bool tensionCutoffActive(const MohrCoulombParameters &p)
{
  if (p.tension_cutoff < 0.0) return false;
  const double sin_phi = std::sin(p.friction_angle);
  if (sin_phi <= 0.0) return true;
  return p.tension_cutoff < p.cohesion * std::cos(p.friction_angle) / sin_phi;
}

/// The Mohr-Coulomb planes (1 + sin phi) s_i - (1 - sin phi) s_j = 2 c cos phi for
/// (i, j) = (1, 3) (the face of the ordered sector), (2, 3) (its neighbour across the triaxial
/// compression edge s1 = s2) and (1, 2) (its neighbour across the triaxial extension edge
/// s2 = s3); then the tension planes s_i = sigma_t if the cut-off is active.
/// Compression negative: s3 is the major compressive stress.
int yieldPlanes(const MohrCoulombParameters &p, Plane planes[6])
{
  const double sin_phi = std::sin(p.friction_angle), sin_psi = std::sin(p.dilation_angle);
  const double k = 2.0 * p.cohesion * std::cos(p.friction_angle);
  const int pairs[3][2] = {{0, 2}, {1, 2}, {0, 1}};
  int n = 0;
  for (const auto &ij : pairs) {
    Plane &q = planes[n++];
    for (int a = 0; a < 3; ++a)
      q.a[a] = q.b[a] = 0.0;
    q.a[ij[0]] = 1.0 + sin_phi;
    q.a[ij[1]] = -(1.0 - sin_phi);
    q.b[ij[0]] = 1.0 + sin_psi;
    q.b[ij[1]] = -(1.0 - sin_psi);
    q.k = k;
    q.tension = false;
  }
  if (tensionCutoffActive(p))
    for (int i = 0; i < 3; ++i) {
      // Associated flow on the cut-off: opening in tension is normal to the plane.
      Plane &q = planes[n++];
      for (int a = 0; a < 3; ++a)
        q.a[a] = q.b[a] = a == i ? 1.0 : 0.0;
      q.k = p.tension_cutoff;
      q.tension = true;
    }
  return n;
}

double dot3(const double x[3], const double y[3])
{
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/// Principal elastic stiffness D (3x3 block of C on the principal axes) times x.
void principalStiffness(const ElasticModuli &m, const double x[3], double out[3])
{
  const double trace = x[0] + x[1] + x[2];
  for (int a = 0; a < 3; ++a)
    out[a] = m.lambda * trace + 2.0 * m.shear * x[a];
}

/// Solves the n x n system M x = r (n <= 3) by Gaussian elimination with partial pivoting;
/// false if M is singular relative to its largest entry (dependent planes).
bool solveSmall(int n, double M[3][3], double r[3], double x[3])
{
  double scale = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      scale = std::fmax(scale, std::fabs(M[i][j]));
  if (!(scale > 0.0)) return false;
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int i = c + 1; i < n; ++i)
      if (std::fabs(M[i][c]) > std::fabs(M[pivot][c])) pivot = i;
    if (std::fabs(M[pivot][c]) < 1e-10 * scale) return false;
    if (pivot != c) {
      for (int j = 0; j < n; ++j)
        std::swap(M[c][j], M[pivot][j]);
      std::swap(r[c], r[pivot]);
    }
    for (int i = c + 1; i < n; ++i) {
      const double f = M[i][c] / M[c][c];
      for (int j = c; j < n; ++j)
        M[i][j] -= f * M[c][j];
      r[i] -= f * r[c];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    double s = r[i];
    for (int j = i + 1; j < n; ++j)
      s -= M[i][j] * x[j];
    x[i] = s / M[i][i];
  }
  return true;
}

/// The return in principal space: returned principal stresses y and dy/dx (x the trial ones).
struct PrincipalReturn {
  double y[3];
  double dy_dx[3][3];
  YieldState state;
};

/// Return with the planes in `active` (indices into planes): solves a_j . (x - sum_i l_i D b_i)
/// = k_j for the multipliers l, and accepts if every l_i >= 0 and every plane holds at y.
bool tryActiveSet(const ElasticModuli &m, const Plane planes[], int n_planes, const int active[],
                  int n_active, const double x[3], double stress_tol, double multiplier_tol,
                  PrincipalReturn &out)
{
  double Db[3][3], M[3][3], r[3], l[3];
  for (int i = 0; i < n_active; ++i)
    principalStiffness(m, planes[active[i]].b, Db[i]);
  for (int j = 0; j < n_active; ++j) {
    const Plane &q = planes[active[j]];
    for (int i = 0; i < n_active; ++i)
      M[j][i] = dot3(q.a, Db[i]);
    r[j] = dot3(q.a, x) - q.k;
  }
  double Mcopy[3][3];
  for (int j = 0; j < n_active; ++j)
    for (int i = 0; i < n_active; ++i)
      Mcopy[j][i] = M[j][i];
  if (!solveSmall(n_active, Mcopy, r, l)) return false;
  for (int i = 0; i < n_active; ++i)
    if (l[i] < -multiplier_tol) return false;
  for (int a = 0; a < 3; ++a) {
    out.y[a] = x[a];
    for (int i = 0; i < n_active; ++i)
      out.y[a] -= l[i] * Db[i][a];
  }
  for (int j = 0; j < n_planes; ++j)
    if (dot3(planes[j].a, out.y) - planes[j].k > stress_tol) return false;
  // The returned stresses keep the order of the trial ones (the planes of the neighbouring
  // sectors above already enforce it; this guards the tension-only returns too).
  if (out.y[1] > out.y[0] + stress_tol || out.y[2] > out.y[1] + stress_tol) return false;

  // dy/dx = I - D B M^-1 A^T: column c of M^-1 A^T is the multipliers' response to x_c.
  for (int c = 0; c < 3; ++c) {
    double rc[3], lc[3];
    for (int j = 0; j < n_active; ++j) {
      rc[j] = planes[active[j]].a[c];
      for (int i = 0; i < n_active; ++i)
        Mcopy[j][i] = M[j][i];
    }
    solveSmall(n_active, Mcopy, rc, lc);
    for (int a = 0; a < 3; ++a) {
      out.dy_dx[a][c] = a == c ? 1.0 : 0.0;
      for (int i = 0; i < n_active; ++i)
        out.dy_dx[a][c] -= Db[i][a] * lc[i];
    }
  }
  int n_mohr_coulomb = 0;
  bool tension = false;
  for (int i = 0; i < n_active; ++i) {
    if (planes[active[i]].tension)
      tension = true;
    else
      ++n_mohr_coulomb;
  }
  out.state = tension               ? YieldState::tension
              : n_mohr_coulomb == 1 ? YieldState::face
              : n_mohr_coulomb == 2 ? YieldState::edge
                                    : YieldState::apex;
  return true;
}

/// True when the stress lies inside every yield plane by a clear margin, judged on its
/// largest and smallest principal values from the trigonometric closed form. That form costs a
/// fraction of the Jacobi rotations but loses about half the digits at repeated eigenvalues
/// (errors up to ~1e-8 of the deviatoric stress), so the margin is 1e-6 of the stress scale;
/// closer to the surface the full decomposition decides.
bool clearlyInside(const MohrCoulombParameters &p, const double s[3][3])
{
  const double mean = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  const double off = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
  const double d0 = s[0][0] - mean, d1 = s[1][1] - mean, d2 = s[2][2] - mean;
  const double radius = std::sqrt((d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0);
  double largest = mean, smallest = mean;
  if (radius > 0.0) {
    // Eigenvalues mean + 2 radius cos(angle + 2 pi k / 3), cos(3 angle) = det(dev / radius) / 2.
    const double b00 = d0 / radius, b11 = d1 / radius, b22 = d2 / radius;
    const double b01 = s[0][1] / radius, b02 = s[0][2] / radius, b12 = s[1][2] / radius;
    const double det = b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) +
                       b02 * (b01 * b12 - b11 * b02);
    const double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, 0.5 * det))) / 3.0;
    largest = mean + 2.0 * radius * std::cos(angle);
    smallest = mean + 2.0 * radius * std::cos(angle + 2.0 * kPi / 3.0);
  }
  const double margin =
      1e-6 * (std::fabs(mean) + radius + p.cohesion + std::fmax(p.tension_cutoff, 0.0));
  const double sin_phi = std::sin(p.friction_angle);
  const double f = (1.0 + sin_phi) * largest - (1.0 - sin_phi) * smallest -
                   2.0 * p.cohesion * std::cos(p.friction_angle);
  if (f > -margin) return false;
  return !tensionCutoffActive(p) || largest - p.tension_cutoff < -margin;
}

/// The return of the trial principal stresses x (descending) to the yield surface.
PrincipalReturn principalReturn(const MohrCoulombParameters &p, const double x[3], bool &elastic)
{
  Plane planes[6];
  const int n = yieldPlanes(p, planes);
  double scale = std::fmax(std::fabs(x[0]), std::fabs(x[2]));
  scale = std::fmax(scale, p.cohesion);
  if (tensionCutoffActive(p)) scale = std::fmax(scale, p.tension_cutoff);
  const double stress_tol = kRelativeTolerance * scale;
  const double multiplier_tol = stress_tol / p.elastic.shear;

  PrincipalReturn out{};
  elastic = true;
  for (int j = 0; j < n; ++j)
    if (dot3(planes[j].a, x) - planes[j].k > stress_tol) elastic = false;
  if (elastic) return out;

  // Active sets by increasing size: a face before its edges, an edge before a corner.
  for (int size = 1; size <= 3; ++size)
    for (int mask = 1; mask < (1 << n); ++mask) {
      int active[6], count = 0;
      for (int j = 0; j < n; ++j)
        if (mask & (1 << j)) active[count++] = j;
      if (count != size) continue;
      if (tryActiveSet(p.elastic, planes, n, active, count, x, stress_tol, multiplier_tol, out))
        return out;
    }

  // No set of planes reached with non-negative multipliers: the trial stress lies beyond the
  // corner where every plane meets, in the part of space that a non-associated flow cannot
  // reach (e.g. isotropic tension with psi = 0: no volumetric plastic strain). The stress goes
  // to that corner, as in de Souza Neto et al.'s apex return: the apex c / tan(phi) of the
  // Mohr-Coulomb cone, or the corner of the tension cut-off. The stress no longer depends on
  // the strain there. (Tresca without cut-off, which has no apex, never gets here: the faces and
  // edges of its prism reach every point, with deviatoric flow from any trial stress.)
  const bool cutoff = tensionCutoffActive(p);
  const double corner = cutoff
                            ? p.tension_cutoff
                            : p.cohesion * std::cos(p.friction_angle) / std::sin(p.friction_angle);
  for (int a = 0; a < 3; ++a) {
    out.y[a] = corner;
    for (int c = 0; c < 3; ++c)
      out.dy_dx[a][c] = 0.0;
  }
  out.state = cutoff ? YieldState::tension : YieldState::apex;
  return out;
}

void elasticResponse(const ElasticModuli &m, const double initial_stress[3][3],
                     const SkeletonHistory &committed, const double strain[3][3],
                     SkeletonResponse &r)
{
  double elastic_strain[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      elastic_strain[i][j] = strain[i][j] - committed.plastic_strain[i][j];
  elasticStress(m, elastic_strain, r.stress);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r.stress[i][j] += initial_stress[i][j];
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          r.tangent[i][j][k][l] = (i == j && k == l ? m.lambda : 0.0) +
                                  m.shear * ((i == k && j == l) + (i == l && j == k));
    }
  r.state = YieldState::elastic;
  r.updated = committed;
}

} // namespace

void symmetricEigen(const double a[3][3], double values[3], double vectors[3][3])
{
  // Cyclic Jacobi rotations: orthonormal eigenvectors to round-off, also for repeated
  // eigenvalues (where closed-form solvers lose the vectors), and quadratic convergence (a few
  // sweeps for 3x3).
  double A[3][3], V[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      A[i][j] = 0.5 * (a[i][j] + a[j][i]);
      V[i][j] = i == j ? 1.0 : 0.0;
    }
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    bool rotated = false;
    for (const auto &pq : pairs) {
      const int p = pq[0], q = pq[1];
      // Negligible against both diagonal entries: adding it would not change them in double.
      if (std::fabs(A[p][q]) <= 1e-18 * (std::fabs(A[p][p]) + std::fabs(A[q][q]))) {
        A[p][q] = A[q][p] = 0.0;
        continue;
      }
      if (A[p][q] == 0.0) continue;
      rotated = true;
      // The rotation that zeroes A[p][q]: t = tan of its angle, the smaller root of
      // t^2 + 2 theta t - 1 = 0.
      const double theta = (A[q][q] - A[p][p]) / (2.0 * A[p][q]);
      const double t =
          (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
      for (int k = 0; k < 3; ++k) {
        const double akp = A[k][p], akq = A[k][q];
        A[k][p] = c * akp - s * akq;
        A[k][q] = s * akp + c * akq;
      }
      for (int k = 0; k < 3; ++k) {
        const double apk = A[p][k], aqk = A[q][k];
        A[p][k] = c * apk - s * aqk;
        A[q][k] = s * apk + c * aqk;
      }
      for (int k = 0; k < 3; ++k) {
        const double vkp = V[k][p], vkq = V[k][q];
        V[k][p] = c * vkp - s * vkq;
        V[k][q] = s * vkp + c * vkq;
      }
    }
    if (!rotated) break;
  }
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (A[order[j]][order[j]] > A[order[i]][order[i]]) std::swap(order[i], order[j]);
  for (int c = 0; c < 3; ++c) {
    values[c] = A[order[c]][order[c]];
    for (int i = 0; i < 3; ++i)
      vectors[i][c] = V[i][order[c]];
  }
}

std::string mohrCoulombParameterError(const MohrCoulombParameters &p)
{
  std::ostringstream why;
  const double deg = 180.0 / kPi;
  const double bulk = p.elastic.lambda + 2.0 * p.elastic.shear / 3.0;
  if (!(p.elastic.shear > 0.0) || !(bulk > 0.0) || !std::isfinite(p.elastic.lambda))
    why << "elastic moduli must give a positive shear modulus and bulk modulus (got G = "
        << p.elastic.shear << " Pa, K = " << bulk << " Pa)";
  else if (!(p.cohesion >= 0.0) || !std::isfinite(p.cohesion))
    why << "cohesion must be >= 0 Pa (got " << p.cohesion << ")";
  else if (!(p.friction_angle >= 0.0 && p.friction_angle < 0.5 * kPi))
    why << "friction angle must be in [0, 90) degrees (got " << p.friction_angle * deg << ")";
  else if (!(p.dilation_angle >= 0.0 && p.dilation_angle <= p.friction_angle))
    why << "dilation angle must be in [0, friction angle = " << p.friction_angle * deg
        << "] degrees (got " << p.dilation_angle * deg << ")";
  else if (p.cohesion == 0.0 && p.friction_angle == 0.0)
    why << "cohesion and friction angle are both zero: the soil would have no strength";
  else if (std::isnan(p.tension_cutoff) || std::isinf(p.tension_cutoff))
    why << "tension cut-off must be a finite stress >= 0 Pa (got " << p.tension_cutoff << ")";
  return why.str();
}

SkeletonResponse elasticSkeletonResponse(const ElasticModuli &m, const double initial_stress[3][3],
                                         const SkeletonHistory &committed,
                                         const double strain[3][3])
{
  SkeletonResponse r;
  elasticResponse(m, initial_stress, committed, strain, r);
  return r;
}

SkeletonResponse mohrCoulombResponse(const MohrCoulombParameters &p,
                                     const double initial_stress[3][3],
                                     const SkeletonHistory &committed, const double strain[3][3])
{
  SkeletonResponse r;
  elasticResponse(p.elastic, initial_stress, committed, strain, r);
  if (clearlyInside(p, r.stress)) return r;
  double x[3], Q[3][3];
  symmetricEigen(r.stress, x, Q);
  bool elastic = false;
  const PrincipalReturn ret = principalReturn(p, x, elastic);
  if (elastic) return r;

  const ElasticModuli &m = p.elastic;
  // sigma = sum_a y_a n_a n_a on the trial stress's principal axes, which the return keeps.
  // Plastic strain increment C^-1 : (sigma_trial - sigma), principal on the same axes:
  // D^-1 = (I - lambda / (3 lambda + 2 G) 1 1^T) / (2 G).
  double dx[3], de[3];
  for (int a = 0; a < 3; ++a)
    dx[a] = x[a] - ret.y[a];
  const double dtrace = dx[0] + dx[1] + dx[2];
  for (int a = 0; a < 3; ++a)
    de[a] = (dx[a] - m.lambda / (3.0 * m.lambda + 2.0 * m.shear) * dtrace) / (2.0 * m.shear);
  double norm2 = 0.0;
  for (int a = 0; a < 3; ++a)
    norm2 += de[a] * de[a];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0.0, e = 0.0;
      for (int a = 0; a < 3; ++a) {
        s += ret.y[a] * Q[i][a] * Q[j][a];
        e += de[a] * Q[i][a] * Q[j][a];
      }
      r.stress[i][j] = s;
      r.updated.plastic_strain[i][j] = committed.plastic_strain[i][j] + e;
    }
  r.updated.equivalent_plastic_strain =
      committed.equivalent_plastic_strain + std::sqrt(2.0 / 3.0 * norm2);
  r.state = ret.state;

  // Tangent on the principal axes: d sigma_aa / d eps_ee = (dy/dx D)_ae, and the shear terms
  // d sigma_ab / d eps_ab = G (y_a - y_b) / (x_a - x_b) from the rotation of the axes; for
  // (nearly) equal trial stresses its limit dy_a/dx_a - dy_a/dx_b.
  double PD[3][3];
  for (int a = 0; a < 3; ++a)
    for (int e = 0; e < 3; ++e)
      PD[a][e] = m.lambda * (ret.dy_dx[a][0] + ret.dy_dx[a][1] + ret.dy_dx[a][2]) +
                 2.0 * m.shear * ret.dy_dx[a][e];
  // Dyads of the axes: diag[a] = n_a n_a, sym[ab] = n_a n_b + n_b n_a for the pairs a < b.
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  double diag[3][3][3], sym[3][3][3], spin[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      for (int a = 0; a < 3; ++a)
        diag[a][i][j] = Q[i][a] * Q[j][a];
      for (int n = 0; n < 3; ++n) {
        const int a = pairs[n][0], b = pairs[n][1];
        sym[n][i][j] = Q[i][a] * Q[j][b] + Q[i][b] * Q[j][a];
      }
    }
  const double scale = std::fmax(std::fabs(x[0]), std::fabs(x[2]));
  for (int n = 0; n < 3; ++n) {
    const int a = pairs[n][0], b = pairs[n][1];
    const double gap = x[a] - x[b];
    spin[n] = std::fabs(gap) > 1e-9 * scale
                  ? m.shear * (ret.y[a] - ret.y[b]) / gap
                  : 0.5 * m.shear *
                        (ret.dy_dx[a][a] - ret.dy_dx[a][b] + ret.dy_dx[b][b] - ret.dy_dx[b][a]);
  }
  // T = sum_ae PD_ae n_a n_a n_e n_e + sum_(a<b) spin_ab sym_ab sym_ab.
  double left[3][3][3]; // left[e] = sum_a PD_ae n_a n_a
  for (int e = 0; e < 3; ++e)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        left[e][i][j] =
            PD[0][e] * diag[0][i][j] + PD[1][e] * diag[1][i][j] + PD[2][e] * diag[2][i][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          double t = 0.0;
          for (int n = 0; n < 3; ++n)
            t += left[n][i][j] * diag[n][k][l] + spin[n] * sym[n][i][j] * sym[n][k][l];
          r.tangent[i][j][k][l] = t;
        }
  return r;
}

} // namespace poroseam::physics
