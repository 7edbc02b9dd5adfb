// Hydraulics of a zero-thickness interface, three-node scheme (docs/physics.md section 5, paper section 2.2):
// pure point laws, volumetric (the mass balances are divided by rho_w). SI units.
//   aperture          h = D0 + o                        (o: mechanical opening)
//   longitudinal flux q_l = -(h^3 / (12 mu_w)) (grad_T p3 - rho_w g_T)   [m2/s per m width]
//   transversal flux  f_1 = T_1 (p1 - p3), f_2 = T_2 (p3 - p2)           [m/s]
//   interface balance dh/dt + div_T q_l = f_1 - f_2
#pragma once

namespace poroseam::physics {

/// Cubic-law conductivity h^3 / (12 mu_w) [m3/(Pa s)] and its derivative in h.
struct Conductivity {
  double value = 0.0;
  double d_aperture = 0.0;
};
Conductivity cubicLawConductivity(double aperture, double viscosity);

/// Longitudinal volumetric flux per unit width, q_l = -c (grad_p - rho_w g_tangential), with
/// grad_p the surface gradient of p3 and g_tangential the tangential part of gravity.
void longitudinalFlux(double conductivity, int dim, const double grad_p[],
                      const double gravity_tangential[], double fluid_density, double flux[]);

/// Transversal flux from pressure p_from to p_to through transmissivity T [m/(Pa s)].
inline double transversalFlux(double transmissivity, double p_from, double p_to)
{
  return transmissivity * (p_from - p_to);
}

} // namespace poroseam::physics
