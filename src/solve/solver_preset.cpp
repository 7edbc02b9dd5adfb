#include "poroseam/solver_preset.hpp"

#include "poroseam/option_registry.hpp"

#include "poroseam/auto_threshold.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

#ifndef POROSEAM_SOLVER_DIR
#error "POROSEAM_SOLVER_DIR (the folder of the solver presets) must be defined by the build"
#endif

namespace poroseam {
namespace {

bool validName(const std::string &name)
{
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum((unsigned char)c) || c == '_' || c == '-')) return false;
  return true;
}

/// Copies the options of `file` into the global database, except those already set there.
PetscErrorCode insertUnset(MPI_Comm comm, const std::string &file)
{
  PetscOptions preset;
  char *all;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsCreate(&preset));
  PetscCall(PetscOptionsInsertFile(comm, preset, file.c_str(), PETSC_TRUE));
  PetscCall(PetscOptionsGetAll(preset, &all));
  // "-name value -flag -name2 value2 ...": a token that starts with '-' followed by a letter
  // is a name, anything else the value of the name before it (presets hold no negative
  // numbers as separate values with letters, e.g. 1e-8 starts with a digit).
  std::istringstream tokens(all);
  std::string token, name, value;
  auto flush = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (!name.empty()) {
      PetscBool set;
      PetscCall(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &set));
      if (!set)
        PetscCall(
            PetscOptionsSetValue(nullptr, name.c_str(), value.empty() ? nullptr : value.c_str()));
    }
    name.clear();
    value.clear();
    PetscFunctionReturn(0);
  };
  while (tokens >> token) {
    if (token.size() > 1 && token[0] == '-' && std::isalpha((unsigned char)token[1])) {
      PetscCall(flush());
      name = token;
    } else {
      value = value.empty() ? token : value + " " + token;
    }
  }
  PetscCall(flush());
  PetscCall(PetscFree(all));
  PetscCall(PetscOptionsDestroy(&preset));
  PetscFunctionReturn(0);
}

} // namespace

std::string solverPresetFile(const std::string &name)
{
  if (!validName(name)) return "";
  const std::string file = std::string(POROSEAM_SOLVER_DIR) + "/" + name + ".opts";
  struct stat info;
  return stat(file.c_str(), &info) == 0 && S_ISREG(info.st_mode) ? file : "";
}

bool isSolverPresetFile(const std::string &path)
{
  std::error_code failed;
  const auto folder = std::filesystem::weakly_canonical(POROSEAM_SOLVER_DIR, failed);
  if (failed) return false;
  return std::filesystem::weakly_canonical(path, failed).parent_path() == folder && !failed;
}

std::vector<std::string> solverPresetOptionNames()
{
  std::vector<std::string> names;
  std::error_code failed;
  for (const auto &entry : std::filesystem::directory_iterator(POROSEAM_SOLVER_DIR, failed)) {
    if (entry.path().extension() != ".opts") continue;
    std::ifstream in(entry.path());
    std::string word;
    for (std::string line; std::getline(in, line);) {
      std::istringstream words(line);
      if (words >> word && word.size() > 1 && word[0] == '-' &&
          std::isalpha((unsigned char)word[1]))
        names.push_back(word.substr(1));
    }
  }
  return names;
}

std::string solverPresetList()
{
  std::vector<std::string> names;
  std::error_code failed;
  for (const auto &entry : std::filesystem::directory_iterator(POROSEAM_SOLVER_DIR, failed))
    if (entry.path().extension() == ".opts" && validName(entry.path().stem().string()))
      names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  std::string list;
  for (const auto &n : names)
    list += (list.empty() ? "" : ", ") + n;
  return list.empty() ? "(none)" : list;
}

long defaultAutoThreshold(int displacement_order)
{
  return displacement_order >= 2 ? 70000 : 30000;
}

std::string chosenPreset(const std::string &preset, bool solver_named, int dim, double unknowns,
                         long threshold)
{
  if (!preset.empty() && preset != "auto") return preset;
  if (solver_named) return "";
  return dim == 3 && unknowns > threshold ? "fieldsplit" : "direct";
}

PetscErrorCode applySolverPreset(MPI_Comm comm, int dim, int displacement_order, long unknowns,
                                 std::string *choice)
{
  char buffer[256] = "auto";
  PetscBool given;
  PetscInt threshold;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam solver preset", "docs/scenes.md");
  const OptionSpec &preset = spec(Option::solver_preset);
  PetscCall(PetscOptionsString(preset.flag, preset.help, preset.doc, preset.default_shown, buffer,
                               sizeof buffer, &given));
  PetscCall(readAutoThreshold(PetscOptionsObject, comm, displacement_order, &threshold));
  PetscOptionsEnd();
  // The solver is the user's own when -ksp_type or -pc_type is set (scene, options file,
  // command line); then auto, the default, inserts nothing. Any other -ksp_*, -pc_*, -snes_*
  // option only tunes the preset: it keeps its value (insertUnset).
  char ksp_type[64] = "", pc_type[64] = "";
  PetscBool ksp_given, pc_given;
  PetscCall(
      PetscOptionsGetString(nullptr, nullptr, "-ksp_type", ksp_type, sizeof ksp_type, &ksp_given));
  PetscCall(
      PetscOptionsGetString(nullptr, nullptr, "-pc_type", pc_type, sizeof pc_type, &pc_given));
  const std::string requested = buffer;
  PetscCheck(validName(requested), comm, PETSC_ERR_USER_INPUT,
             "-solver_preset %s: expected auto or the name of a file in %s (letters, digits, _ "
             "and -)",
             buffer, POROSEAM_SOLVER_DIR);
  const std::string name =
      chosenPreset(requested, ksp_given || pc_given, dim, (double)unknowns, (long)threshold);
  if (name.empty()) { // a solver chosen by the scene, an options file or the command line
    std::string own = ksp_given ? std::string("-ksp_type ") + ksp_type : std::string();
    if (pc_given) own += (own.empty() ? "" : ", ") + std::string("-pc_type ") + pc_type;
    *choice = "as given (" + own + ")";
    PetscCall(PetscPrintf(comm, "solver %s\n", choice->c_str()));
    PetscFunctionReturn(0);
  }
  std::string why;
  if (requested == "auto")
    why =
        std::string(given ? " (auto: " : " (auto, the default: ") + std::to_string(dim) + "D, " +
        std::to_string(unknowns) + " unknowns" +
        (name == "fieldsplit" ? " > " + std::to_string((long)threshold)
                              : "; iterative only for 3D above " + std::to_string((long)threshold) +
                                    ", -solver_auto_threshold") +
        ")";
  const std::string file = solverPresetFile(name);
  PetscCheck(!file.empty(), comm, PETSC_ERR_USER_INPUT,
             "-solver_preset %s: no preset file %s/%s.opts (the presets: %s)", name.c_str(),
             POROSEAM_SOLVER_DIR, name.c_str(), solverPresetList().c_str());
  PetscCall(insertUnset(comm, file));
  *choice = "preset " + name + why;
  PetscCall(PetscPrintf(comm, "solver %s\n", choice->c_str()));
  PetscFunctionReturn(0);
}

} // namespace poroseam
