#include "poroseam/interface_flow.hpp"

namespace poroseam::physics {

Conductivity cubicLawConductivity(double aperture, double viscosity)
{
  Conductivity c;
  c.value = aperture * aperture * aperture / (12.0 * viscosity);
  c.d_aperture = aperture * aperture / (4.0 * viscosity);
  return c;
}

void longitudinalFlux(double conductivity, int dim, const double grad_p[],
                      const double gravity_tangential[], double fluid_density, double flux[])
{
  for (int d = 0; d < dim; ++d)
    flux[d] = -conductivity * (grad_p[d] - fluid_density * gravity_tangential[d]);
}

} // namespace poroseam::physics
