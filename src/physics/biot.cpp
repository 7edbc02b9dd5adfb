#include "poroseam/biot.hpp"

namespace poroseam::physics {

void darcyFlux(const BiotProperties &b, int dim, const double grad_p[], const double gravity[],
               double flux[])
{
  for (int d = 0; d < dim; ++d)
    flux[d] = -b.mobility * (grad_p[d] - b.fluid_density * gravity[d]);
}

double fluidContentRate(const BiotProperties &b, double volumetric_strain_rate,
                        double pressure_rate)
{
  return b.biot_coefficient * volumetric_strain_rate + b.storage * pressure_rate;
}

double stabilizationParameter(const BiotProperties &b, const ElasticModuli &m, double cell_size,
                              double factor)
{
  return factor * b.biot_coefficient * b.biot_coefficient * cell_size * cell_size / m.constrained();
}

double saturatedDensity(double porosity, double solid_density, double fluid_density)
{
  return (1.0 - porosity) * solid_density + porosity * fluid_density;
}

} // namespace poroseam::physics
