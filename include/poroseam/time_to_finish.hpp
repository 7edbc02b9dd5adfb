#pragma once
// The wall time a run still needs, shown on each step line ("eta"). Pure: fed the wall time
// of each accepted step, asked with the time reached, the final time and the size of the
// coming steps.
//
// Why not the mean wall time per unit of simulated time: a step cut back k times costs k + 1
// attempts and simulates 2^-k of a step, and the cut steps grow back by 2 per step, so a run
// whose first step was cut back three times promised 30 times its real remaining time at its
// first step and then fell step by step (issue 24: "from 58 to 3 minutes"). Here: the steps
// still to take at the coming step size, times the median wall time of the last few steps.
// The median ignores a step that needed several attempts (or the first, which also factors
// the matrix) as long as most recent steps did not, and follows a lasting change of the cost
// (plastic flow setting in) within half a window.

#include <string>
#include <vector>

namespace poroseam {

class TimeToFinish {
public:
  /// Steps in the median's window.
  static constexpr int kWindow = 9;

  /// An accepted step took `wall` seconds (its rejected attempts included).
  void addStep(double wall);

  /// Seconds still needed from time t to t_end at steps of `step` (the coming step size: the
  /// nominal one at fixed steps, the controller's at adaptive steps); < 0 when not known yet
  /// (no step, or no step size).
  double seconds(double t, double t_end, double step) const;

private:
  std::vector<double> recent_; ///< wall times of the last kWindow steps, oldest first
};

/// "42 s", "17 min", "3.2 h"; "?" for a negative (unknown) duration.
std::string formatDuration(double seconds);

} // namespace poroseam
