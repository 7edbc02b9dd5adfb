// Mechanical law of a zero-thickness interface (docs/physics.md section 4, paper section 2.1): normal
// penalty contact without tension, and Coulomb friction written as elastoplasticity (stick =
// elastic with tangential penalty K_T, slip = plastic on |tau| = mu p'_N), with a return
// mapping from the last converged state. Pure point law in the local frame (e1 normal of
// side 1 towards side 2, e2 and e3 tangent); gaps in m, stresses in Pa.
#pragma once

#include <vector>

namespace poroseam::physics {

enum class ContactState { open = 0, stick = 1, slip = 2 };

struct ContactParameters {
  double normal_stiffness = 0.0;     ///< K_N [Pa/m]
  double tangential_stiffness = 0.0; ///< K_T [Pa/m]
  double friction = 0.0;             ///< mu [-]
};

/// The state the interface starts from (the geostatic state).
struct ContactInitial {
  double gap_normal = 0.0;                 ///< g_N,0 [m]
  double contact_pressure_effective = 0.0; ///< p'_N0 [Pa], >= 0
};

/// History at an integration point: the tangential gap and shear stress of the last
/// converged step (local tangent components; only the first is used in 2D).
struct ContactHistory {
  double gap_tangential[2] = {0.0, 0.0};
  double shear[2] = {0.0, 0.0};
};

struct ContactResponse {
  double contact_pressure_effective = 0.0; ///< p'_N >= 0 (compression positive)
  double shear[2] = {0.0, 0.0};            ///< tau in the local tangent directions
  ContactState state = ContactState::open;
  /// Consistent tangent d(p'_N, tau_1, tau_2) / d(g_N, g_T1, g_T2); unsymmetric in slip.
  double tangent[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  /// History to commit if the step converges.
  ContactHistory updated;
};

/// Traction of the interface for the current gaps. `tangential_dims` is 1 in 2D, 2 in 3D.
ContactResponse contactResponse(const ContactParameters &p, const ContactInitial &initial,
                                const ContactHistory &history, int tangential_dims,
                                double gap_normal, const double gap_tangential[]);

/// Where the law changes branch (open / stick / slip) along the straight gap path
/// g(s) = g + s dg, 0 < s <= 1: appends every such s to `out` (unsorted). On each interval
/// between them the traction is linear in s, so a Newton step's residual is piecewise linear
/// along the step, with kinks only there (the line search of newton_control.cpp uses them).
void contactStateChanges(const ContactParameters &p, const ContactInitial &initial,
                         const ContactHistory &history, int tangential_dims, double gap_normal,
                         const double gap_tangential[], double d_gap_normal,
                         const double d_gap_tangential[], std::vector<double> &out);

/// Mechanical opening o = max(0, g_N - g_N,0 - p'_N0 / K_N) [m]: zero while in contact.
double mechanicalOpening(const ContactParameters &p, const ContactInitial &initial,
                         double gap_normal);

} // namespace poroseam::physics
