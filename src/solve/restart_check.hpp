// What a restart keeps of the run it continues (docs/checkpoints.md, "What a restart must
// keep"). A restart continues one computation; it is refused, in one line naming the option
// and both values, when it would compute something else: another option that changes the
// physics or the discretisation, a file an option names whose content has changed (the mesh,
// a time table), output files of the run that are gone, or a final time it has reached
// already. Internal to src/solve.
#pragma once

#include "checkpoint.hpp"
#include "checkpoint_integrity.hpp"

#include <string>
#include <vector>

namespace poroseam {
namespace simulation_detail {

/// Whether an option may differ between a run and its restart: the choice and tolerances of
/// the solvers, what is written and how often, profiling, PETSc's runtime and the run's own
/// controls (checkpoints, restart, step limits). Every other option given is compared, so that
/// an option added later is compared unless declared may_change (options.def) or, for PETSc's,
/// listed in restart_check.cpp. (-ts_max_time: checkFinalTime.)
bool restartMayChange(const std::string &name);

/// The options given to this run, as the options file a checkpoint keeps (one "-name value" a
/// line; command line and options files, before poroseam adds its own), and for each option
/// compared at a restart whose value names a file, "-name <content hash>" a line. Rank 0
/// reads the files; every rank gets the same text. Collective.
PetscErrorCode givenOptions(MPI_Comm comm, std::string *options, std::string *option_files);

/// The output files of a run (names in its output directory): those a new run clears, a
/// checkpoint lists as written, and a restart needs.
const std::vector<std::string> &outputFileNames();

/// Those of outputFileNames() present in `dir`, one a line. Rank 0 looks. Collective.
PetscErrorCode presentOutputFiles(MPI_Comm comm, const std::string &dir, std::string *names);

/// The checkpoint a restart continues from (checkpoint.hpp: findCheckpoint, the latest whole
/// one), refused in one line when this run's options differ from its run's in an option that
/// is compared, or an output file it lists is missing from the output directory. Prints the
/// warnings of findCheckpoint. Collective.
PetscErrorCode chooseRestartCheckpoint(MPI_Comm comm, const RestartOptions &restart,
                                       const std::string &options, const std::string &option_files,
                                       std::string *path);

/// A restart continues to a final time after its checkpoint's (a later -ts_max_time extends
/// a run); at or before it, it is refused in one line. Collective.
PetscErrorCode checkFinalTime(MPI_Comm comm, double t_end, double t_checkpoint,
                              const std::string &path);

} // namespace simulation_detail
} // namespace poroseam
