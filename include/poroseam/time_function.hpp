// Time dependence of a boundary condition: value(t) = magnitude * factor(t).
#pragma once

#include <string>
#include <vector>

namespace poroseam {

class TimeFunction {
public:
  enum class Kind { step, ramp, table };

  /// Constant magnitude, switched on at t = 0+ (factor 0 at t <= 0, 1 after).
  static TimeFunction step();
  /// Linear from 0 at t = 0 to 1 at t = ramp_time, then held.
  static TimeFunction ramp(double ramp_time);
  /// Piecewise linear through (time, factor) pairs, held constant beyond the last one (and
  /// before the first, which the scene reader requires at t <= 0, the start of a run).
  static TimeFunction table(std::vector<double> times, std::vector<double> factors);

  double factor(double t) const;
  /// The same factor at every time (the same kind and parameters).
  bool operator==(const TimeFunction &o) const
  {
    return kind_ == o.kind_ && ramp_time_ == o.ramp_time_ && times_ == o.times_ &&
           factors_ == o.factors_;
  }
  Kind kind() const { return kind_; }

private:
  Kind kind_ = Kind::step;
  double ramp_time_ = 0.0;
  std::vector<double> times_, factors_;
};

/// The largest time table file read [bytes] (about a million rows).
constexpr unsigned long long kMaxTimeTableBytes = 64ull << 20;

/// Reads a two-column table "time,factor" (header line optional, '#' comments): exactly two
/// finite numbers a row, times increasing strictly, a regular file of at most
/// kMaxTimeTableBytes (a FIFO or a device is refused, not read: it could block forever).
/// Returns an empty string on success, otherwise an error message naming the file and line.
std::string readTimeTable(const std::string &path, std::vector<double> &times,
                          std::vector<double> &factors);

} // namespace poroseam
