// Options typed that nothing reads, found before the first step or after the first linear
// solve: see unused_options.hpp.
#include "poroseam/unused_options.hpp"
#include "poroseam/option_registry.hpp"

#include "poroseam/option_check.hpp"
#include "poroseam/solver_preset.hpp"

#include <algorithm>

#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace poroseam {
namespace {

enum class Moment { set_up, first_solve };

bool startsWith(const std::string &s, const char *prefix)
{
  return s.rfind(prefix, 0) == 0;
}

bool endsWith(const std::string &s, const std::string &suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Options PETSc reads as it starts or finishes (or only when asked to debug): not a solver's.
bool runtimeOption(const std::string &name)
{
  static const char *const prefixes[] = {
      "log",
      "malloc",
      "options_",
      "info",
      "on_error",
      "no_signal_handler",
      "fp_trap",
      "debugger",
      "start_in_",
      "stop_for_",
      "history",
      "objects_dump",
      "memory_view",
      "check_pointer_intensity",
      "nox",
      "saws",
      "mpi",
      "petsc",
      "use_gpu_aware_mpi",
      "skip_petscrc",
      "viewer",
      "draw",
      "version",
      "help",
      "test_"}; // test_: poroseam's test hooks, read where they act
  for (const char *p : prefixes)
    if (startsWith(name, p)) return true;
  return false;
}

/// Read at the end of a solve or of the run: viewers (-ksp_view, -ts_view, -mat_view ...)
/// and -ksp_converged_reason, -snes_converged_reason.
bool readLate(const std::string &name)
{
  return name.find("view") != std::string::npos || endsWith(name, "converged_reason");
}

/// Read by TSSetFromOptions, TSSetUp and SNESSetUp: the top-level solvers' own options.
bool readAtSetUp(const std::string &name)
{
  for (const char *p : {"ts_", "snes_", "ksp_", "pc_"})
    if (startsWith(name, p)) return true;
  return false;
}

/// PETSc's help printers take no context: while listOptionNames runs, they append here.
std::string *help_sink = nullptr;

PetscErrorCode captureHelp(MPI_Comm, const char format[], ...)
{
  char line[4096];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  if (help_sink) *help_sink += line;
  return 0;
}

PetscErrorCode captureVFPrintf(FILE *, const char format[], va_list args)
{
  char line[4096];
  std::vsnprintf(line, sizeof line, format, args);
  if (help_sink) *help_sink += line;
  return 0;
}

/// Sets the sub-solvers of `ksp`'s split preconditioner from the options (-help is on, so
/// they list what they read).
void listSubSolvers(KSP ksp)
{
  PC pc;
  PetscBool split = PETSC_FALSE;
  if (KSPGetPC(ksp, &pc) || PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &split) || !split)
    return;
  PetscInt n = 0;
  KSP *subs = nullptr;
  if (PCFieldSplitGetSubKSP(pc, &n, &subs)) return;
  for (PetscInt i = 0; i < n; ++i) {
    KSPSetFromOptions(subs[i]);
    listSubSolvers(subs[i]);
  }
  PetscFree(subs);
}

/// The option names the run's solvers read in their present configuration, as PETSc's -help
/// lists them: the solvers are set from the options once more with -help on and its output
/// captured. Only on the way to an error (it resets what poroseam configured after
/// TSSetFromOptions, such as its line search); errors inside are ignored.
std::vector<std::string> listOptionNames(TS ts, bool sub_solvers)
{
  std::string text;
  auto help_printf = PetscHelpPrintf;
  auto vfprintf = PetscVFPrintf;
  help_sink = &text;
  PetscHelpPrintf = captureHelp;
  PetscVFPrintf = captureVFPrintf;
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  if (!PetscOptionsSetValue(nullptr, "-help", nullptr)) {
    TSSetFromOptions(ts);
    SNES snes;
    KSP ksp;
    if (sub_solvers && !TSGetSNES(ts, &snes) && !SNESGetKSP(snes, &ksp)) listSubSolvers(ksp);
    PetscOptionsClearValue(nullptr, "-help");
  }
  PetscPopErrorHandler();
  PetscHelpPrintf = help_printf;
  PetscVFPrintf = vfprintf;
  help_sink = nullptr;
  // "  -ts_dt <0.1 : 0.1>: Initial time step (TSSetTimeStep)": a line's first word.
  std::vector<std::string> names;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const auto at = line.find_first_not_of(' ');
    if (at == std::string::npos || line[at] != '-' || at + 1 >= line.size() ||
        !std::isalpha((unsigned char)line[at + 1]))
      continue;
    const auto end = line.find_first_of(" <:", at);
    names.push_back(line.substr(at + 1, end == std::string::npos ? end : end - at - 1));
  }
  return names;
}

PetscErrorCode checkUnused(MPI_Comm comm, UnusedOptionCheck &check, Moment moment)
{
  std::vector<int> unused(check.typed.size(), 0);
  // Options of the solver presets are PETSc's, spelt right: a scene file's direct-solver
  // options (-pc_factor_mat_solver_type) with the iterative preset after it are unused, not
  // misspelt (reported at the end of the run).
  const std::vector<std::string> preset_names = solverPresetOptionNames();
  PetscFunctionBeginUser;
  for (std::size_t i = 0; i < check.typed.size(); ++i) {
    const std::string &name = check.typed[i];
    // -options_unsued_ok: the opt-out misspelt, among PETSc's runtime names; read at set-up.
    const bool opt_out = !closestName(name, {"options_unused_ok"}).empty();
    if (isSceneOption(name) || (runtimeOption(name) && !opt_out) || readLate(name)) continue;
    if (std::find(preset_names.begin(), preset_names.end(), name) != preset_names.end()) continue;
    if (moment == Moment::set_up && !readAtSetUp(name) && !opt_out) continue;
    PetscBool used = PETSC_FALSE;
    PetscCall(PetscOptionsUsed(nullptr, name.c_str(), &used));
    unused[i] = !used;
  }
  // Unused only when no rank read it: every rank then reaches the same verdict.
  if (!unused.empty())
    PetscCallMPI(
        MPI_Allreduce(MPI_IN_PLACE, unused.data(), (int)unused.size(), MPI_INT, MPI_LAND, comm));
  std::vector<std::string> found;
  for (std::size_t i = 0; i < unused.size(); ++i)
    if (unused[i] && !check.warned.count(check.typed[i])) {
      bool twice = false;
      for (const auto &f : found)
        twice = twice || f == check.typed[i];
      if (!twice) found.push_back(check.typed[i]);
    }
  if (found.empty()) PetscFunctionReturn(0);
  // What could have been meant: poroseam's names, the options read, and (on the way to an
  // error only) every option the run's solvers read in this configuration.
  std::vector<std::string> candidates = sceneOptionNames();
  {
    std::vector<std::pair<std::string, std::string>> all;
    PetscCall(allOptions(all));
    for (const auto &o : all) {
      PetscBool used = PETSC_FALSE;
      PetscCall(PetscOptionsUsed(nullptr, o.first.c_str(), &used));
      if (used) candidates.push_back(o.first);
    }
  }
  if (!check.warn_only) {
    const auto listed = listOptionNames(check.ts, moment == Moment::first_solve);
    candidates.insert(candidates.end(), listed.begin(), listed.end());
  }
  const char *when = moment == Moment::set_up
                         ? "before the first step"
                         : "after the first linear solve (solver splits and factorisations "
                           "read their options there)";
  for (std::size_t i = 0; i < found.size(); ++i) {
    const std::string meant = closestName(found[i], candidates);
    const std::string line = "option -" + found[i] + ": no such option in this run" +
                             (meant.empty() ? "" : " (did you mean -" + meant + "?)");
    if (check.warn_only) {
      check.warned.insert(found[i]);
      PetscCall(PetscPrintf(comm, "poroseam: warning: %s; running on (-options_unused_ok)\n",
                            line.c_str()));
    } else if (i + 1 < found.size()) {
      PetscCall(PetscFPrintf(comm, PETSC_STDERR, "poroseam: error: %s\n", line.c_str()));
    } else {
      SETERRQ(comm, PETSC_ERR_USER_INPUT,
              "%s; stopped %s: correct or remove %s, or give -options_unused_ok to run on with "
              "a warning",
              line.c_str(), when, found.size() > 1 ? "these options" : "it");
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode afterSolve(KSP, Vec, Vec, void *ctx)
{
  auto &check = *static_cast<UnusedOptionCheck *>(ctx);
  PetscFunctionBeginUser;
  if (check.first_solve_checked) PetscFunctionReturn(0);
  check.first_solve_checked = true;
  PetscCall(checkUnused(PetscObjectComm((PetscObject)check.ts), check, Moment::first_solve));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readUnusedOptionsOk(MPI_Comm comm, UnusedOptionCheck *check)
{
  PetscBool ok = check->warn_only ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam option check", "docs/input_errors.md");
  const OptionSpec &option = spec(Option::options_unused_ok);
  PetscCall(PetscOptionsBool(option.flag, option.help, option.doc, ok, &ok, nullptr));
  PetscOptionsEnd();
  check->warn_only = ok;
  PetscFunctionReturn(0);
}

PetscErrorCode reportUnusedOptions(MPI_Comm comm)
{
  PetscInt n;
  char **names, **values;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    // PETSc reads -options_left in PetscFinalize, after this report: it is used, just later.
    if (std::string(names[i]) == "options_left") continue;
    PetscCall(PetscPrintf(comm, "poroseam: warning: option -%s%s%s was given but never used\n",
                          names[i], values[i] ? " " : "", values[i] ? values[i] : ""));
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscFunctionReturn(0);
}

PetscErrorCode checkUnusedOptionsAfterSetUp(MPI_Comm comm, UnusedOptionCheck *check)
{
  SNES snes;
  KSP ksp;
  PetscFunctionBeginUser;
  PetscCall(checkUnused(comm, *check, Moment::set_up));
  PetscCall(TSGetSNES(check->ts, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetPostSolve(ksp, afterSolve, check));
  PetscFunctionReturn(0);
}

} // namespace poroseam
