#include "poroseam/contact.hpp"

#include <algorithm>
#include <cmath>

namespace poroseam::physics {

double dilation(const ContactParameters &p, double slip_plastic)
{
  if (p.dilation == 0.0) return 0.0;
  return p.dilation * std::min(slip_plastic, p.dilation_slip_limit);
}

ContactResponse contactResponse(const ContactParameters &p, const ContactInitial &initial,
                                const ContactHistory &history, int tangential_dims,
                                double gap_normal, const double gap_tangential[])
{
  ContactResponse r;
  const int nt = tangential_dims;
  for (int k = 0; k < nt; ++k)
    r.updated.gap_tangential[k] = gap_tangential[k];
  r.updated.slip_plastic = history.slip_plastic;
  // Normal: penalty from the initial state, the faces lifted apart by the dilation of the last
  // converged state (more is added below if the point slides), no tension.
  const double dilation_n = dilation(p, history.slip_plastic);
  r.dilation = dilation_n;
  const double pressure = initial.contact_pressure_effective -
                          p.normal_stiffness * (gap_normal - initial.gap_normal - dilation_n);
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
    // Slip: tau = mu p'_N n, n = trial / |trial|, after a plastic slip dl along n:
    // |tau| = |trial| - K_T dl. With dilation the faces move apart by tan(psi) dl, which
    // raises the pressure to p'_N = p_trial + K_N tan(psi) dl while dl is within the room
    // left before the dilation limit; the yield condition is then linear in dl:
    //   dl = (|trial| - mu p_trial) / (K_T + mu K_N tan(psi)).
    // Past the limit the dilation is fixed and dl = (|trial| - mu p'_N) / K_T.
    r.state = ContactState::slip;
    double n[2] = {0.0, 0.0};
    for (int k = 0; k < nt; ++k)
      n[k] = trial[k] / norm;
    const double room = p.dilation > 0.0 ? p.dilation_slip_limit - history.slip_plastic : 0.0;
    double pn = pressure, slip, dp_dgn = -p.normal_stiffness, dp_dgt[2] = {0.0, 0.0};
    if (room > 0.0) {
      const double hardening =
          p.tangential_stiffness + p.friction * p.normal_stiffness * p.dilation; // K_T + mu K_N tan
      slip = (norm - limit) / hardening;
      if (slip <= room) {
        // d dl / d g_N = mu K_N / H, d dl / d g_T = K_T n / H; p'_N gains K_N tan(psi) dl.
        pn = pressure + p.normal_stiffness * p.dilation * slip;
        dp_dgn = -p.normal_stiffness * p.tangential_stiffness / hardening;
        const double ddl_dgn = p.friction * p.normal_stiffness / hardening;
        r.d_dilation[0] = p.dilation * ddl_dgn;
        for (int l = 0; l < nt; ++l) {
          const double ddl_dgt = p.tangential_stiffness * n[l] / hardening;
          dp_dgt[l] = p.normal_stiffness * p.dilation * ddl_dgt;
          r.d_dilation[1 + l] = p.dilation * ddl_dgt;
        }
      } else {
        pn = pressure + p.normal_stiffness * p.dilation * room; // the limit reached in this step
        slip = (norm - p.friction * pn) / p.tangential_stiffness;
      }
    } else
      slip = (norm - limit) / p.tangential_stiffness;
    r.updated.slip_plastic = history.slip_plastic + slip;
    r.dilation = dilation(p, r.updated.slip_plastic);
    r.contact_pressure_effective = pn;
    r.tangent[0][0] = dp_dgn;
    // tau = mu p'_N n: d tau / d g_N = mu (d p'_N / d g_N) n and
    // d tau / d g_T = mu n (d p'_N / d g_T)^T + (mu p'_N K_T / |trial|) (I - n n^T).
    const double scale = p.friction * pn * p.tangential_stiffness / norm;
    for (int k = 0; k < nt; ++k) {
      r.shear[k] = p.friction * pn * n[k];
      r.tangent[0][1 + k] = dp_dgt[k];
      r.tangent[1 + k][0] = p.friction * dp_dgn * n[k];
      for (int l = 0; l < nt; ++l)
        r.tangent[1 + k][1 + l] = p.friction * n[k] * dp_dgt[l] + scale * ((k == l) - n[k] * n[l]);
    }
  }
  for (int k = 0; k < nt; ++k)
    r.updated.shear[k] = r.shear[k];
  return r;
}

namespace {

/// The s in (0, 1] where |A + B s| = alpha + beta s with alpha + beta s > 0 and the point in
/// contact (a + b s > 0), appended to `out`: the roots of |A + B s|^2 - (alpha + beta s)^2.
void crossings(double AA, double AB, double BB, double alpha, double beta, double a, double b,
               std::vector<double> &out)
{
  const double c0 = AA - alpha * alpha, c1 = 2.0 * (AB - alpha * beta), c2 = BB - beta * beta;
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
    if (s > 0.0 && s <= 1.0 && a + b * s > 0.0 && alpha + beta * s >= 0.0) out.push_back(s);
  }
}

} // namespace

void contactStateChanges(const ContactParameters &p, const ContactInitial &initial,
                         const ContactHistory &history, int tangential_dims, double gap_normal,
                         const double gap_tangential[], double d_gap_normal,
                         const double d_gap_tangential[], std::vector<double> &out)
{
  const int nt = tangential_dims;
  // Trial p'_N(s) = a + b s (with the last converged dilation); contact where it is >= 0.
  const double a =
      initial.contact_pressure_effective -
      p.normal_stiffness * (gap_normal - initial.gap_normal - dilation(p, history.slip_plastic));
  const double b = -p.normal_stiffness * d_gap_normal;
  if (b != 0.0) {
    const double s = -a / b;
    if (s > 0.0 && s <= 1.0) out.push_back(s);
  }
  // Trial shear tau(s) = A + B s; yield |tau| = mu p'_N, i.e. the roots of
  // |A + B s|^2 - mu^2 (a + b s)^2 where p'_N(s) > 0.
  double AA = 0.0, AB = 0.0, BB = 0.0;
  for (int k = 0; k < nt; ++k) {
    const double A =
        history.shear[k] + p.tangential_stiffness * (gap_tangential[k] - history.gap_tangential[k]);
    const double B = p.tangential_stiffness * d_gap_tangential[k];
    AA += A * A, AB += A * B, BB += B * B;
  }
  crossings(AA, AB, BB, p.friction * a, p.friction * b, a, b, out);
  // With dilation, sliding reaches the dilation limit where the plastic slip of the step,
  // (|tau_trial| - mu p_trial) / (K_T + mu K_N tan(psi)), equals the room left:
  // |A + B s| = mu (a + b s) + (K_T + mu K_N tan(psi)) room.
  const double room = p.dilation > 0.0 ? p.dilation_slip_limit - history.slip_plastic : 0.0;
  if (room > 0.0 && std::isfinite(room)) {
    const double hardening = p.tangential_stiffness + p.friction * p.normal_stiffness * p.dilation;
    crossings(AA, AB, BB, p.friction * a + hardening * room, p.friction * b, a, b, out);
  }
}

double mechanicalOpening(const ContactParameters &p, const ContactInitial &initial,
                         double gap_normal, double dilation)
{
  const double o = gap_normal - initial.gap_normal -
                   initial.contact_pressure_effective / p.normal_stiffness - dilation;
  return o > 0.0 ? o : 0.0;
}

} // namespace poroseam::physics
