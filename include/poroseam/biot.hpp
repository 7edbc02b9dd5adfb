// Biot poroelasticity (saturated, quasi-static): pure point laws, no mesh.
// Volumetric balance: alpha d(div u)/dt + (1/M) dp/dt + div q = 0, q = -(k/mu_w)(grad p - rho_w g).
#pragma once

#include "poroseam/elastic.hpp"

namespace poroseam::physics {

struct BiotProperties {
  double biot_coefficient = 1.0; ///< alpha [-]
  double storage = 0.0;          ///< 1/M [1/Pa]; 0 for incompressible grains and water
  double mobility = 0.0;         ///< k / mu_w [m2/(Pa s)]
  double fluid_density = 1000.0; ///< rho_w [kg/m3]
};

/// Darcy flux q = -(k/mu_w)(grad p - rho_w g) [m/s]; gravity is the vector g [m/s2].
void darcyFlux(const BiotProperties &b, int dim, const double grad_p[], const double gravity[],
               double flux[]);

/// Rate of fluid volume stored per unit volume: alpha div(du/dt) + (1/M) dp/dt [1/s].
double fluidContentRate(const BiotProperties &b, double volumetric_strain_rate,
                        double pressure_rate);

/// Pressure stabilisation parameter for equal-order elements (Aguilar, Gaspar, Lisbona and
/// Rodrigo 2008): beta = factor alpha^2 h^2 / (lambda + 2 G) [m2/Pa]. The term
/// beta grad(dp/dt) . grad(psi) added to the mass balance removes the spurious pressure
/// oscillations of the nearly undrained limit; factor 1/4 is their optimal 1D value.
double stabilizationParameter(const BiotProperties &b, const ElasticModuli &m, double cell_size,
                              double factor);

/// Saturated density rho_sat = (1 - n) rho_s + n rho_w [kg/m3].
double saturatedDensity(double porosity, double solid_density, double fluid_density);

} // namespace poroseam::physics
