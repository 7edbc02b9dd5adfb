#include "poroseam/time_to_finish.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace poroseam {

void TimeToFinish::addStep(double wall)
{
  if (!(wall >= 0.0)) return; // NaN or negative: no measurement
  recent_.push_back(wall);
  if ((int)recent_.size() > kWindow) recent_.erase(recent_.begin());
}

double TimeToFinish::seconds(double t, double t_end, double step) const
{
  if (recent_.empty() || !(step > 0.0)) return -1.0;
  const double left = t_end - t;
  if (!(left > 0.0)) return 0.0;
  // The last step is clipped to land on t_end: whole steps, rounding a last fraction up
  // (a relative 1e-9 for times like 288 s / 6 s that are whole numbers of steps in theory).
  const double steps = std::ceil(left / step * (1.0 - 1e-9));
  std::vector<double> sorted = recent_;
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  return steps * median;
}

std::string formatDuration(double seconds)
{
  if (seconds < 0.0) return "?";
  char text[32];
  if (seconds < 120.0)
    std::snprintf(text, sizeof(text), "%.0f s", seconds);
  else if (seconds < 7200.0)
    std::snprintf(text, sizeof(text), "%.0f min", seconds / 60.0);
  else
    std::snprintf(text, sizeof(text), "%.1f h", seconds / 3600.0);
  return text;
}

} // namespace poroseam
