// The geostatic column (geostatic.hpp): its layers from ground regions, what it refuses, and
// its stresses against the weight above each depth summed by hand and against equilibrium
// (d sigma_v / dz = rho g in each layer, total stress continuous, -q_w at the surface).
#include "poroseam/geostatic.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace poroseam::physics;

namespace {

const double g = 9.81, rho_w = 1000.0;

/// Three layers, listed out of order: deep [-10, -4], middle [-4, -1], shallow [-1, 0].
std::vector<GroundRegion> threeLayers()
{
  return {{"middle", -4.0, -1.0, 1990.0, 0.5, 1.0},
          {"deep", -10.0, -4.0, 2190.0, 0.7, 0.9},
          {"shallow", -1.0, 0.0, 1880.0, 0.45, 0.8}};
}

GeostaticColumn column(const std::vector<GroundRegion> &regions, double water)
{
  GeostaticColumn c{0.0, water, rho_w, g, {}};
  EXPECT_EQ(buildGeostaticLayers(regions, 0.0, 1e-9, c.layers), "");
  return c;
}

} // namespace

TEST(Geostatic, LayersFromTheSurfaceDown)
{
  const auto c = column(threeLayers(), 0.0);
  ASSERT_EQ(c.layers.size(), 3u);
  EXPECT_DOUBLE_EQ(c.layers[0].top, 0.0);
  EXPECT_DOUBLE_EQ(c.layers[0].density, 1880.0);
  EXPECT_DOUBLE_EQ(c.layers[1].density, 1990.0);
  EXPECT_DOUBLE_EQ(c.layers[2].bottom, -10.0);
  EXPECT_DOUBLE_EQ(c.layers[2].density, 2190.0);
}

TEST(Geostatic, TotalStressIsTheWeightAbove)
{
  // The weight above each depth, summed by hand from the layers' thicknesses above it.
  const std::vector<std::pair<double, double>> weight = {
      {0.0, 0.0},
      {-0.5, 1880.0 * 0.5},
      {-1.0, 1880.0},
      {-2.2, 1880.0 + 1990.0 * 1.2},
      {-4.0, 1880.0 + 1990.0 * 3.0},
      {-7.3, 1880.0 + 1990.0 * 3.0 + 2190.0 * 3.3},
      {-10.0, 1880.0 + 1990.0 * 3.0 + 2190.0 * 6.0}};
  for (double water : {-2.5, 0.0, 3.0}) {
    const auto c = column(threeLayers(), water);
    const double q_w = rho_w * g * std::max(0.0, water);
    for (const auto &[z, rho_h] : weight) {
      const double exact = -(q_w + rho_h * g);
      EXPECT_NEAR(totalVerticalStress(c, z), exact, 1e-12 * std::abs(exact) + 1e-12) << z;
    }
    EXPECT_DOUBLE_EQ(surfaceWaterLoad(c), q_w);
  }
}

TEST(Geostatic, EffectiveStressBalancesGravityForAnyAlpha)
{
  // d/dz (sigma'_v - alpha p) = rho g in each layer, and sigma'_v - alpha p (the total stress)
  // is continuous across layers and -q_w at the surface.
  const auto regions = threeLayers();
  for (double water : {-2.5, 0.0, 3.0}) {
    const auto c = column(regions, water);
    for (const auto &r : regions) {
      double s[3][3], t[3][3];
      const double z1 = r.bottom + 0.25 * (r.top - r.bottom), z2 = r.bottom + 0.75 * (r.top - r.bottom);
      geostaticStress(c, z1, r.k0, r.alpha, 3, s);
      geostaticStress(c, z2, r.k0, r.alpha, 3, t);
      const double total1 = s[2][2] - r.alpha * hydrostaticPressure(c, z1);
      const double total2 = t[2][2] - r.alpha * hydrostaticPressure(c, z2);
      EXPECT_NEAR((total2 - total1) / (z2 - z1), r.density * g, 1e-9 * r.density * g);
      EXPECT_NEAR(s[0][0], r.k0 * s[2][2], 1e-12 * std::abs(s[2][2]));
      EXPECT_NEAR(s[1][1], r.k0 * s[2][2], 1e-12 * std::abs(s[2][2]));
      EXPECT_EQ(s[0][2], 0.0);
      // Total stress at the region's top equals the column's there (continuity).
      double top[3][3];
      geostaticStress(c, r.top, r.k0, r.alpha, 3, top);
      EXPECT_NEAR(top[2][2] - r.alpha * hydrostaticPressure(c, r.top), totalVerticalStress(c, r.top),
                  1e-9 * (1.0 + std::abs(totalVerticalStress(c, r.top))));
    }
    // At the surface: sigma'_v = sigma_v + alpha p = -q_w + alpha rho_w g (h_w - z_s).
    double s[3][3];
    geostaticStress(c, 0.0, 0.45, 0.8, 2, s);
    EXPECT_NEAR(s[1][1], -surfaceWaterLoad(c) + 0.8 * rho_w * g * water, 1e-9);
  }
}

TEST(Geostatic, WaterAboveTheSurface)
{
  const auto c = column(threeLayers(), 2.0);
  double s[3][3];
  geostaticStress(c, 0.0, 0.45, 0.8, 2, s);
  EXPECT_NEAR(totalVerticalStress(c, 0.0), -rho_w * g * 2.0, 1e-9);
  EXPECT_NEAR(s[1][1], -(1.0 - 0.8) * rho_w * g * 2.0, 1e-9);
  EXPECT_NEAR(hydrostaticPressure(c, -1.0), rho_w * g * 3.0, 1e-9);
}

TEST(Geostatic, SideBySideRegionsOfOneKind)
{
  // Two regions side by side with the same properties (e.g. a soil cut by an interface) and a
  // layer below: accepted.
  std::vector<GroundRegion> r = {{"left", -3.0, 0.0, 1900.0, 0.5, 1.0},
                                 {"right", -3.0, 0.0, 1900.0, 0.5, 1.0},
                                 {"base", -5.0, -3.0, 2100.0, 0.6, 1.0}};
  std::vector<GeostaticLayer> layers;
  EXPECT_EQ(buildGeostaticLayers(r, 0.0, 1e-9, layers), "");
  EXPECT_EQ(layers.size(), 2u);
}

TEST(Geostatic, RefusesWhatItCannotMakeExact)
{
  std::vector<GeostaticLayer> layers;
  auto refused = [&](std::vector<GroundRegion> r, const char *text) {
    const std::string e = buildGeostaticLayers(r, 0.0, 1e-9, layers);
    EXPECT_NE(e.find(text), std::string::npos) << e;
  };
  // Side by side with another density, K0 or alpha: a boundary that is not horizontal.
  refused({{"a", -3.0, 0.0, 1900.0, 0.5, 1.0}, {"b", -2.0, 0.0, 2000.0, 0.5, 1.0}}, "side by side");
  refused({{"a", -3.0, 0.0, 1900.0, 0.5, 1.0}, {"b", -3.0, 0.0, 1900.0, 0.6, 1.0}}, "side by side");
  refused({{"a", -3.0, 0.0, 1900.0, 0.5, 1.0}, {"b", -3.0, 0.0, 1900.0, 0.5, 0.9}}, "side by side");
  // K0 differing side by side: the message says where each K0 came from (a derived one was
  // never given: the user must learn which option set it).
  refused({{"a", -3.0, 0.0, 1900.0, 0.5, 1.0,
            "K0 = nu/(1-nu) = 0.5 from -region_a_nu 0.333333 (-region_a_K0 not given)"},
           {"b", -3.0, 0.0, 1900.0, 0.6, 1.0, "-region_b_K0 0.6"}},
          "different K0 (K0 = nu/(1-nu) = 0.5 from -region_a_nu 0.333333 (-region_a_K0 not "
          "given), and -region_b_K0 0.6; set -region_<r>_K0 to one value for both)");
  // A gap between layers, or between the top of the ground and the surface.
  refused({{"a", -1.0, 0.0, 1900.0, 0.5, 1.0}, {"b", -3.0, -2.0, 2000.0, 0.5, 1.0}},
          "no ground region between z = -2 and -1");
  refused({{"a", -3.0, -0.5, 1900.0, 0.5, 1.0}}, "no ground region between z = -0.5 and 0");
  // Ground above the surface.
  refused({{"a", -3.0, 0.5, 1900.0, 0.5, 1.0}}, "reaches z = 0.5 above the soil surface");
  // Within the tolerance, elevations are the same.
  EXPECT_EQ(buildGeostaticLayers({{"a", -1.0, 1e-12, 1900.0, 0.5, 1.0},
                                  {"b", -2.0, -1.0 + 1e-12, 2000.0, 0.5, 1.0}},
                                 0.0, 1e-9, layers),
            "");
}
