// Is an interface's penalty stiffness sensible for the mesh beside it?
//
// A penalty K [Pa/m] acts like a thin elastic layer in series with the elements on both
// sides. Against an element of size h (normal to the face) and Young's modulus E, whose
// stiffness per unit area is about E / h, the ratio beta = K h / E says how much compliance the
// interface adds: beta = 100 adds about 1 %. docs/interface_parameters.md explains the range.
#pragma once

namespace poroseam {

/// The recommended range of beta = K h / E (docs/interface_parameters.md).
constexpr double kPenaltyRatioSoft = 1.0;  ///< below: the interface is as compliant as an element
constexpr double kPenaltyRatioStiff = 1e4; ///< above: the penalties dominate the conditioning

enum class PenaltyVerdict { fine, too_soft, too_stiff };

/// Verdict for a penalty K against its softest (E_soft, the body whose deformation the overlap
/// competes with) and stiffest (E_stiff, whose rows the penalty competes with in the matrix)
/// neighbour, both next to a face of height h. Pure: unit-tested in tests/unit.
inline PenaltyVerdict advisePenalty(double K, double h, double E_soft, double E_stiff)
{
  if (!(K > 0.0) || !(h > 0.0) || !(E_soft > 0.0) || !(E_stiff > 0.0)) return PenaltyVerdict::fine;
  if (K * h / E_soft < kPenaltyRatioSoft) return PenaltyVerdict::too_soft;
  if (K * h / E_stiff > kPenaltyRatioStiff) return PenaltyVerdict::too_stiff;
  return PenaltyVerdict::fine;
}

} // namespace poroseam
