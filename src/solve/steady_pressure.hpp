// The steady pore pressure (docs/outputs.md, "Steady and excess pore pressure"): the pressure
// the water would settle to if the hydraulic conditions of time t (prescribed p and p3, fluxes)
// stayed as they are, with the current displacements. PLAXIS reports the same split: its
// steady-state pore pressure from the phreatic level of the phase, and the excess over it.
// When a river rises (docs/tutorial.md), the steady pressure follows the river; the excess is
// what consolidation still has to dissipate, and tends to 0 in the drained state.
//
// Computed from the run's own residual with every rate set to 0 (no storage, no volume change:
// only the flows), solved for the pressure unknowns (p and p3) with the displacements held:
// Newton on the pressure block of the Jacobian (shift 0), factored by a direct solver; the
// flows are linear in the pressures, so one iteration solves it, a second checks it.
// Recomputed only when the hydraulic conditions change (their values at t are compared with
// those of the last solve): once per run for constant conditions. Undefined when no pressure
// is prescribed anywhere (a closed body keeps whatever water it has) or when the pressure
// block is singular (a region with zero permeability): then the initial pressure stands in,
// as before this split existed, and the run says so once. Internal to src/solve.
#pragma once

#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"

#include <petscksp.h>
#include <vector>

namespace poroseam {
namespace simulation_detail {

class SteadyPressure {
public:
  /// Collective. `initial` (local) is the stand-in where the steady pressure is undefined.
  PetscErrorCode setup(DM dm, const Scene &scene, Vec initial);
  /// Collective. A local vector whose pressures (p, p3) are the steady ones at time t for the
  /// displacements of `local` (boundary values inserted), valid until the next call; nullptr
  /// for scenes without pressure unknowns. `J` is work space (a matrix of the DM).
  PetscErrorCode compute(const Problem &problem, double t, Vec local, Mat J, Vec *steady);
  PetscErrorCode destroy();

  /// For checkpoints: the steady state kept (this rank's local vector) and the conditions it
  /// was solved for; empty when none is kept. A restart gives them back (restore) so that it
  /// continues with the steady state the interrupted run had, not one solved anew at the
  /// restart's displacements (which differs with apertures, and by round-off anyway).
  PetscErrorCode kept(std::vector<double> &values, std::vector<double> &conditions) const;
  PetscErrorCode restore(const std::vector<double> &values, const std::vector<double> &conditions);

private:
  /// The values of the hydraulic conditions at t.
  std::vector<double> signature(const Scene &scene, double t) const;
  PetscErrorCode solve(const Problem &problem, double t, Vec local, Mat J, bool *solved);

  DM dm_ = nullptr;
  bool enabled_ = false; ///< the scene has pressure unknowns
  bool defined_ = false; ///< some pressure is prescribed
  bool warned_ = false;
  bool have_ = false; ///< steady_ holds a solve for signature_
  std::vector<double> signature_;
  Vec initial_ = nullptr;                      ///< not owned
  Vec steady_ = nullptr, zero_rate_ = nullptr; ///< local
  IS pressure_ = nullptr;                      ///< global indices of p and p3
  KSP ksp_ = nullptr;
};

} // namespace simulation_detail
} // namespace poroseam
