// Every option as given, before PETSc starts: see given_options.hpp.
#include "poroseam/given_options.hpp"

#include "poroseam/run_options.hpp"

#include <cctype>
#include <cstdio>
#include <set>

namespace poroseam {
namespace {

bool contains(const std::string &s, const char *part)
{
  return s.find(part) != std::string::npos;
}

bool endsWith(const std::string &s, const std::string &suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Options whose value names a file or a directory: poroseam's, and PETSc's viewers and
/// monitors ("-log_view :run.xml:ascii_xml"), which write to a file they name.
bool takesPath(const std::string &name)
{
  for (const char *exact : {"-mesh", "-output_dir", "-restart"})
    if (name == exact) return true;
  for (const char *suffix : {"_table", "_dump_operator", "_file", "_dir"})
    if (endsWith(name, suffix)) return true;
  return contains(name, "view") || contains(name, "monitor") || name.rfind("-log", 0) == 0;
}

/// The first control character of `text` as a reader would name it, or "".
std::string controlCharacter(const std::string &text)
{
  for (unsigned char c : text) {
    if (c == '\n') return "a line break";
    if (c == '\r') return "a carriage return";
    if (c == '\t') return "a tab";
    if (c < 0x20 || c == 0x7f) {
      char code[48];
      std::snprintf(code, sizeof code, "the control character 0x%02x", c);
      return code;
    }
  }
  return "";
}

/// `text` on one line, at most `most` characters of it.
std::string shown(const std::string &text, std::size_t most = 60)
{
  std::string s;
  for (unsigned char c : text) {
    if (s.size() >= most) return s + "...";
    if (c == '\n')
      s += "\\n";
    else if (c == '\t')
      s += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "\\x%02x", c);
      s += code;
    } else
      s += (char)c;
  }
  return s;
}

std::string lowered(std::string s)
{
  for (char &c : s)
    c = (char)std::tolower((unsigned char)c);
  return s;
}

} // namespace

std::string checkGivenOptions(const std::vector<GivenOption> &options)
{
  std::set<std::string> names;
  std::size_t probes = 0;
  for (const auto &o : options) {
    const std::string where = " (" + o.where + ")";
    const std::string in_name = controlCharacter(o.name);
    if (!in_name.empty())
      return "option '" + shown(o.name) + "'" + where + " holds " + in_name +
             " in its name: an option name is '-' and letters, digits and '_'";
    if (o.name.size() > kMaxOptionValue)
      return "option " + shown(o.name) + where + ": a name of " + std::to_string(o.name.size()) +
             " characters, more than the " + std::to_string(kMaxOptionValue) +
             " PETSc reads; no option of poroseam or PETSc is that long";
    const std::string in_value = controlCharacter(o.value);
    if (!in_value.empty())
      return "option " + o.name + where + ": its value '" + shown(o.value, 400) + "' holds " +
             in_value + "; control characters are refused in values (in a path they would " +
             "break run.yaml, the XDMF and the CSV files)";
    const bool path = takesPath(o.name);
    const std::size_t most = path ? kMaxOptionPath : kMaxOptionValue;
    if (o.value.size() > most)
      return "option " + o.name + where + ": a value of " + std::to_string(o.value.size()) +
             " characters ('" + shown(o.value, 24) + "'), more than the " + std::to_string(most) +
             " PETSc reads for " + (path ? "a path" : "a value") +
             " (the rest would be cut off silently)";
    // Here, where the file and line are known; checkNumericOptions checks the same again.
    const std::string range = integerRangeError(o.name, o.value);
    if (!range.empty()) return "option " + o.name + " " + o.value + where + ": " + range;
    names.insert(lowered(o.name));
    if (o.name.rfind("-probe_", 0) == 0) ++probes;
  }
  if (names.size() > kMaxGivenOptions)
    return std::to_string(names.size()) +
           " options given (command line and options files), more than the " +
           std::to_string(kMaxGivenOptions) +
           " poroseam accepts (PETSc 3.18 holds 512 options; 64 are kept for the solver " +
           "preset and PETSc's own)" +
           (probes > names.size() / 2
                ? ": " + std::to_string(probes) + " of them are probes (-probe_<name>); use fewer"
                : std::string());
  return "";
}

} // namespace poroseam
