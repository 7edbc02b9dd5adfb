// Mohr-Coulomb point law (tension positive): returns to every part of the yield surface against
// points built to return there (a point y0 on the surface plus the elastic image of a plastic
// strain g in the cone of the potential's gradients returns exactly to y0 with plastic strain
// g), the consistent tangent against central differences of the stress in every regime,
// objectivity, drained triaxial compression and extension against the closed-form peak and
// dilatancy, and the elastic law in the same shape against elasticStress.
#include "poroseam/mohr_coulomb.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

using namespace poroseam::physics;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

MohrCoulombParameters params(double c, double phi_deg, double psi_deg, double cutoff = -1.0)
{
  MohrCoulombParameters p;
  p.elastic = lameFromYoung(1e8, 0.3);
  p.cohesion = c;
  p.friction_angle = phi_deg * kDeg;
  p.dilation_angle = psi_deg * kDeg;
  p.tension_cutoff = cutoff;
  return p;
}

using Vec = std::vector<double>;

/// Gradient of (1 + sin a) s_i - (1 - sin a) s_j: a = phi gives the yield function's,
/// a = psi the plastic potential's.
Vec mcGradient(double angle, int i, int j)
{
  Vec v(3, 0.0);
  v[i] = 1.0 + std::sin(angle);
  v[j] = -(1.0 - std::sin(angle));
  return v;
}

Vec unit(int i)
{
  Vec v(3, 0.0);
  v[i] = 1.0;
  return v;
}

Vec combine(const std::vector<double> &mu, const std::vector<Vec> &vs)
{
  Vec g(3, 0.0);
  for (size_t n = 0; n < vs.size(); ++n)
    for (int a = 0; a < 3; ++a)
      g[a] += mu[n] * vs[n][a];
  return g;
}

/// Principal elastic stiffness times a principal strain.
Vec stiffness(const ElasticModuli &m, const Vec &e)
{
  const double tr = e[0] + e[1] + e[2];
  return {m.lambda * tr + 2 * m.shear * e[0], m.lambda * tr + 2 * m.shear * e[1],
          m.lambda * tr + 2 * m.shear * e[2]};
}

/// A rotation about the axis (1, 2, 3) (Rodrigues), so that no principal axis is a coordinate
/// axis.
void rotation(double angle, double R[3][3])
{
  double n[3] = {1, 2, 3};
  const double norm = std::sqrt(14.0);
  for (double &x : n)
    x /= norm;
  const double c = std::cos(angle), s = std::sin(angle);
  const double K[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      R[i][j] = (i == j ? c : 0.0) + s * K[i][j] + (1 - c) * n[i] * n[j];
}

/// R diag(v) R^T.
void fromPrincipal(const double R[3][3], const Vec &v, double out[3][3])
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      out[i][j] = 0.0;
      for (int a = 0; a < 3; ++a)
        out[i][j] += R[i][a] * v[a] * R[j][a];
    }
}

/// Strain whose elastic trial stress from sigma0 is `trial` (compliance of isotropic elasticity).
void strainFor(const ElasticModuli &m, const double sigma0[3][3], const double trial[3][3],
               double strain[3][3])
{
  double ds[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      ds[i][j] = trial[i][j] - sigma0[i][j];
  const double tr = ds[0][0] + ds[1][1] + ds[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      strain[i][j] = (ds[i][j] - (i == j ? m.lambda / (3 * m.lambda + 2 * m.shear) * tr : 0.0)) /
                     (2 * m.shear);
}

/// Largest value of every yield function (Mohr-Coulomb and cut-off) at a stress [Pa], on the
/// principal stresses of symmetricEigen (checked on its own below; the trigonometric closed
/// form loses half the digits at repeated eigenvalues, too few for these checks).
double maxYield(const MohrCoulombParameters &p, const double s[3][3])
{
  double e[3], vectors[3][3];
  symmetricEigen(s, e, vectors);
  const double sp = std::sin(p.friction_angle);
  double f = (1 + sp) * e[0] - (1 - sp) * e[2] - 2 * p.cohesion * std::cos(p.friction_angle);
  if (p.tension_cutoff >= 0) f = std::fmax(f, e[0] - p.tension_cutoff);
  return f;
}

const double kZero[3][3] = {};

/// A point of the yield surface y0 with a plastic strain increment g (principal, in the cone of
/// the potential's gradients of the planes active at y0): the trial y0 + D g returns to y0.
struct ReturnCase {
  std::string name;
  MohrCoulombParameters p;
  Vec y0;
  Vec g;
  YieldState state;
};

std::vector<ReturnCase> returnCases()
{
  const double c = 20e3, phi = 30 * kDeg, psi = 10 * kDeg, sp = std::sin(phi);
  const MohrCoulombParameters mc = params(c, 30, 10);
  // On the main face (1 + sin phi) s1 - (1 - sin phi) s3 = 2 c cos phi with s3 = -100 kPa.
  const double s1 = (2 * c * std::cos(phi) + (1 - sp) * -100e3) / (1 + sp);
  const double apex = c * std::cos(phi) / sp;
  const double t = 5e3; // tension cut-off below the apex (34.6 kPa)
  const MohrCoulombParameters cut = params(c, 30, 10, t);
  const double s3_cut = ((1 + sp) * t - 2 * c * std::cos(phi)) / (1 - sp);
  const Vec b13 = mcGradient(psi, 0, 2), b23 = mcGradient(psi, 1, 2), b12 = mcGradient(psi, 0, 1);
  std::vector<ReturnCase> cases = {
      {"face", mc, {s1, -50e3, -100e3}, combine({1e-3}, {b13}), YieldState::face},
      // Triaxial compression edge s1 = s2: trial with distinct and with equal s1, s2.
      {"compression edge",
       mc,
       {s1, s1, -100e3},
       combine({1e-3, 4e-4}, {b13, b23}),
       YieldState::edge},
      {"compression edge, repeated trial",
       mc,
       {s1, s1, -100e3},
       combine({6e-4, 6e-4}, {b13, b23}),
       YieldState::edge},
      // Triaxial extension edge s2 = s3.
      {"extension edge",
       mc,
       {s1, -100e3, -100e3},
       combine({1e-3, 3e-4}, {b13, b12}),
       YieldState::edge},
      {"extension edge, repeated trial",
       mc,
       {s1, -100e3, -100e3},
       combine({5e-4, 5e-4}, {b13, b12}),
       YieldState::edge},
      {"apex",
       mc,
       {apex, apex, apex},
       combine({1e-3, 5e-4, 3e-4}, {b13, b23, b12}),
       YieldState::apex},
      {"tresca face",
       params(c, 0, 0),
       {0.0, -10e3, -2 * c},
       combine({1e-3}, {mcGradient(0, 0, 2)}),
       YieldState::face},
      {"tresca compression edge",
       params(c, 0, 0),
       {0.0, 0.0, -2 * c},
       combine({1e-3, 2e-4}, {mcGradient(0, 0, 2), mcGradient(0, 1, 2)}),
       YieldState::edge},
      {"tension plane", cut, {t, -20e3, -40e3}, combine({1e-3}, {unit(0)}), YieldState::tension},
      {"tension edge",
       cut,
       {t, t, -40e3},
       combine({1e-3, 5e-4}, {unit(0), unit(1)}),
       YieldState::tension},
      {"tension corner",
       cut,
       {t, t, t},
       combine({1e-3, 7e-4, 5e-4}, {unit(0), unit(1), unit(2)}),
       YieldState::tension},
      {"tension and face",
       cut,
       {t, -30e3, s3_cut},
       combine({1e-3, 5e-4}, {unit(0), b13}),
       YieldState::tension},
  };
  return cases;
}

SkeletonResponse respond(const MohrCoulombParameters &p, const double R[3][3], const Vec &trial,
                         double strain[3][3])
{
  double sigma_trial[3][3];
  fromPrincipal(R, trial, sigma_trial);
  strainFor(p.elastic, kZero, sigma_trial, strain);
  return mohrCoulombResponse(p, kZero, SkeletonHistory{}, strain);
}

Vec trialOf(const ReturnCase &rc)
{
  const Vec Dg = stiffness(rc.p.elastic, rc.g);
  return {rc.y0[0] + Dg[0], rc.y0[1] + Dg[1], rc.y0[2] + Dg[2]};
}

/// Central differences of the stress against the returned tangent, for symmetric strain
/// perturbations of size h.
void expectTangentMatchesDifferences(const MohrCoulombParameters &p,
                                     const double initial_stress[3][3],
                                     const SkeletonHistory &history, const double strain[3][3],
                                     const std::string &what)
{
  const SkeletonResponse r = mohrCoulombResponse(p, initial_stress, history, strain);
  const double h = 1e-9;
  double worst = 0.0;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      double plus[3][3], minus[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          plus[i][j] = minus[i][j] = strain[i][j];
      plus[k][l] += 0.5 * h;
      plus[l][k] += 0.5 * h;
      minus[k][l] -= 0.5 * h;
      minus[l][k] -= 0.5 * h;
      const SkeletonResponse rp = mohrCoulombResponse(p, initial_stress, history, plus);
      const SkeletonResponse rm = mohrCoulombResponse(p, initial_stress, history, minus);
      EXPECT_EQ(rp.state, r.state) << what << ": the perturbation left the regime";
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double fd = (rp.stress[i][j] - rm.stress[i][j]) / (2 * h);
          // Symmetrised in (k, l): the strain is symmetric, so only that part is defined.
          const double tangent = 0.5 * (r.tangent[i][j][k][l] + r.tangent[i][j][l][k]);
          worst = std::fmax(worst, std::fabs(fd - tangent));
        }
    }
  EXPECT_LT(worst, 1e-6 * p.elastic.constrained()) << what;
}

} // namespace

TEST(SkeletonLaw, ElasticLawEqualsElasticStress)
{
  const ElasticModuli m = lameFromYoung(3e7, 0.25);
  const double sigma0[3][3] = {{-1e5, 2e3, 0}, {2e3, -2e5, -1e3}, {0, -1e3, -1.5e5}};
  SkeletonHistory h;
  h.plastic_strain[0][1] = h.plastic_strain[1][0] = 1e-4;
  h.plastic_strain[2][2] = -3e-4;
  h.equivalent_plastic_strain = 2e-4;
  const double eps[3][3] = {{1e-3, 2e-4, -1e-4}, {2e-4, -5e-4, 3e-4}, {-1e-4, 3e-4, 7e-4}};
  double elastic[3][3], expected[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      elastic[i][j] = eps[i][j] - h.plastic_strain[i][j];
  elasticStress(m, elastic, expected);
  const SkeletonResponse r = elasticSkeletonResponse(m, sigma0, h, eps);
  EXPECT_EQ(r.state, YieldState::elastic);
  EXPECT_EQ(r.updated.equivalent_plastic_strain, 2e-4);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_DOUBLE_EQ(r.stress[i][j], sigma0[i][j] + expected[i][j]);
      EXPECT_EQ(r.updated.plastic_strain[i][j], h.plastic_strain[i][j]);
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          EXPECT_EQ(r.tangent[i][j][k][l], elasticTangent(m, i, j, k, l));
    }
}

TEST(MohrCoulomb, InsideTheSurfaceIsElastic)
{
  const MohrCoulombParameters p = params(20e3, 30, 10, 5e3);
  const double sigma0[3][3] = {{-1e5, 0, 0}, {0, -1e5, 0}, {0, 0, -1e5}};
  const double eps[3][3] = {{1e-4, 2e-5, 0}, {2e-5, -1e-4, 1e-5}, {0, 1e-5, 5e-5}};
  const SkeletonResponse r = mohrCoulombResponse(p, sigma0, SkeletonHistory{}, eps);
  const SkeletonResponse e = elasticSkeletonResponse(p.elastic, sigma0, SkeletonHistory{}, eps);
  EXPECT_EQ(r.state, YieldState::elastic);
  EXPECT_LT(maxYield(p, r.stress), 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(r.stress[i][j], e.stress[i][j]);
      EXPECT_EQ(r.updated.plastic_strain[i][j], 0.0);
    }
  EXPECT_EQ(r.updated.equivalent_plastic_strain, 0.0);
}

TEST(MohrCoulomb, ReturnsToEveryFaceEdgeApexAndCutoffWithThePotentialsFlow)
{
  double R[3][3];
  rotation(0.7, R);
  for (const ReturnCase &rc : returnCases()) {
    SCOPED_TRACE(rc.name);
    double strain[3][3];
    const SkeletonResponse r = respond(rc.p, R, trialOf(rc), strain);
    EXPECT_EQ(r.state, rc.state);
    double expected_stress[3][3], expected_plastic[3][3];
    fromPrincipal(R, rc.y0, expected_stress);
    fromPrincipal(R, rc.g, expected_plastic);
    const double scale = 1e5;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(r.stress[i][j], expected_stress[i][j], 1e-9 * scale);
        EXPECT_NEAR(r.updated.plastic_strain[i][j], expected_plastic[i][j], 1e-13);
      }
    // On the surface: the largest yield function (evaluated on independently computed
    // principal stresses) is zero.
    EXPECT_NEAR(maxYield(rc.p, r.stress), 0.0, 1e-9 * scale);
    double g2 = 0.0;
    for (double x : rc.g)
      g2 += x * x;
    EXPECT_NEAR(r.updated.equivalent_plastic_strain, std::sqrt(2.0 / 3.0 * g2), 1e-15);
  }
}

TEST(MohrCoulomb, FaceFlowIsNonAssociated)
{
  // With psi < phi the plastic strain follows the potential's gradient, not the yield
  // function's: the ratio of minor to major principal plastic strain is -(1 - sin psi) /
  // (1 + sin psi), the volumetric plastic strain 2 sin psi per unit multiplier.
  const MohrCoulombParameters p = params(20e3, 30, 10);
  const ReturnCase rc = returnCases()[0];
  double R[3][3], strain[3][3];
  rotation(-1.1, R);
  const SkeletonResponse r = respond(p, R, trialOf(rc), strain);
  // Principal plastic strains on the rotated axes.
  double e[3];
  for (int a = 0; a < 3; ++a) {
    e[a] = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        e[a] += R[i][a] * r.updated.plastic_strain[i][j] * R[j][a];
  }
  const double sin_psi = std::sin(10 * kDeg), sin_phi = std::sin(30 * kDeg);
  EXPECT_NEAR(e[1], 0.0, 1e-15);
  EXPECT_NEAR(e[2] / e[0], -(1 - sin_psi) / (1 + sin_psi), 1e-10);
  EXPECT_GT(std::fabs(e[2] / e[0] + (1 - sin_phi) / (1 + sin_phi)), 0.1); // not associated
  EXPECT_NEAR((e[0] + e[1] + e[2]) / e[0], 2 * sin_psi / (1 + sin_psi), 1e-10);
}

TEST(MohrCoulomb, TrialBeyondTheApexWithoutDilatancyGoesToTheApex)
{
  // psi = 0: no plastic volume change, so isotropic tension beyond the apex reaches no face or
  // edge; the stress goes to the apex c / tan(phi).
  const MohrCoulombParameters p = params(20e3, 30, 0);
  const double apex = 20e3 / std::tan(30 * kDeg);
  double R[3][3], strain[3][3];
  rotation(0.3, R);
  for (const Vec &trial :
       {Vec{2 * apex, 2 * apex, 2 * apex}, Vec{2.2 * apex, 2 * apex, 1.9 * apex}}) {
    const SkeletonResponse r = respond(p, R, trial, strain);
    EXPECT_EQ(r.state, YieldState::apex);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(r.stress[i][j], i == j ? apex : 0.0, 1e-9 * apex);
    expectTangentMatchesDifferences(p, kZero, SkeletonHistory{}, strain, "apex, psi = 0");
  }
}

TEST(MohrCoulomb, RandomTrialsReturnOntoTheSurfaceWithElasticConsistency)
{
  // From anywhere, the returned stress satisfies every yield function, and the plastic strain
  // increment is C^-1 : (trial - returned) (perfect plasticity).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const MohrCoulombParameters &p :
       {params(20e3, 30, 10), params(20e3, 35, 0), params(20e3, 30, 30), params(20e3, 0, 0),
        params(20e3, 30, 5, 5e3), params(0.0, 35, 5), params(20e3, 40, 10, 0.0)}) {
    int plastic = 0;
    for (int n = 0; n < 2000; ++n) {
      double eps[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j <= i; ++j)
          eps[i][j] = eps[j][i] = 2e-3 * u(rng) - (i == j ? 5e-4 : 0.0);
      const SkeletonResponse r = mohrCoulombResponse(p, kZero, SkeletonHistory{}, eps);
      plastic += r.state != YieldState::elastic;
      ASSERT_LE(maxYield(p, r.stress), 1e-9 * 4e5) << "trial " << n;
      double elastic[3][3], back[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          elastic[i][j] = eps[i][j] - r.updated.plastic_strain[i][j];
      elasticStress(p.elastic, elastic, back);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          ASSERT_NEAR(back[i][j], r.stress[i][j], 1e-9 * 4e5);
    }
    EXPECT_GT(plastic, 200);
  }
}

TEST(MohrCoulomb, TangentMatchesCentralDifferencesInEveryRegime)
{
  double R[3][3];
  rotation(0.7, R);
  for (const ReturnCase &rc : returnCases()) {
    double strain[3][3];
    const SkeletonResponse r = respond(rc.p, R, trialOf(rc), strain);
    ASSERT_EQ(r.state, rc.state) << rc.name;
    expectTangentMatchesDifferences(rc.p, kZero, SkeletonHistory{}, strain, rc.name);
  }
  // Elastic, with distinct and with repeated (isotropic) principal stresses.
  const MohrCoulombParameters p = params(20e3, 30, 10, 5e3);
  double strain[3][3];
  for (const Vec &trial : {Vec{-1e4, -3e4, -6e4}, Vec{-5e4, -5e4, -5e4}, Vec{-2e4, -5e4, -5e4}}) {
    ASSERT_EQ(respond(p, R, trial, strain).state, YieldState::elastic);
    expectTangentMatchesDifferences(p, kZero, SkeletonHistory{}, strain, "elastic");
  }
  // With an initial stress and a committed plastic strain whose axes differ from the trial's.
  const double sigma0[3][3] = {{-8e4, 1e4, 0}, {1e4, -1.2e5, 5e3}, {0, 5e3, -1e5}};
  SkeletonHistory h;
  h.plastic_strain[0][0] = 2e-4;
  h.plastic_strain[1][2] = h.plastic_strain[2][1] = -1e-4;
  const double eps[3][3] = {{1e-3, 3e-4, -2e-4}, {3e-4, -2e-3, 1e-4}, {-2e-4, 1e-4, 4e-4}};
  const SkeletonResponse r = mohrCoulombResponse(params(20e3, 30, 10), sigma0, h, eps);
  EXPECT_NE(r.state, YieldState::elastic);
  expectTangentMatchesDifferences(params(20e3, 30, 10), sigma0, h, eps, "general");
}

TEST(MohrCoulomb, Objectivity)
{
  // Rotating the strain (with the initial stress and the history) rotates the stress and the
  // tangent and changes nothing else.
  const MohrCoulombParameters p = params(10e3, 35, 5, 2e3);
  const double sigma0[3][3] = {{-8e4, 1e4, 0}, {1e4, -1.2e5, 5e3}, {0, 5e3, -1e5}};
  SkeletonHistory h;
  h.plastic_strain[0][0] = 2e-4;
  h.plastic_strain[0][2] = h.plastic_strain[2][0] = -1e-4;
  h.equivalent_plastic_strain = 3e-4;
  const double eps[3][3] = {{1e-3, 3e-4, -2e-4}, {3e-4, -2e-3, 1e-4}, {-2e-4, 1e-4, 4e-4}};
  double Q[3][3];
  rotation(2.1, Q);
  auto rotate = [&](const double a[3][3], double out[3][3]) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        out[i][j] = 0.0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            out[i][j] += Q[i][k] * Q[j][l] * a[k][l];
      }
  };
  double sigma0_r[3][3], eps_r[3][3];
  rotate(sigma0, sigma0_r);
  rotate(eps, eps_r);
  SkeletonHistory h_r = h;
  rotate(h.plastic_strain, h_r.plastic_strain);
  const SkeletonResponse a = mohrCoulombResponse(p, sigma0, h, eps);
  const SkeletonResponse b = mohrCoulombResponse(p, sigma0_r, h_r, eps_r);
  ASSERT_NE(a.state, YieldState::elastic);
  EXPECT_EQ(a.state, b.state);
  EXPECT_NEAR(a.updated.equivalent_plastic_strain, b.updated.equivalent_plastic_strain, 1e-15);
  double expected[3][3], plastic[3][3];
  rotate(a.stress, expected);
  rotate(a.updated.plastic_strain, plastic);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(b.stress[i][j], expected[i][j], 1e-9 * 1e5);
      EXPECT_NEAR(b.updated.plastic_strain[i][j], plastic[i][j], 1e-15);
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          double t = 0.0;
          for (int m = 0; m < 3; ++m)
            for (int n = 0; n < 3; ++n)
              for (int o = 0; o < 3; ++o)
                for (int q = 0; q < 3; ++q)
                  t += Q[i][m] * Q[j][n] * Q[k][o] * Q[l][q] * a.tangent[m][n][o][q];
          EXPECT_NEAR(b.tangent[i][j][k][l], t, 1e-9 * p.elastic.constrained());
        }
    }
}

namespace {

struct TriaxialResult {
  double peak_q;               ///< largest axial minus lateral stress magnitude reached [Pa]
  double elastic_slope;        ///< dq / d(axial strain) before yield [Pa]
  double dilatancy;            ///< d(volumetric strain) / d(axial strain) at the end
  std::vector<int> iterations; ///< Newton iterations on the lateral strain per step
};

/// Drained triaxial test from an isotropic state -confinement: axial strain increments of
/// d_axial per step (negative: compression), the lateral stress held at -confinement by
/// Newton's method on the lateral strain with the law's tangent; history committed per step.
TriaxialResult triaxial(const MohrCoulombParameters &p, double confinement, double d_axial,
                        int steps)
{
  double sigma0[3][3] = {};
  for (int i = 0; i < 3; ++i)
    sigma0[i][i] = -confinement;
  SkeletonHistory h;
  double axial = 0.0, lateral = 0.0, last_axial = 0.0, last_volume = 0.0;
  TriaxialResult out{0.0, 0.0, 0.0, {}};
  for (int n = 1; n <= steps; ++n) {
    axial += d_axial;
    SkeletonResponse r{};
    int it = 0;
    for (; it < 30; ++it) {
      const double eps[3][3] = {{lateral, 0, 0}, {0, lateral, 0}, {0, 0, axial}};
      r = mohrCoulombResponse(p, sigma0, h, eps);
      const double residual = r.stress[0][0] + confinement;
      if (std::fabs(residual) < 1e-10 * confinement) break;
      lateral -= residual / (r.tangent[0][0][0][0] + r.tangent[0][0][1][1]);
    }
    out.iterations.push_back(it);
    h = r.updated;
    const double q = std::fabs(r.stress[2][2] - r.stress[0][0]);
    if (n == 1) out.elastic_slope = q / std::fabs(axial);
    out.peak_q = std::fmax(out.peak_q, q);
    const double volume = axial + 2 * lateral;
    if (n == steps) out.dilatancy = (volume - last_volume) / (axial - last_axial);
    last_axial = axial;
    last_volume = volume;
  }
  return out;
}

} // namespace

TEST(MohrCoulomb, DrainedTriaxialCompressionPeakAndDilatancy)
{
  // Compression (s1 = s2 = -sigma_c lateral, s3 axial): q_f = (2 c cos phi + 2 sigma_c sin phi)
  // / (1 - sin phi); then on the compression edge the plastic flow gives d eps_v / d eps_a =
  // -2 sin psi / (1 - sin psi) (dilation while the sample shortens). Elastic slope E.
  const double c = 10e3, sigma_c = 100e3;
  for (double psi : {0.0, 5.0, 15.0}) {
    const MohrCoulombParameters p = params(c, 35, psi);
    const TriaxialResult r = triaxial(p, sigma_c, -1e-4, 100);
    const double sp = std::sin(35 * kDeg), sy = std::sin(psi * kDeg);
    EXPECT_NEAR(r.peak_q, (2 * c * std::cos(35 * kDeg) + 2 * sigma_c * sp) / (1 - sp),
                1e-8 * sigma_c);
    EXPECT_NEAR(r.elastic_slope, 1e8, 1e-6 * 1e8);
    EXPECT_NEAR(r.dilatancy, -2 * sy / (1 - sy), 1e-8);
    // Lateral Newton with the consistent tangent: at most 3 iterations per step (one when
    // elastic or on the plateau, where the stress path is linear).
    for (int it : r.iterations)
      EXPECT_LE(it, 3);
  }
}

TEST(MohrCoulomb, DrainedTriaxialExtensionPeakAndDilatancy)
{
  // Extension (axial stress rises from -sigma_c at constant lateral -sigma_c: s1 axial,
  // s2 = s3 lateral): failure when (1 + sin phi) s1 + (1 - sin phi) sigma_c = 2 c cos phi,
  // q_f = (2 c cos phi + 2 sigma_c sin phi) / (1 + sin phi); on the extension edge
  // d eps_v / d eps_a = 2 sin psi / (1 + sin psi).
  const double c = 10e3, sigma_c = 100e3;
  for (double psi : {0.0, 10.0}) {
    const MohrCoulombParameters p = params(c, 30, psi);
    const TriaxialResult r = triaxial(p, sigma_c, 1e-4, 100);
    const double sp = std::sin(30 * kDeg), sy = std::sin(psi * kDeg);
    EXPECT_NEAR(r.peak_q, (2 * c * std::cos(30 * kDeg) + 2 * sigma_c * sp) / (1 + sp),
                1e-8 * sigma_c);
    EXPECT_NEAR(r.dilatancy, 2 * sy / (1 + sy), 1e-8);
    for (int it : r.iterations)
      EXPECT_LE(it, 3);
  }
}

TEST(MohrCoulomb, UnloadingFromThePlateauIsElastic)
{
  // After plastic loading, a strain step back is elastic from the committed plastic strain.
  const MohrCoulombParameters p = params(10e3, 30, 10);
  double R[3][3], strain[3][3];
  rotation(0.4, R);
  const ReturnCase rc = returnCases()[0];
  const SkeletonResponse loaded = respond(p, R, trialOf(rc), strain);
  ASSERT_EQ(loaded.state, YieldState::face);
  double back[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      back[i][j] = strain[i][j] - 0.5 * loaded.updated.plastic_strain[i][j];
  const SkeletonResponse r = mohrCoulombResponse(p, kZero, loaded.updated, back);
  EXPECT_EQ(r.state, YieldState::elastic);
  const SkeletonResponse e = elasticSkeletonResponse(p.elastic, kZero, loaded.updated, back);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(r.stress[i][j], e.stress[i][j]);
  EXPECT_EQ(r.updated.equivalent_plastic_strain, loaded.updated.equivalent_plastic_strain);
}

TEST(MohrCoulomb, EigenSolverHandlesRepeatedEigenvalues)
{
  double R[3][3], A[3][3], values[3], vectors[3][3];
  rotation(0.9, R);
  for (const Vec &v : {Vec{3, 1, -2}, Vec{1, 1, -2}, Vec{3, -2, -2}, Vec{5, 5, 5}}) {
    fromPrincipal(R, v, A);
    symmetricEigen(A, values, vectors);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(values[a], v[a], 1e-14 * 5);
      // A n_a = values_a n_a and the columns are orthonormal.
      for (int i = 0; i < 3; ++i) {
        double An = 0.0;
        for (int j = 0; j < 3; ++j)
          An += A[i][j] * vectors[j][a];
        EXPECT_NEAR(An, values[a] * vectors[i][a], 1e-13 * 5);
      }
      for (int b = 0; b < 3; ++b) {
        double d = 0.0;
        for (int i = 0; i < 3; ++i)
          d += vectors[i][a] * vectors[i][b];
        EXPECT_NEAR(d, a == b ? 1.0 : 0.0, 1e-14);
      }
    }
  }
}

TEST(MohrCoulomb, ParameterErrorsNameTheValue)
{
  EXPECT_EQ(mohrCoulombParameterError(params(10e3, 30, 10)), "");
  EXPECT_EQ(mohrCoulombParameterError(params(0.0, 35, 0)), "");
  EXPECT_EQ(mohrCoulombParameterError(params(10e3, 0, 0, 0.0)), "");
  EXPECT_NE(mohrCoulombParameterError(params(-1.0, 30, 10)).find("cohesion"), std::string::npos);
  EXPECT_NE(mohrCoulombParameterError(params(10e3, 95, 10)).find("friction angle"),
            std::string::npos);
  EXPECT_NE(mohrCoulombParameterError(params(10e3, 30, 40)).find("dilation angle"),
            std::string::npos);
  EXPECT_NE(mohrCoulombParameterError(params(0.0, 0, 0)).find("no strength"), std::string::npos);
  MohrCoulombParameters p = params(10e3, 30, 10);
  p.elastic.shear = 0.0;
  EXPECT_NE(mohrCoulombParameterError(p).find("shear modulus"), std::string::npos);
}

TEST(MohrCoulomb, EverySextantOfThePyramidReturnsToItsOwnFace)
{
  // The six faces of the Mohr-Coulomb pyramid are the six orderings of the principal
  // stresses over the axes x, y, z: the face case with its principal values assigned to the
  // axes in each order returns to the same values on the same axes.
  const ReturnCase rc = returnCases()[0];
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto &o : orders) {
    double P[3][3] = {}; // axis o[a] carries principal value a
    for (int a = 0; a < 3; ++a)
      P[o[a]][a] = 1.0;
    double strain[3][3];
    const SkeletonResponse r = respond(rc.p, P, trialOf(rc), strain);
    EXPECT_EQ(r.state, YieldState::face);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(r.stress[o[a]][o[a]], rc.y0[a], 1e-9 * 1e5);
      EXPECT_NEAR(r.updated.plastic_strain[o[a]][o[a]], rc.g[a], 1e-13);
    }
    EXPECT_NEAR(r.stress[0][1], 0.0, 1e-9 * 1e5);
    expectTangentMatchesDifferences(rc.p, kZero, SkeletonHistory{}, strain, "sextant");
  }
}
