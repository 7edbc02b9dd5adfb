#include "poroseam/contact.hpp"

#include <cmath>

namespace poroseam::physics {

ContactResponse contactResponse(const ContactParameters &p, const ContactInitial &initial,
                                const ContactHistory &history, int tangential_dims,
                                double gap_normal, const double gap_tangential[])
{
  ContactResponse r;
  const int nt = tangential_dims;
  for (int k = 0; k < nt; ++k)
    r.updated.gap_tangential[k] = gap_tangential[k];
  // Normal: penalty from the initial state, no tension.
  const double pressure =
      initial.contact_pressure_effective - p.normal_stiffness * (gap_normal - initial.gap_normal);
  if (pressure < 0.0) {
    // Open: no traction; the history keeps tau = 0 so that a new contact starts unstressed.
    // At exactly zero pressure (touching) the interface counts as closed, with its
    // stiffness: otherwise bodies that merely touch at the start would float.
    r.state = ContactState::open;
    return r;
  }
  r.contact_pressure_effective = pressure;
  r.tangent[0][0] = -p.normal_stiffness;

  // Tangential: elastic predictor from the last converged state, then Coulomb return.
  double trial[2] = {0.0, 0.0}, norm2 = 0.0;
  for (int k = 0; k < nt; ++k) {
    trial[k] =
        history.shear[k] + p.tangential_stiffness * (gap_tangential[k] - history.gap_tangential[k]);
    norm2 += trial[k] * trial[k];
  }
  const double norm = std::sqrt(norm2);
  const double limit = p.friction * pressure;
  // A point that slipped in the last step starts the next one exactly on the yield surface,
  // where round-off would pick the branch (and a different Newton path on another number of
  // ranks). There it counts as sticking, the elastic predictor, within a 1e-12 margin: the
  // stick tangent serves load reversals far better than the slip one.
  if (norm <= limit * (1.0 + 1e-12)) {
    r.state = ContactState::stick;
    for (int k = 0; k < nt; ++k) {
      r.shear[k] = trial[k];
      r.tangent[1 + k][1 + k] = p.tangential_stiffness;
    }
  } else {
    // Slip: tau = mu p'_N n, n = trial / |trial|; d tau / d g_N = -mu K_N n and
    // d tau / d g_T = (mu p'_N K_T / |trial|) (I - n n^T).
    r.state = ContactState::slip;
    double n[2] = {0.0, 0.0};
    for (int k = 0; k < nt; ++k)
      n[k] = trial[k] / norm;
    const double scale = limit * p.tangential_stiffness / norm;
    for (int k = 0; k < nt; ++k) {
      r.shear[k] = limit * n[k];
      r.tangent[1 + k][0] = -p.friction * p.normal_stiffness * n[k];
      for (int l = 0; l < nt; ++l)
        r.tangent[1 + k][1 + l] = scale * ((k == l) - n[k] * n[l]);
    }
  }
  for (int k = 0; k < nt; ++k)
    r.updated.shear[k] = r.shear[k];
  return r;
}

void contactStateChanges(const ContactParameters &p, const ContactInitial &initial,
                         const ContactHistory &history, int tangential_dims, double gap_normal,
                         const double gap_tangential[], double d_gap_normal,
                         const double d_gap_tangential[], std::vector<double> &out)
{
  const int nt = tangential_dims;
  // p'_N(s) = a + b s; contact where p'_N >= 0.
  const double a = initial.contact_pressure_effective -
                   p.normal_stiffness * (gap_normal - initial.gap_normal);
  const double b = -p.normal_stiffness * d_gap_normal;
  if (b != 0.0) {
    const double s = -a / b;
    if (s > 0.0 && s <= 1.0) out.push_back(s);
  }
  // Trial shear tau(s) = A + B s; yield |tau| = mu p'_N, i.e. the roots of
  // |A + B s|^2 - mu^2 (a + b s)^2 = c0 + c1 s + c2 s^2 where p'_N(s) > 0.
  double AA = 0.0, AB = 0.0, BB = 0.0;
  for (int k = 0; k < nt; ++k) {
    const double A = history.shear[k] +
                     p.tangential_stiffness * (gap_tangential[k] - history.gap_tangential[k]);
    const double B = p.tangential_stiffness * d_gap_tangential[k];
    AA += A * A, AB += A * B, BB += B * B;
  }
  const double m2 = p.friction * p.friction;
  const double c0 = AA - m2 * a * a, c1 = 2.0 * (AB - m2 * a * b), c2 = BB - m2 * b * b;
  double roots[2];
  int n = 0;
  const double scale = std::fabs(c0) + std::fabs(c1) + std::fabs(c2);
  if (scale == 0.0) return;
  if (std::fabs(c2) <= 1e-14 * scale) {
    if (c1 != 0.0) roots[n++] = -c0 / c1;
  } else {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) return;
    // Citardauq-safe roots.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    roots[n++] = q / c2;
    if (q != 0.0) roots[n++] = c0 / q;
  }
  for (int i = 0; i < n; ++i) {
    const double s = roots[i];
    if (s > 0.0 && s <= 1.0 && a + b * s > 0.0) out.push_back(s);
  }
}

double mechanicalOpening(const ContactParameters &p, const ContactInitial &initial,
                         double gap_normal)
{
  const double o =
      gap_normal - initial.gap_normal - initial.contact_pressure_effective / p.normal_stiffness;
  return o > 0.0 ? o : 0.0;
}

} // namespace poroseam::physics
