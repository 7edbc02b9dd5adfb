// Point laws: elastic and Biot, each against closed forms and its tangent against finite
// differences.
#include "poroseam/biot.hpp"
#include "poroseam/elastic.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace poroseam::physics;

TEST(Elastic, LameConstantsFromYoungAndPoisson)
{
  const ElasticModuli m = lameFromYoung(2e8, 0.3);
  EXPECT_NEAR(m.shear, 2e8 / 2.6, 1e-6);
  EXPECT_NEAR(m.lambda, 2e8 * 0.3 / (1.3 * 0.4), 1e-6);
  // Oedometric modulus E (1 - nu) / ((1 + nu)(1 - 2 nu)).
  EXPECT_NEAR(m.constrained(), 2e8 * 0.7 / (1.3 * 0.4), 1e-4);
}

TEST(Elastic, UniaxialStrainGivesOedometricAndLateralStress)
{
  const ElasticModuli m = lameFromYoung(1e7, 0.25);
  double eps[3][3] = {{0, 0, 0}, {0, -1e-3, 0}, {0, 0, 0}}, sig[3][3];
  elasticStress(m, eps, sig);
  EXPECT_NEAR(sig[1][1], -1e-3 * m.constrained(), 1e-9);
  // K0 of an elastic oedometer: nu / (1 - nu).
  EXPECT_NEAR(sig[0][0] / sig[1][1], 0.25 / 0.75, 1e-12);
  EXPECT_NEAR(sig[2][2], sig[0][0], 1e-9);
  EXPECT_EQ(sig[0][1], 0.0);
}

TEST(Elastic, TangentMatchesFiniteDifferencesOfStress)
{
  const ElasticModuli m = lameFromYoung(3e7, 0.2);
  double eps[3][3] = {{1e-3, 2e-4, -1e-4}, {2e-4, -5e-4, 3e-4}, {-1e-4, 3e-4, 7e-4}};
  double base[3][3];
  elasticStress(m, eps, base);
  const double h = 1e-7;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      double pert[3][3], sig[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          pert[i][j] = eps[i][j];
      // Symmetric perturbation: C_ijkl is the derivative with respect to symmetric strain.
      // sigma is linear, so a one-sided difference is exact up to round-off.
      pert[k][l] += 0.5 * h;
      pert[l][k] += 0.5 * h;
      elasticStress(m, pert, sig);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double fd = (sig[i][j] - base[i][j]) / h;
          EXPECT_NEAR(fd, elasticTangent(m, i, j, k, l), 1e-6 * m.constrained());
        }
    }
}

TEST(Biot, DarcyFluxIsZeroInHydrostaticState)
{
  BiotProperties b;
  b.mobility = 1e-11 / 1e-3;
  const double g[3] = {0, -9.81, 0};
  // Hydrostatic: grad p = rho_w g.
  const double grad_p[2] = {0, -1000 * 9.81};
  double q[2];
  darcyFlux(b, 2, grad_p, g, q);
  EXPECT_NEAR(q[0], 0.0, 1e-20);
  EXPECT_NEAR(q[1], 0.0, 1e-20);
  const double grad_p2[2] = {100.0, 0.0};
  darcyFlux(b, 2, grad_p2, g, q);
  EXPECT_NEAR(q[0], -1e-8 * 100.0, 1e-20);       // flows down the gradient
  EXPECT_NEAR(q[1], -1e-8 * 1000 * 9.81, 1e-18); // and, without a gradient, downwards
}

TEST(Biot, ContentRateAndDensities)
{
  BiotProperties b;
  b.biot_coefficient = 0.8;
  b.storage = 1e-9;
  EXPECT_NEAR(fluidContentRate(b, 2e-3, 1e3), 0.8 * 2e-3 + 1e-6, 1e-15);
  EXPECT_NEAR(saturatedDensity(0.36, 2650, 1000), 0.64 * 2650 + 360, 1e-9);
}

TEST(Biot, StabilisationScalesWithSizeSquaredOverConstrainedModulus)
{
  BiotProperties b;
  const ElasticModuli m = lameFromYoung(1e7, 0.25);
  EXPECT_NEAR(stabilizationParameter(b, m, 0.1, 0.25), 0.25 * 0.01 / m.constrained(), 1e-20);
  b.biot_coefficient = 0.5;
  EXPECT_NEAR(stabilizationParameter(b, m, 0.1, 0.25), 0.25 * 0.25 * 0.01 / m.constrained(), 1e-20);
}
