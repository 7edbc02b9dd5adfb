#include "poroseam/time_function.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace poroseam {

TimeFunction TimeFunction::step()
{
  return TimeFunction();
}

TimeFunction TimeFunction::ramp(double ramp_time)
{
  TimeFunction f;
  f.kind_ = Kind::ramp;
  f.ramp_time_ = ramp_time;
  return f;
}

TimeFunction TimeFunction::table(std::vector<double> times, std::vector<double> factors)
{
  TimeFunction f;
  f.kind_ = Kind::table;
  f.times_ = std::move(times);
  f.factors_ = std::move(factors);
  return f;
}

double TimeFunction::factor(double t) const
{
  switch (kind_) {
  case Kind::step:
    return t > 0.0 ? 1.0 : 0.0;
  case Kind::ramp:
    return t <= 0.0 ? 0.0 : std::min(t / ramp_time_, 1.0);
  case Kind::table: {
    if (t <= times_.front()) return factors_.front();
    if (t >= times_.back()) return factors_.back();
    const size_t i = std::upper_bound(times_.begin(), times_.end(), t) - times_.begin();
    const double s = (t - times_[i - 1]) / (times_[i] - times_[i - 1]);
    return (1.0 - s) * factors_[i - 1] + s * factors_[i];
  }
  }
  return 0.0;
}

std::string readTimeTable(const std::string &path, std::vector<double> &times,
                          std::vector<double> &factors)
{
  std::ifstream in(path);
  if (!in) return "cannot open time table '" + path + "'";
  times.clear();
  factors.clear();
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double t, f;
    if (!(fields >> t >> f)) {
      if (times.empty() && lineno == 1) continue; // header
      return "time table '" + path + "' line " + std::to_string(lineno) +
             ": expected two numbers 'time,factor'";
    }
    if (!times.empty() && t <= times.back())
      return "time table '" + path + "' line " + std::to_string(lineno) +
             ": times must increase strictly";
    times.push_back(t);
    factors.push_back(f);
  }
  if (times.empty()) return "time table '" + path + "' has no rows 'time,factor'";
  return "";
}

} // namespace poroseam
