// Option getters on PETSc's options API (see scene_options.hpp): each one is a PetscOptions*
// call inside the caller's PetscOptionsBegin/End section, so -help prints it.
#include "poroseam/scene_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace poroseam {
namespace {

/// A number as -help shows a default: as short as %g makes it.
std::string shown(double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

} // namespace

bool parseNumber(const std::string &text, double *value)
{
  const char *begin = text.c_str();
  char *end = nullptr;
  const double v = std::strtod(begin, &end);
  while (end && (*end == ' ' || *end == '\t'))
    ++end;
  if (end == begin || !end || *end != '\0' || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

namespace {

PetscErrorCode readString(PetscOptionItems *PetscOptionsObject, const std::string &option,
                          const std::string &help, const char *doc, std::string &value, bool *set)
{
  char buffer[PETSC_MAX_PATH_LEN] = "";
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString(option.c_str(), help.c_str(), doc,
                               value.empty() ? "(none)" : value.c_str(), buffer, sizeof buffer,
                               &found));
  if (found) value = buffer;
  if (set) *set = found;
  PetscFunctionReturn(0);
}

PetscErrorCode readReal(PetscOptionItems *PetscOptionsObject, const std::string &option,
                        const std::string &help, const char *doc, double *value, bool *set,
                        const char *unset)
{
  char buffer[256] = "";
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString(option.c_str(), help.c_str(), doc,
                               unset ? unset : shown(*value).c_str(), buffer, sizeof buffer,
                               &found));
  if (found) {
    double v;
    PetscCheck(parseNumber(buffer, &v), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
               "option %s %s: expected a number", option.c_str(),
               buffer[0] ? buffer : "(no value)");
    *value = v;
  }
  if (set) *set = found;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode getString(PetscOptionItems *PetscOptionsObject, const std::string &option,
                         const std::string &help, std::string &value, bool *set)
{
  return readString(PetscOptionsObject, option, help, kSceneDoc, value, set);
}

PetscErrorCode getReal(PetscOptionItems *PetscOptionsObject, const std::string &option,
                       const std::string &help, double *value, bool *set, const char *unset)
{
  return readReal(PetscOptionsObject, option, help, kSceneDoc, value, set, unset);
}

PetscErrorCode getRequiredReal(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                               const std::string &option, const std::string &help, double *value)
{
  char buffer[256] = "";
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString(option.c_str(), (help + " (required)").c_str(), kSceneDoc, "(none)",
                               buffer, sizeof buffer, &found));
  PetscCheck(found, comm, PETSC_ERR_USER_INPUT, "missing option %s: %s is required", option.c_str(),
             help.c_str());
  double v;
  PetscCheck(parseNumber(buffer, &v), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "option %s %s: expected a number", option.c_str(), buffer[0] ? buffer : "(no value)");
  *value = v;
  PetscFunctionReturn(0);
}

PetscErrorCode getRealList(PetscOptionItems *PetscOptionsObject, const std::string &option,
                           const std::string &help, std::vector<double> &values, bool *set)
{
  std::string text;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(getString(PetscOptionsObject, option, help, text, &found));
  values.clear();
  if (found) {
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
      double v;
      PetscCheck(parseNumber(item, &v), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
                 "option %s %s: expected comma-separated numbers", option.c_str(), text.c_str());
      values.push_back(v);
    }
  }
  if (set) *set = found;
  PetscFunctionReturn(0);
}

namespace {

PetscErrorCode readStringList(PetscOptionItems *PetscOptionsObject, const std::string &option,
                              const std::string &help, const char *doc,
                              std::vector<std::string> &values, bool *set)
{
  std::string text;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(readString(PetscOptionsObject, option, help, doc, text, &found));
  values.clear();
  if (found && !text.empty()) {
    std::string::size_type start = 0;
    for (;;) {
      const auto comma = text.find(',', start);
      values.push_back(text.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  if (set) *set = found;
  PetscFunctionReturn(0);
}

PetscErrorCode readFlag(PetscOptionItems *PetscOptionsObject, const std::string &option,
                        const std::string &help, const char *doc, bool *value, bool *set)
{
  PetscBool flag = *value ? PETSC_TRUE : PETSC_FALSE, found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool(option.c_str(), help.c_str(), doc, flag, &flag, &found));
  *value = flag;
  if (set) *set = found;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode getStringList(PetscOptionItems *PetscOptionsObject, const std::string &option,
                             const std::string &help, std::vector<std::string> &values, bool *set)
{
  return readStringList(PetscOptionsObject, option, help, kSceneDoc, values, set);
}

PetscErrorCode getFlag(PetscOptionItems *PetscOptionsObject, const std::string &option,
                       const std::string &help, bool *value, bool *set)
{
  return readFlag(PetscOptionsObject, option, help, kSceneDoc, value, set);
}

PetscErrorCode getReal(PetscOptionItems *PetscOptionsObject, const OptionSpec &option,
                       double *value, bool *set)
{
  return readReal(PetscOptionsObject, option.flag, option.help, option.doc, value, set, nullptr);
}

PetscErrorCode getString(PetscOptionItems *PetscOptionsObject, const OptionSpec &option,
                         std::string &value, bool *set)
{
  return readString(PetscOptionsObject, option.flag, option.help, option.doc, value, set);
}

PetscErrorCode getStringList(PetscOptionItems *PetscOptionsObject, const OptionSpec &option,
                             std::vector<std::string> &values, bool *set)
{
  return readStringList(PetscOptionsObject, option.flag, option.help, option.doc, values, set);
}

PetscErrorCode getFlag(PetscOptionItems *PetscOptionsObject, const OptionSpec &option, bool *value,
                       bool *set)
{
  return readFlag(PetscOptionsObject, option.flag, option.help, option.doc, value, set);
}

} // namespace poroseam
