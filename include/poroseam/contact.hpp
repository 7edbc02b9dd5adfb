// Mechanical law of a zero-thickness interface (docs/physics.md section 4, paper section 2.1):
// normal penalty contact without tension, and Coulomb friction written as elastoplasticity (stick =
// elastic with tangential penalty K_T, slip = plastic on |tau| = mu p'_N), with a return
// mapping from the last converged state. Optional shear dilation (docs/physics.md section 4):
// sliding lifts the faces apart by d = tan(psi) min(s_p, s_lim), s_p the accumulated plastic
// slip, so the contact pressure follows the normal gap minus d (non-associated Coulomb flow:
// normal plastic gap tan(psi) per unit slip). Pure point law in the local frame (e1 normal of
// side 1 towards side 2, e2 and e3 tangent); gaps in m, stresses in Pa.
#pragma once

#include <limits>
#include <vector>

namespace poroseam::physics {

enum class ContactState { open = 0, stick = 1, slip = 2 };

struct ContactParameters {
  double normal_stiffness = 0.0;     ///< K_N [Pa/m]
  double tangential_stiffness = 0.0; ///< K_T [Pa/m]
  double friction = 0.0;             ///< mu [-]
  /// tan(psi) [-], psi the dilation angle: normal dilation per unit plastic slip (0: none).
  double dilation = 0.0;
  /// Accumulated plastic slip after which dilation stops [m] (the joint's asperities are
  /// sheared off): the dilation never exceeds tan(psi) times it.
  double dilation_slip_limit = std::numeric_limits<double>::infinity();
};

/// The state the interface starts from (the geostatic state).
struct ContactInitial {
  double gap_normal = 0.0;                 ///< g_N,0 [m]
  double contact_pressure_effective = 0.0; ///< p'_N0 [Pa], >= 0
};

/// History at an integration point: the tangential gap and shear stress of the last
/// converged step (local tangent components; only the first is used in 2D) and the plastic
/// slip accumulated so far (the length of the slip path, whatever its direction) [m].
struct ContactHistory {
  double gap_tangential[2] = {0.0, 0.0};
  double shear[2] = {0.0, 0.0};
  double slip_plastic = 0.0;
};

/// Normal dilation d = tan(psi) min(s_p, s_lim) [m] of an accumulated plastic slip s_p.
double dilation(const ContactParameters &p, double slip_plastic);

struct ContactResponse {
  double contact_pressure_effective = 0.0; ///< p'_N >= 0 (compression positive)
  double shear[2] = {0.0, 0.0};            ///< tau in the local tangent directions
  ContactState state = ContactState::open;
  /// Consistent tangent d(p'_N, tau_1, tau_2) / d(g_N, g_T1, g_T2); unsymmetric in slip.
  double tangent[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  /// Normal dilation d [m] of the current state and its derivative d(d) / d(g_N, g_T1, g_T2)
  /// (non-zero only while sliding with dilation, below the limit).
  double dilation = 0.0;
  double d_dilation[3] = {0.0, 0.0, 0.0};
  /// History to commit if the step converges.
  ContactHistory updated;
};

/// Traction of the interface for the current gaps. `tangential_dims` is 1 in 2D, 2 in 3D.
/// Normal: p'_N = p'_N0 - K_N (g_N - g_N,0 - d) >= 0, open (no traction) where the trial
/// pressure with the last converged dilation is negative. Slip with dilation: the plastic
/// slip increment dl of |tau| = mu p'_N solves |tau_trial| - K_T dl = mu (p_trial + K_N
/// tan(psi) min(dl, room)), room = s_lim - s_p,n the slip left before dilation stops.
ContactResponse contactResponse(const ContactParameters &p, const ContactInitial &initial,
                                const ContactHistory &history, int tangential_dims,
                                double gap_normal, const double gap_tangential[]);

/// Where the law changes branch (open / stick / slip, and slip with dilation / slip past the
/// dilation limit) along the straight gap path g(s) = g + s dg, 0 < s <= 1: appends every such
/// s to `out` (unsorted). On each interval between them the traction is smooth in s (linear in
/// 2D), so a Newton step's residual is piecewise smooth along the step, with kinks only there
/// (the line search of newton_control.cpp uses them).
void contactStateChanges(const ContactParameters &p, const ContactInitial &initial,
                         const ContactHistory &history, int tangential_dims, double gap_normal,
                         const double gap_tangential[], double d_gap_normal,
                         const double d_gap_tangential[], std::vector<double> &out);

/// Mechanical opening o = max(0, g_N - g_N,0 - p'_N0 / K_N - d) [m] beyond the (dilated)
/// contact position: zero while in contact. The hydraulic aperture is D0 + d + o.
double mechanicalOpening(const ContactParameters &p, const ContactInitial &initial,
                         double gap_normal, double dilation = 0.0);

} // namespace poroseam::physics
