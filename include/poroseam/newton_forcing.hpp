#pragma once
// Linear tolerance of each Newton solve: the forcing term of an inexact Newton method
// (Eisenstat and Walker, SIAM J. Sci. Comput. 17, 1996). Newton on contact and friction is
// limited by its active set (stick/slip, open/closed) settling, not by the accuracy of the
// linear solves, so solving each to -ksp_rtol wastes most iterations of an iterative solver.

#include <algorithm>

namespace poroseam {

/// Relative tolerance for the next linear solve of a Newton iteration.
///   floor:         the tightest tolerance asked for (-ksp_rtol);
///   target_ratio:  target / |F_k|, the reduction that would end Newton now (0: not known,
///                  as at a step's first solve);
///   contraction:   |F_k| / |F_k-1|, how much the last Newton iteration reduced the residual
///                  (for a step's first solve, that of the last step's first iteration;
///                  0: not known, or a step that converged in one iteration).
/// Two reasons to solve less exactly than the floor, the larger wins:
///   - a hundred times below the target is all this iteration needs to end Newton;
///   - when the last Newton iteration only reduced the residual by a factor c, the next
///     iterate's residual is dominated by the non-linearity at about c |F|, so a linear
///     residual below c/10 |F| does not change it (Eisenstat-Walker choice 2, alpha 1,
///     gamma 0.1).
/// At most 0.01, so that every solve still makes a real Newton step. 0.01, not 0.1: with one
/// AMG V-cycle per outer iteration (options/solvers/fieldsplit.opts) a solve stopped at 0.1
/// leaves its error spread over the interface points, and the active set took longer to
/// settle: whole 37k-unknown 3D caisson run, 2 ranks, 60 Newton and 1310 outer iterations
/// with 0.01, 68 and 1376 with 0.1.
/// Nothing known (no target, no contraction) gives the floor; newton_control.cpp passes the
/// target from the first solve of a step on, so a step that ends in one Newton iteration
/// solves a hundred times below its target, not to the floor.
inline double linearTolerance(double floor, double target_ratio, double contraction)
{
  constexpr double loosest = 0.01;
  const double to_finish = 0.01 * std::max(target_ratio, 0.0);
  const double below_nonlinearity = 0.1 * std::max(contraction, 0.0);
  return std::max(floor, std::min(loosest, std::max(to_finish, below_nonlinearity)));
}

} // namespace poroseam
