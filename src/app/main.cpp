// poroseam: hydro-mechanical finite elements for saturated soils, on PETSc.
//   mpiexec -n 2 poroseam -options_file options/<scene>.opts [PETSc options]
#include "poroseam/given_options.hpp"
#include "poroseam/help_filter.hpp"
#include "poroseam/option_registry.hpp"
#include "poroseam/options_file.hpp"
#include "poroseam/output_directory.hpp"
#include "poroseam/run_options.hpp"
#include "poroseam/scene.hpp"
#include "poroseam/simulation.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <petscsys.h>
#include <string>
#include <vector>

static const char help[] = "poroseam: Biot consolidation with zero-thickness hydro-mechanical "
                           "interfaces.\nUsage: poroseam -options_file options/<scene>.opts\n";

namespace {

/// Set when an error that every rank meets together (a bad option value found by PETSc's
/// parser) has been reported in one line: the run then ends cleanly, not with MPI_Abort.
bool collective_input_error = false;

int worldRank()
{
  int initialized = 0, rank = 0;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

/// PETSc's parse errors of an option value name the value only ("Input string abc has no
/// integer value"): find the option that has it. Returns "" for other errors.
std::string optionParseError(const char *mess)
{
  if (!mess) return "";
  const std::string m = mess;
  std::string value, expected;
  const std::string input = "Input string ";
  if (m.rfind(input, 0) == 0) {
    const auto end = m.find(" has no ", input.size());
    if (end == std::string::npos) return "";
    value = m.substr(input.size(), end - input.size());
    expected = m.find("integer", end) != std::string::npos ? "an integer" : "a number";
  } else if (m.rfind("Unknown logical value: ", 0) == 0) {
    value = m.substr(std::strlen("Unknown logical value: "));
    expected = "true or false";
  } else if (m.find("string of length zero has no numerical value") != std::string::npos) {
    return "an option that needs a number was given without one";
  } else {
    return "";
  }
  while (!value.empty() && value.back() == ' ')
    value.pop_back();
  const std::string names = poroseam::optionsWithValue(value);
  return (names.empty() ? "an option" : "option " + names) + " " + value + ": expected " + expected;
}

/// Bad input and a run that cannot go on are the user's to fix, not ours to debug: say what
/// is wrong in one line, without PETSc's traceback. Everything else keeps the traceback.
PetscErrorCode reportError(MPI_Comm comm, int line, const char *func, const char *file,
                           PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  if (p == PETSC_ERROR_INITIAL) {
    const std::string parse = optionParseError(mess);
    if (!parse.empty()) {
      // Options are the same on every rank and read in collective set-up calls: every rank
      // meets this error at the same point. One line, from rank 0.
      collective_input_error = true;
      if (worldRank() == 0) std::fprintf(stderr, "poroseam: error: %s\n", parse.c_str());
      return n;
    }
  } else if (collective_input_error) {
    return n; // the same error on its way up
  }
  if (n != PETSC_ERR_USER_INPUT && n != PETSC_ERR_NOT_CONVERGED)
    return PetscTraceBackErrorHandler(comm, line, func, file, n, p, mess, ctx);
  if (p == PETSC_ERROR_INITIAL) {
    int rank = 0;
    if (comm != MPI_COMM_NULL && comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
    if (rank == 0) std::fprintf(stderr, "poroseam: error: %s\n", mess);
  }
  return n;
}

/// The command line PETSc is to see, the same on every rank: rank 0 reads the options files
/// (options_file.hpp) and checks every option as given (given_options.hpp), as PETSc reads
/// options files on rank 0 and broadcasts them. `typed`: the names (without '-') of the
/// options the user typed, not those of a solver preset's file (unused_options.hpp). Returns
/// "" or the one-line error.
std::string readCommandLine(int argc, char **argv, std::vector<std::string> *args,
                            std::vector<std::string> *typed)
{
  std::string error, packed, typed_names;
  if (worldRank() == 0) {
    poroseam::ExpandedCommandLine expanded;
    error = poroseam::expandOptionsFiles(argc, argv, std::getenv("PETSC_OPTIONS"), &expanded);
    if (error.empty()) error = poroseam::checkGivenOptions(expanded.options);
    // Arguments are C strings: a NUL separates them.
    for (const auto &a : expanded.args)
      packed += a + '\0';
    for (const auto &o : expanded.options)
      if (!o.preset) typed_names += o.name.substr(o.name.find_first_not_of('-')) + '\0';
  }
  for (std::string *text : {&error, &packed, &typed_names}) {
    unsigned long size = text->size();
    MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG, 0, MPI_COMM_WORLD);
    text->resize(size);
    if (size) MPI_Bcast(text->data(), (int)size, MPI_CHAR, 0, MPI_COMM_WORLD);
  }
  // Read above, in place, with the command line: PETSc must not read it (and its files) again.
  unsetenv("PETSC_OPTIONS");
  args->clear();
  for (std::size_t start = 0; start < packed.size();) {
    const std::size_t end = packed.find('\0', start);
    args->push_back(packed.substr(start, end - start));
    start = end + 1;
  }
  typed->clear();
  for (std::size_t start = 0; start < typed_names.size();) {
    const std::size_t end = typed_names.find('\0', start);
    typed->push_back(typed_names.substr(start, end - start));
    start = end + 1;
  }
  return error;
}

/// After an error inside a log phase (a stage pushed, events begun), or any bad input: leave
/// the stages, and do not print -log_view's tables, whose nested formats would stop with a
/// follow-up error about unbalanced events ("Entry 7 is larger than number of parents";
/// "Depth 2 > maxdepth+1" after an input error found before the first stage) that hides the
/// real one. Returns whether a stage was still open.
bool leaveLogPhases(bool input_error)
{
  PetscStageLog log = nullptr;
  int stage = -1;
  bool open = false;
  if (PetscLogGetStageLog(&log) || !log) return false;
  while (!PetscStageLogGetCurrent(log, &stage) && stage > 0) {
    if (PetscLogStagePop()) break;
    open = true;
  }
  if (open || input_error) {
    for (const char *name : {"-log_view", "-log_view_memory", "-log_view_gpu_time", "-log_all",
                             "-log_trace", "-log_summary"})
      PetscOptionsClearValue(nullptr, name);
  }
  return open;
}

/// PetscHelpPrintf on ranks other than 0: prints nothing.
/// PetscVFPrintf on ranks other than 0 during -help: prints nothing. PETSc prints some option
/// help through it on PETSC_COMM_SELF (PetscFECreateLagrange's matrices list
/// -mat_seqaij_type from every rank), which PetscHelpPrintf alone does not catch.
PetscErrorCode silentVFPrintf(FILE *, const char[], va_list)
{
  return 0;
}

PetscErrorCode silentHelpPrintf(MPI_Comm, const char[], ...)
{
  return 0;
}

} // namespace

int main(int argc, char **argv)
{
  // MPI first, so that a bad -options_file is reported once, by rank 0, and every rank
  // finishes MPI cleanly (PETSc then leaves MPI_Finalize to us).
  // Open MPI 4.1's shared-file-pointer component "lockedfile" overflows a fixed buffer (glibc
  // aborts: "buffer overflow detected") when HDF5 opens a file whose path is longer than about
  // 200 characters, e.g. fields.h5 under a deep -output_dir. HDF5 never uses shared file
  // pointers; leave that component out unless the user chose the components themselves.
  setenv("OMPI_MCA_sharedfp", "^lockedfile", 0);
  MPI_Init(&argc, &argv);
  std::vector<std::string> args; // PETSc keeps pointers into these until PetscFinalize
  std::vector<std::string> typed;
  const std::string options_error = readCommandLine(argc, argv, &args, &typed);
  if (!options_error.empty()) {
    if (worldRank() == 0) std::fprintf(stderr, "poroseam: error: %s\n", options_error.c_str());
    MPI_Finalize();
    return 1;
  }
  std::vector<char *> petsc_argv;
  for (auto &a : args)
    petsc_argv.push_back(a.data());
  petsc_argv.push_back(nullptr);
  int petsc_argc = (int)args.size();
  char **petsc_args = petsc_argv.data();
  // Rank 0 lists the options without what PETSc's internal objects read (help_filter.hpp),
  // from PetscInitialize's own sections on.
  for (const auto &a : args)
    if ((a == "-help" || a == "-h") && worldRank() == 0) poroseam::installHelpFilter();
  PetscCall(PetscInitialize(&petsc_argc, &petsc_args, nullptr, help));
  PetscCall(PetscPushErrorHandler(reportError, nullptr));
  PetscBool help_requested = PETSC_FALSE, has_mesh = PETSC_FALSE;
  PetscCall(PetscOptionsHasHelp(nullptr, &help_requested));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, poroseam::spec(poroseam::Option::mesh).flag,
                                &has_mesh));
  // Objects on PETSC_COMM_SELF (index sets of the field split, for one) print their options'
  // help from every rank; rank 1's lines then landed in the middle of rank 0's listing, which
  // Open MPI forwards in chunks, and cut some of its lines in two. Rank 0 speaks for all.
  if (help_requested && worldRank() != 0) {
    PetscHelpPrintf = silentHelpPrintf;
    PetscVFPrintf = silentVFPrintf;
  }

  // -help alone prints docs/scenes.md; with a scene, the run is set up (nothing written, no
  // step taken) and PETSc lists every option, poroseam's and its own, with its value.
  if (help_requested && !has_mesh) poroseam::printSceneHelp(PETSC_COMM_WORLD);
  PetscErrorCode error = 0;
  poroseam::OutputDirectoryLock lock; // held until the process ends
  if (!help_requested || has_mesh) {
    error = poroseam::checkNumericOptions(PETSC_COMM_WORLD);
    if (!error && !help_requested) error = poroseam::checkOutputDirectory(PETSC_COMM_WORLD);
    if (!error && !help_requested) error = lock.acquire(PETSC_COMM_WORLD);
    if (!error) error = poroseam::runSimulation(PETSC_COMM_WORLD, typed);
  }
  const bool collective =
      error == PETSC_ERR_USER_INPUT || error == PETSC_ERR_NOT_CONVERGED || collective_input_error;
  if (error && !collective) {
    // An internal error may be on one rank only: the others cannot be waited for.
    MPI_Abort(PETSC_COMM_WORLD, (int)error);
  }
  // Input errors and failed runs are detected on every rank together: finish cleanly.
  if (error) leaveLogPhases(error == PETSC_ERR_USER_INPUT || collective_input_error);
  PetscCall(PetscPopErrorHandler()); // what main pushed (-malloc_dump: nothing left)
  PetscCall(PetscFinalize());
  MPI_Finalize();
  return error ? 1 : 0;
}
