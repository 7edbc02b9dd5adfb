// The geostatic (K0) initial state of horizontally layered ground: pure laws, no mesh.
//
// Vertical coordinate z (y in 2D), gravity g along -z, stresses tension positive [Pa].
// The ground is a column of horizontal layers below the soil surface z_s; the free water
// stands at the level h_w (above or below z_s).
//   pore pressure     p(z)       = rho_w g (h_w - z)                  (everywhere, also < 0)
//   water on the top  q_w        = rho_w g max(0, h_w - z_s)          (its weight on the soil)
//   total vertical    sigma_v(z) = -(q_w + g int_z^z_s rho(z') dz')   (rho of the layer at z')
//   effective         sigma'_v   = sigma_v + alpha p,  sigma'_h = K0 sigma'_v
// The total stress of the Biot model is sigma' - alpha p I (cell_kernel.hpp), so
// div(sigma' - alpha p I) + rho g = 0 holds exactly for any alpha in each layer, and the total
// stress is continuous from layer to layer and equals -q_w at the surface. A porous layer is
// saturated at every elevation, above the water table too, where p < 0 (suction): the only
// state of the saturated Biot equations in which no water flows (docs/scenes.md). A layer that
// is not porous carries the total stress (alpha = 0).
#pragma once

#include <string>
#include <vector>

namespace poroseam::physics {

/// One ground region as the column sees it: its vertical extent and what sets its stresses.
struct GroundRegion {
  std::string name;
  double bottom = 0.0, top = 0.0; ///< lowest and highest elevation of its cells [m]
  double density = 0.0;           ///< rho_sat (porous) or rho_s [kg/m3]
  double k0 = 1.0;                ///< sigma'_h / sigma'_v [-]
  double alpha = 1.0;             ///< Biot coefficient; 0 for a region without pore pressure
  std::string k0_origin;          ///< the option K0 came from, or nu/(1-nu) from nu (messages)
};

/// A horizontal layer of the column: [bottom, top] of one density.
struct GeostaticLayer {
  double bottom = 0.0, top = 0.0, density = 0.0;
};

struct GeostaticColumn {
  double surface = 0.0;       ///< z_s [m]
  double water_level = 0.0;   ///< h_w [m]
  double fluid_density = 0.0; ///< rho_w [kg/m3]
  double gravity = 0.0;       ///< g [m/s2]
  std::vector<GeostaticLayer> layers; ///< from the surface down, contiguous
};

/// Cuts the ground regions into horizontal layers from the surface down, or says why the
/// ground is not a horizontally layered column (then the message is non-empty):
///   - a region reaches above the surface,
///   - an elevation between the surface and the bottom of the ground has no ground region
///     (the weight above a point would be unknown),
///   - regions side by side at one elevation differ in density, K0 or alpha (their boundary
///     is not horizontal, and the stresses on its two sides would not balance).
/// `tolerance` [m]: elevations closer than this are the same.
std::string buildGeostaticLayers(const std::vector<GroundRegion> &regions, double surface,
                                 double tolerance, std::vector<GeostaticLayer> &layers);

/// Hydrostatic pore pressure rho_w g (h_w - z) [Pa]; negative above the water level.
double hydrostaticPressure(const GeostaticColumn &c, double z);

/// Pressure of the free water on the soil surface rho_w g max(0, h_w - z_s) [Pa].
double surfaceWaterLoad(const GeostaticColumn &c);

/// Total vertical stress sigma_v(z) [Pa], <= 0: the water load plus the weight of the layers
/// between z and the surface (z is clamped to the surface and to the bottom of the column).
double totalVerticalStress(const GeostaticColumn &c, double z);

/// Initial effective stress at elevation z of a region with K0 `k0` and Biot coefficient
/// `alpha` (0 without pore pressure): sigma'_v = sigma_v + alpha p on the vertical axis
/// (index dim - 1), K0 sigma'_v on the other two, no shear.
void geostaticStress(const GeostaticColumn &c, double z, double k0, double alpha, int dim,
                     double stress[3][3]);

} // namespace poroseam::physics
