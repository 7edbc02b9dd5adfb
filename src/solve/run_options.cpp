#include "poroseam/run_options.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/option_check.hpp"
#include "poroseam/option_registry.hpp"
#include "poroseam/scene.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <utility>
#include <vector>

namespace poroseam {
namespace {

/// Integer options read by the PETSc objects poroseam sets up, by their name without a solver
/// prefix (-fieldsplit_displacement_ksp_max_it matches ksp_max_it); poroseam's own come from
/// their declarations (options.def, checked before_run). The two vertex_blocks_ options are
/// poroseam's preconditioner's (src/solve/vertex_blocks*.cpp), read with a solver prefix like
/// PETSc's own.
const char *const kPetscIntegerOptions[] = {"ts_max_steps",
                                            "ts_max_reject",
                                            "ts_max_snes_failures",
                                            "ts_bdf_order",
                                            "snes_max_it",
                                            "snes_max_funcs",
                                            "snes_max_fail",
                                            "snes_max_linear_solve_fail",
                                            "snes_lag_jacobian",
                                            "snes_lag_preconditioner",
                                            "ksp_max_it",
                                            "ksp_gmres_restart",
                                            "pc_mg_levels",
                                            "pc_gamg_agg_nsmooths",
                                            "pc_hypre_boomeramg_max_iter",
                                            "pc_hypre_boomeramg_max_levels",
                                            "snes_linesearch_max_it",
                                            "ksp_chebyshev_esteig_steps",
                                            "pc_factor_levels",
                                            "pc_asm_overlap",
                                            "pc_hypre_boomeramg_agg_nl",
                                            "pc_hypre_boomeramg_agg_num_paths",
                                            "pc_fieldsplit_block_size",
                                            "vertex_blocks_coarse_lag",
                                            "vertex_blocks_dump_operator_setup"};
/// Real options of PETSc's objects, likewise.
const char *const kPetscRealOptions[] = {"ts_dt",
                                         "ts_max_time",
                                         "ts_rtol",
                                         "ts_atol",
                                         "ts_adapt_dt_min",
                                         "ts_adapt_dt_max",
                                         "ts_adapt_safety",
                                         "ts_adapt_reject_safety",
                                         "ts_adapt_scale_solve_failed",
                                         "ts_adapt_clip",
                                         "snes_rtol",
                                         "snes_atol",
                                         "snes_stol",
                                         "snes_divergence_tolerance",
                                         "ksp_rtol",
                                         "ksp_atol",
                                         "ksp_divtol",
                                         "pc_factor_shift_amount"};

/// Whether `option` is `base` or `<prefix>_base`.
bool matches(const std::string &option, const std::string &base)
{
  if (option == base) return true;
  return option.size() > base.size() + 1 &&
         option.compare(option.size() - base.size(), base.size(), base) == 0 &&
         option[option.size() - base.size() - 1] == '_';
}

/// Whether `option` is one of poroseam's declared options of `kind` whose value is checked
/// before the run (options.def), with or without a solver prefix.
bool declaredAs(const std::string &option, OptionKind kind)
{
  for (const auto &s : optionRegistry())
    if (s.kind == kind && s.check == OptionCheck::before_run && matches(option, s.name()))
      return true;
  return false;
}

/// Integer options: PETSc's and poroseam's.
bool isIntegerOption(const std::string &option)
{
  return declaredAs(option, OptionKind::integer) ||
         std::any_of(std::begin(kPetscIntegerOptions), std::end(kPetscIntegerOptions),
                     [&](const char *base) { return matches(option, base); });
}

/// Real options: PETSc's and poroseam's.
bool isRealOption(const std::string &option)
{
  return declaredAs(option, OptionKind::real) ||
         std::any_of(std::begin(kPetscRealOptions), std::end(kPetscRealOptions),
                     [&](const char *base) { return matches(option, base); });
}

/// MUMPS's integer controls, -mat_mumps_icntl_<n> (with any solver prefix).
bool isMumpsIcntl(const std::string &option)
{
  const std::string key = "mat_mumps_icntl_";
  const auto at = option.find(key);
  if (at == std::string::npos || (at > 0 && option[at - 1] != '_')) return false;
  const std::string n = option.substr(at + key.size());
  return !n.empty() && n.find_first_not_of("0123456789") == std::string::npos;
}

/// The range of PetscInt, as "from -2147483648 to 2147483647".
std::string intRange()
{
  return "from " + std::to_string((long long)PETSC_MIN_INT) + " to " +
         std::to_string((long long)PETSC_MAX_INT);
}

/// Whether `text`, if it is a number in decimal digits, fits a PetscInt. PETSc's parser
/// (PetscOptionsStringToInt) casts a longer number silently: -checkpoint_every 4294967297
/// became 1, 2147483648 became -2147483648.
bool fitsInt(const std::string &text)
{
  const char *begin = text.c_str();
  char *end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 10);
  if (end == begin) return true; // a name: PETSC_DECIDE, DEFAULT ...
  return errno != ERANGE && v >= (long long)PETSC_MIN_INT && v <= (long long)PETSC_MAX_INT;
}

/// PETSc's own parsers, without their error output: true when `text` parses.
bool parsesAsInt(const std::string &text, PetscInt *value)
{
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  const PetscErrorCode bad = PetscOptionsStringToInt(text.c_str(), value);
  PetscPopErrorHandler();
  return !bad;
}

bool parsesAsReal(const std::string &text, PetscReal *value)
{
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  const PetscErrorCode bad = PetscOptionsStringToReal(text.c_str(), value);
  PetscPopErrorHandler();
  return !bad && !PetscIsInfOrNanReal(*value);
}

} // namespace

std::string integerRangeError(const std::string &option, const std::string &value)
{
  const std::string name = option.substr(option.find_first_not_of('-'));
  const bool integer = isMumpsIcntl(name) || isIntegerOption(name);
  if (integer && !fitsInt(value)) return "out of range, expected an integer " + intRange();
  if (declaredAs(name, OptionKind::whole_number)) {
    char *end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (end != value.c_str() && std::isfinite(v) && std::fabs(v) > (double)PETSC_MAX_INT)
      return "out of range, expected a whole number " + intRange();
  }
  return "";
}

PetscErrorCode checkNumericOptions(MPI_Comm comm)
{
  std::vector<std::pair<std::string, std::string>> options;
  PetscFunctionBeginUser;
  PetscCall(allOptions(options));
  for (const auto &[name, value] : options) {
    PetscInt icntl = 0;
    // MUMPS reads its controls inside the first factorisation, where a value that is no
    // integer is reported by its own parser (reportError); one that overflows, it would take.
    if (isMumpsIcntl(name) && parsesAsInt(value, &icntl))
      PetscCheck(fitsInt(value), comm, PETSC_ERR_USER_INPUT,
                 "option -%s %s: out of range, expected an integer %s", name.c_str(), value.c_str(),
                 intRange().c_str());
    if (isIntegerOption(name)) {
      PetscInt v = 0;
      PetscCheck(!value.empty(), comm, PETSC_ERR_USER_INPUT,
                 "option -%s has no value: expected an integer", name.c_str());
      PetscCheck(parsesAsInt(value, &v), comm, PETSC_ERR_USER_INPUT,
                 "option -%s %s: expected an integer", name.c_str(), value.c_str());
      PetscCheck(fitsInt(value), comm, PETSC_ERR_USER_INPUT,
                 "option -%s %s: out of range, expected an integer %s", name.c_str(), value.c_str(),
                 intRange().c_str());
      if (name == "ts_max_steps")
        PetscCheck(v > 0, comm, PETSC_ERR_USER_INPUT,
                   "option -ts_max_steps %s: must be > 0 (the most steps the run may take)",
                   value.c_str());
      if (name == "ts_max_reject")
        PetscCheck(v >= 0, comm, PETSC_ERR_USER_INPUT,
                   "option -ts_max_reject %s: must be >= 0 (cuts of the time step allowed per "
                   "step; a negative number would halve the step without end)",
                   value.c_str());
      if (name == spec(Option::solver_auto_threshold).name())
        PetscCheck(v >= 0, comm, PETSC_ERR_USER_INPUT, "option %s %s: must be >= 0 (unknowns)",
                   spec(Option::solver_auto_threshold).flag, value.c_str());
    }
    if (declaredAs(name, OptionKind::whole_number)) {
      PetscReal v = 0;
      PetscCheck(!parsesAsReal(value, &v) || std::fabs(v) <= (PetscReal)PETSC_MAX_INT, comm,
                 PETSC_ERR_USER_INPUT, "option -%s %s: out of range, expected a whole number %s",
                 name.c_str(), value.c_str(), intRange().c_str());
    }
    if (isRealOption(name)) {
      PetscReal v = 0;
      PetscCheck(!value.empty(), comm, PETSC_ERR_USER_INPUT,
                 "option -%s has no value: expected a number", name.c_str());
      PetscCheck(parsesAsReal(value, &v), comm, PETSC_ERR_USER_INPUT,
                 "option -%s %s: expected a number", name.c_str(), value.c_str());
      if (name == "ts_max_time")
        PetscCheck(v > 0, comm, PETSC_ERR_USER_INPUT,
                   "option -ts_max_time %s: must be > 0 (the time [s] the run ends at)",
                   value.c_str());
      if (name == "ts_dt")
        PetscCheck(v > 0, comm, PETSC_ERR_USER_INPUT,
                   "option -ts_dt %s: must be > 0 (the time step [s])", value.c_str());
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkOutputDirectory(MPI_Comm comm)
{
  char buffer[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, spec(Option::output_dir).flag, buffer,
                                  sizeof buffer, &set));
  const std::string dir = set ? buffer : Scene().output_dir;
  PetscCheck(!dir.empty(), comm, PETSC_ERR_USER_INPUT,
             "option -output_dir has no value: name the directory for the results");
  std::string error;
  if (rank == 0) {
    // The filesystem library and plain file calls: no shell ever sees the name.
    const std::string what =
        "cannot write to the output directory '" + dir + "' (option -output_dir)";
    std::error_code failed;
    std::filesystem::create_directories(dir, failed);
    if (failed) {
      error = what + ": " + failed.message();
    } else if (!std::filesystem::is_directory(dir, failed)) {
      error = what + ": it exists and is not a directory";
    } else if (std::filesystem::exists(dir + "/checkpoints", failed) &&
               !std::filesystem::is_directory(dir + "/checkpoints", failed)) {
      // Found at the first checkpoint otherwise, many steps in, with a traceback.
      error = "'" + dir + "/checkpoints' is not a directory: poroseam keeps its checkpoints " +
              "in that folder (option -output_dir " + dir +
              "); move the file away or choose another -output_dir";
    } else {
      const std::string probe = dir + "/.poroseam-write-test-" + std::to_string(getpid());
      const int fd =
          open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
      if (fd < 0 || write(fd, "poroseam\n", 9) != 9)
        error = what + ": cannot create a file in it (" + std::strerror(errno) + ")";
      if (fd >= 0) close(fd);
      std::filesystem::remove(probe, failed);
    }
  }
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

PetscErrorCode checkTimeSteppingOptions(TS ts)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)ts);
  PetscReal max_time;
  PetscInt max_steps, max_reject = 0;
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(TSGetMaxTime(ts, &max_time));
  PetscCall(TSGetMaxSteps(ts, &max_steps));
  PetscCheck(max_time > 0, comm, PETSC_ERR_USER_INPUT,
             "-ts_max_time %g: must be > 0 (the time [s] the run ends at)", (double)max_time);
  PetscCheck(max_steps > 0, comm, PETSC_ERR_USER_INPUT,
             "-ts_max_steps %d: must be > 0 (the most steps the run may take)", (int)max_steps);
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-ts_max_reject", &max_reject, &set));
  PetscCheck(!set || max_reject >= 0, comm, PETSC_ERR_USER_INPUT,
             "-ts_max_reject %d: must be >= 0 (cuts of the time step allowed per step; a "
             "negative number would halve the step without end)",
             (int)max_reject);
  PetscFunctionReturn(0);
}

std::string optionsWithValue(const std::string &value)
{
  std::vector<std::pair<std::string, std::string>> options;
  if (allOptions(options)) return "";
  std::string names;
  for (const auto &[name, v] : options)
    if (v == value) names += (names.empty() ? "-" : " or -") + name;
  return names;
}

} // namespace poroseam
