#include "poroseam/time_function.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

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

namespace {

/// The fields of a table line, trimmed: separated by commas ("0,1", "0, 1", "0,,1" has an
/// empty second field) or, in a line without a comma, by blanks ("0 1").
std::vector<std::string> tableFields(const std::string &line)
{
  std::vector<std::string> fields;
  const bool commas = line.find(',') != std::string::npos;
  std::istringstream in(line);
  std::string field;
  if (commas) {
    while (std::getline(in, field, ',')) {
      const auto a = field.find_first_not_of(" \t\r"), b = field.find_last_not_of(" \t\r");
      fields.push_back(a == std::string::npos ? "" : field.substr(a, b - a + 1));
    }
    if (line[line.find_last_not_of(" \t\r")] == ',') fields.push_back(""); // "0,1,": a third field
  } else {
    while (in >> field)
      fields.push_back(field);
  }
  return fields;
}

/// A header names its columns: its first field starts with a letter and is not a number
/// strtod would read ("nan", "inf": those are refused as values, not skipped as a header).
bool headerField(std::string field)
{
  for (auto &ch : field)
    ch = (char)std::tolower((unsigned char)ch);
  return !field.empty() && std::isalpha((unsigned char)field[0]) && field.rfind("nan", 0) != 0 &&
         field.rfind("inf", 0) != 0;
}

std::string shown(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

/// A field as a message may quote it: a binary file's bytes become '?', and at most 24
/// characters are shown.
std::string quoted(const std::string &field)
{
  std::string s = field.substr(0, 24);
  for (auto &ch : s)
    if (!std::isprint((unsigned char)ch)) ch = '?';
  return field.size() > 24 ? s + "..." : s;
}

/// A finite number written in full (no trailing text): "1e400", "nan", "inf", "1x" are not.
bool finiteNumber(const std::string &text, double *value)
{
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

} // namespace

std::string readTimeTable(const std::string &path, std::vector<double> &times,
                          std::vector<double> &factors)
{
  times.clear();
  factors.clear();
  // A FIFO or a device would block or never end (/dev/zero), a directory reads as empty:
  // only a regular file is a table. Its size is bounded before a line is read, so that a
  // huge file (or one without line breaks) is refused, not read into memory on every rank.
  struct stat st;
  if (stat(path.c_str(), &st) != 0)
    return "cannot open time table '" + path + "': " + std::strerror(errno);
  if (!S_ISREG(st.st_mode))
    return "time table '" + path + "' is not a regular file (" +
           (S_ISDIR(st.st_mode)    ? "a directory"
            : S_ISFIFO(st.st_mode) ? "a FIFO"
                                   : "a device or socket") +
           "): give a CSV file of rows 'time,factor'";
  if ((unsigned long long)st.st_size > kMaxTimeTableBytes)
    return "time table '" + path + "' is " + std::to_string((unsigned long long)st.st_size) +
           " bytes, more than the " + std::to_string(kMaxTimeTableBytes >> 20) +
           " MiB a table of 'time,factor' rows may have (thin it out: the factor is "
           "interpolated linearly between rows)";
  std::ifstream in(path);
  if (!in) return "cannot open time table '" + path + "'";
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = "time table '" + path + "' line " + std::to_string(lineno) + ": ";
    const auto fields = tableFields(line);
    double t, f;
    // The first line may be a header ("time,factor").
    if (lineno == 1 && headerField(fields[0])) continue;
    if (fields.size() != 2)
      return where + std::to_string(fields.size()) + (fields.size() == 1 ? " field" : " fields") +
             ", expected two numbers 'time,factor' (a table has exactly two columns)";
    if (!finiteNumber(fields[0], &t) || !finiteNumber(fields[1], &f))
      return where + "'" + quoted(fields[0]) + "," + quoted(fields[1]) +
             "': expected two finite numbers 'time,factor'";
    if (!times.empty() && t <= times.back())
      return where + "time " + quoted(fields[0]) + " after " + shown(times.back()) +
             ": times must increase strictly";
    times.push_back(t);
    factors.push_back(f);
  }
  if (times.empty()) return "time table '" + path + "' has no rows 'time,factor'";
  return "";
}

} // namespace poroseam
