#include "poroseam/geostatic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poroseam::physics {
namespace {

bool same(double a, double b)
{
  // Properties read from the same options are equal to the last bit; 1e-12 allows only for
  // the rounding of rho_sat = (1 - n) rho_s + n rho_w written two ways.
  return std::abs(a - b) <= 1e-12 * std::max({std::abs(a), std::abs(b), 1.0});
}

std::string shown(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

/// "K0 0.5 of 'rock'" or where a derived K0 came from.
std::string origin(const GroundRegion &r)
{
  return r.k0_origin.empty() ? "K0 " + shown(r.k0) + " of '" + r.name + "'" : r.k0_origin;
}

} // namespace

std::string buildGeostaticLayers(const std::vector<GroundRegion> &regions, double surface,
                                 double tolerance, std::vector<GeostaticLayer> &layers)
{
  layers.clear();
  if (regions.empty()) return "";
  std::ostringstream msg;
  std::vector<double> z{surface};
  for (const auto &r : regions) {
    if (r.top > surface + tolerance) {
      msg << "ground region '" << r.name << "' reaches z = " << r.top << " above the soil surface "
          << surface
          << " (-surface_elevation): the geostatic state integrates the weight from the surface "
             "down, so the surface must be the top of the ground (a structure standing on it "
             "takes -region_"
          << r.name << "_ground false; porous regions are ground by default)";
      return msg.str();
    }
    z.push_back(r.bottom);
    z.push_back(std::min(r.top, surface));
  }
  std::sort(z.begin(), z.end(), [](double a, double b) { return a > b; });
  std::vector<double> levels; // from the surface down, distinct
  for (double v : z)
    if (levels.empty() || levels.back() - v > tolerance) levels.push_back(v);
  for (size_t k = 0; k + 1 < levels.size(); ++k) {
    const double top = levels[k], bottom = levels[k + 1];
    const GroundRegion *first = nullptr;
    for (const auto &r : regions) {
      if (r.bottom > bottom + tolerance || r.top < top - tolerance) continue;
      if (!first) {
        first = &r;
        continue;
      }
      // Name the property that differs, and for K0 where each came from: a K0 derived from
      // nu was never given, and the user has to learn which option to set.
      std::string what;
      if (!same(r.density, first->density))
        what = "density (" + shown(first->density) + " and " + shown(r.density) + " kg/m3)";
      else if (!same(r.k0, first->k0))
        what = "K0 (" + origin(*first) + ", and " + origin(r) +
               "; set -region_<r>_K0 to one value for both)";
      else if (!same(r.alpha, first->alpha))
        what = "biot_alpha (" + shown(first->alpha) + " and " + shown(r.alpha) + ")";
      if (!what.empty()) {
        msg << "ground regions '" << first->name << "' and '" << r.name
            << "' lie side by side between z = " << bottom << " and " << top << " with different "
            << what
            << ": the geostatic state is exact only for horizontal layers (regions at the same "
               "elevation must have the same density, K0 and biot_alpha)";
        return msg.str();
      }
    }
    if (!first) {
      msg << "no ground region between z = " << bottom << " and " << top
          << " below the soil surface " << surface
          << " (-surface_elevation): the weight above the ground below is unknown; the "
             "surface must be the top of the ground, and the ground layers must touch";
      return msg.str();
    }
    layers.push_back({bottom, top, first->density});
  }
  return "";
}

double hydrostaticPressure(const GeostaticColumn &c, double z)
{
  return c.fluid_density * c.gravity * (c.water_level - z);
}

double surfaceWaterLoad(const GeostaticColumn &c)
{
  return c.fluid_density * c.gravity * std::max(0.0, c.water_level - c.surface);
}

double totalVerticalStress(const GeostaticColumn &c, double z)
{
  double weight = surfaceWaterLoad(c);
  for (const auto &layer : c.layers) {
    const double thickness = layer.top - std::max(layer.bottom, std::min(z, layer.top));
    weight += layer.density * c.gravity * thickness;
  }
  return -weight;
}

void geostaticStress(const GeostaticColumn &c, double z, double k0, double alpha, int dim,
                     double stress[3][3])
{
  const double vertical = totalVerticalStress(c, z) + alpha * hydrostaticPressure(c, z);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      stress[i][j] = i == j ? k0 * vertical : 0.0;
  stress[dim - 1][dim - 1] = vertical;
}

} // namespace poroseam::physics
