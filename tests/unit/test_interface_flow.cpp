// Interface flow laws: the cubic law (Poiseuille between parallel plates) and its derivative.
#include "poroseam/interface_flow.hpp"

#include <gtest/gtest.h>

using namespace poroseam::physics;

TEST(InterfaceFlow, CubicLawIsPoiseuilleBetweenPlates)
{
  // Flow rate per unit width between plates a distance h apart: h^3 / (12 mu) dp/dx.
  const double h = 1e-4, mu = 1e-3, dpdx = -1e3;
  const auto c = cubicLawConductivity(h, mu);
  EXPECT_NEAR(c.value, 1e-12 / 12e-3, 1e-24);
  const double grad[3] = {dpdx, 0, 0}, g[3] = {0, 0, 0};
  double q[3];
  longitudinalFlux(c.value, 3, grad, g, 1000.0, q);
  EXPECT_NEAR(q[0], -h * h * h / (12 * mu) * dpdx, 1e-20);
  EXPECT_EQ(q[1], 0.0);
}

TEST(InterfaceFlow, HydrostaticGapDoesNotFlow)
{
  // Along a vertical gap, grad p3 = rho_w g: no flow.
  const double grad[2] = {0.0, -1000.0 * 9.81}, g[2] = {0.0, -9.81};
  double q[2];
  longitudinalFlux(1.0, 2, grad, g, 1000.0, q);
  EXPECT_NEAR(q[1], 0.0, 1e-12);
}

TEST(InterfaceFlow, ConductivityDerivativeMatchesFiniteDifference)
{
  const double h = 3e-5, mu = 1e-3, e = 1e-12;
  const double fd =
      (cubicLawConductivity(h + e, mu).value - cubicLawConductivity(h - e, mu).value) / (2 * e);
  EXPECT_NEAR(cubicLawConductivity(h, mu).d_aperture, fd, 1e-6 * fd);
}

TEST(InterfaceFlow, TransversalFluxesInSeries)
{
  // Steady: f1 = f2 gives p3 = (T1 p1 + T2 p2) / (T1 + T2) and f = (p1 - p2) / (1/T1 + 1/T2).
  const double T1 = 2e-8, T2 = 5e-9, p1 = 3e4, p2 = 1e4;
  const double p3 = (T1 * p1 + T2 * p2) / (T1 + T2);
  EXPECT_NEAR(transversalFlux(T1, p1, p3), transversalFlux(T2, p3, p2), 1e-18);
  EXPECT_NEAR(transversalFlux(T1, p1, p3), (p1 - p2) / (1 / T1 + 1 / T2), 1e-18);
}
