// The wall time still needed (include/poroseam/time_to_finish.hpp) against the true remaining
// wall time of synthetic runs: fixed steps of 6 s to 288 s (the caisson scenes), each step
// costing 1 s +- 30 % (a fixed pseudo-random sequence), the first cut back three times (four
// attempts and the matrix factorisation: about 5 s for 0.75 s of simulated time) and growing
// back by 2 per step, a step in the middle cut back eight times (nine attempts for 6/256 s).
// The estimate cannot know of a cut-back still to come; from the third step on it must be
// within a factor 2 of the truth, and so must each estimate of the one before, less the step
// just taken. The mean wall time per unit of simulated time (the former estimate) fails this,
// which shows that the check can tell.
#include "poroseam/time_to_finish.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using poroseam::formatDuration;
using poroseam::TimeToFinish;

namespace {

struct Step {
  double wall, dt, t;
};

/// The synthetic run: costs times `cost_after(k)` from step k on.
std::vector<Step> syntheticRun(double late_cost = 1.0, int late_from = 1 << 30)
{
  const double nominal = 6.0, t_end = 288.0;
  std::uint64_t state = 12345;
  auto uniform = [&]() { // in [0, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(state >> 11) / 9007199254740992.0;
  };
  std::vector<Step> run;
  double t = 0.0, next = nominal;
  for (int k = 1; t < t_end - 1e-9; ++k) {
    const int cuts = k == 1 ? 3 : k == 20 ? 8 : 0;
    const double factorisation = k == 1 ? 1.0 : 0.0;
    const double cost = (k >= late_from ? late_cost : 1.0) * (1.0 + 0.3 * (2.0 * uniform() - 1.0));
    const double dt = std::min(next / std::pow(2.0, cuts), t_end - t);
    t += dt;
    run.push_back({cost * (cuts + 1) + factorisation, dt, t});
    next = std::min(nominal, 2.0 * dt);
  }
  return run;
}

/// Estimates after each step: the median-based one and the former one (mean wall time per unit
/// of simulated time).
void estimates(const std::vector<Step> &run, std::vector<double> &median_based,
               std::vector<double> &per_simulated_time, std::vector<double> &truth)
{
  TimeToFinish eta;
  double wall = 0.0;
  for (size_t k = 0; k < run.size(); ++k) {
    eta.addStep(run[k].wall);
    wall += run[k].wall;
    median_based.push_back(eta.seconds(run[k].t, 288.0, 6.0));
    per_simulated_time.push_back((288.0 - run[k].t) * wall / run[k].t);
    double left = 0.0;
    for (size_t j = k + 1; j < run.size(); ++j)
      left += run[j].wall;
    truth.push_back(left);
  }
}

/// Largest factor between estimate and truth over steps 3 to the last but one, and between
/// consecutive estimates from step 3 on (the later one plus the step it took).
void worstFactors(const std::vector<Step> &run, const std::vector<double> &estimate,
                  const std::vector<double> &truth, double *vs_truth, double *swing)
{
  *vs_truth = 1.0, *swing = 1.0;
  auto factor = [](double a, double b) { return std::max(a / b, b / a); };
  for (size_t k = 2; k + 1 < run.size(); ++k) {
    *vs_truth = std::max(*vs_truth, factor(estimate[k], truth[k]));
    if (k >= 3) *swing = std::max(*swing, factor(estimate[k] + run[k].wall, estimate[k - 1]));
  }
}

} // namespace

TEST(TimeToFinish, CutBacksDoNotSwingTheEstimate)
{
  const std::vector<Step> run = syntheticRun();
  ASSERT_EQ(run.size(), 58u); // 48 steps, 3 to grow back after the first, 8 after step 20
  std::vector<double> ours, former, truth;
  estimates(run, ours, former, truth);
  double ours_truth, ours_swing, former_truth, former_swing;
  worstFactors(run, ours, truth, &ours_truth, &ours_swing);
  worstFactors(run, former, truth, &former_truth, &former_swing);
  std::printf("worst factor vs truth / between steps: median-based %.2f / %.2f, per simulated "
              "time %.2f / %.2f\n",
              ours_truth, ours_swing, former_truth, former_swing);
  EXPECT_LE(ours_truth, 2.0);
  EXPECT_LE(ours_swing, 2.0);
  EXPECT_GT(former_truth, 2.0); // the check tells the two apart
}

// A lasting change of the cost per step (plastic flow setting in at step 30, 1.5 times the
// cost): the estimate follows within half its window.
TEST(TimeToFinish, FollowsALastingChangeOfCost)
{
  const std::vector<Step> run = syntheticRun(1.5, 30);
  std::vector<double> ours, former, truth;
  estimates(run, ours, former, truth);
  const size_t settled = 30 + TimeToFinish::kWindow / 2 + 1;
  for (size_t k = settled; k + 3 < run.size(); ++k) // the last steps: few to average
    EXPECT_NEAR(ours[k] / truth[k], 1.0, 0.35) << "after step " << k + 1;
}

TEST(TimeToFinish, UnknownAndDone)
{
  TimeToFinish eta;
  EXPECT_LT(eta.seconds(0.0, 10.0, 1.0), 0.0); // no step yet
  eta.addStep(2.0);
  EXPECT_LT(eta.seconds(1.0, 10.0, 0.0), 0.0);         // no step size
  EXPECT_DOUBLE_EQ(eta.seconds(10.0, 10.0, 1.0), 0.0); // at the final time
  EXPECT_DOUBLE_EQ(eta.seconds(4.0, 10.0, 2.0), 6.0);  // 3 steps of 2 s
  EXPECT_DOUBLE_EQ(eta.seconds(4.5, 10.0, 2.0), 6.0);  // 2.75 steps: the last one clipped
  EXPECT_EQ(formatDuration(-1.0), "?");
  EXPECT_EQ(formatDuration(42.4), "42 s");
  EXPECT_EQ(formatDuration(1020.0), "17 min");
  EXPECT_EQ(formatDuration(3.2 * 3600.0), "3.2 h");
}
