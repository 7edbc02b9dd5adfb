#include "rolling_checkpoint.hpp"
#include "poroseam/option_registry.hpp"

#include "checkpoint.hpp"
#include "run.hpp"

#include <algorithm>
#include <filesystem>

namespace poroseam {
namespace simulation_detail {
namespace {

/// Open MPI's time between the SIGTERM it sends the ranks and its SIGKILL [s]
/// (odls_base_sigkill_timeout's default).
constexpr double kGrace = 1.0;

/// Rank 0 removes a checkpoint file this run wrote (never what a link points to: remove()
/// removes the link). A file that cannot be removed stays: one checkpoint too many.
void removeFile(MPI_Comm comm, const std::string &path)
{
  PetscMPIInt rank;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0 || path.empty()) return;
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

} // namespace

PetscErrorCode readRollingCheckpointOptions(MPI_Comm comm, RollingCheckpoint *rolling)
{
  PetscBool enabled = rolling->enabled ? PETSC_TRUE : PETSC_FALSE;
  PetscReal interval = rolling->interval;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam rolling checkpoint", "docs/checkpoints.md");
  const OptionSpec &rolling_option = spec(Option::checkpoint_rolling);
  const OptionSpec &interval_option = spec(Option::checkpoint_rolling_interval);
  PetscCall(PetscOptionsBool(rolling_option.flag, rolling_option.help, rolling_option.doc, enabled,
                             &enabled, nullptr));
  PetscCall(PetscOptionsReal(interval_option.flag, interval_option.help, interval_option.doc,
                             interval, &interval, nullptr));
  PetscOptionsEnd();
  PetscCheck(interval >= 0.0 || interval == -1.0, comm, PETSC_ERR_USER_INPUT,
             "-checkpoint_rolling_interval %g: expected a wall time >= 0 s (0: a rolling "
             "checkpoint after every step), or -1 (the default: after every step while they "
             "cost less than 10%% of the run's wall time)",
             (double)interval);
  rolling->enabled = enabled;
  rolling->interval = interval;
  PetscFunctionReturn(0);
}

PetscErrorCode updateRollingCheckpoint(Run &run, Vec X, double step_wall)
{
  RollingCheckpoint &r = run.rolling;
  PetscFunctionBeginUser;
  if (!r.enabled) PetscFunctionReturn(0);
  const double start = MPI_Wtime();
  // The same decision on every rank: rank 0's clock.
  // Automatic (-1): once 9 times the last write's cost has passed, so that they cost at most a
  // tenth of the run (on a large mesh, every step: a step takes seconds and a checkpoint a
  // fraction of it; on a tiny scene every few steps), and after any step longer than the
  // second mpiexec leaves the ranks between its SIGTERM and its SIGKILL: a stop in the next
  // step would not be reached in time.
  const double interval = r.interval >= 0.0 ? r.interval : 9.0 * r.cost;
  // And after every step once a stop may be near (a SIGCONT: mpiexec's warning, a second
  // before its SIGTERM), so that the stop finds its last step on disk and only has to say so.
  int due = r.written == 0 || start - r.last_wall >= interval ||
            (r.interval < 0.0 && (step_wall >= kGrace || StopRequest::warned()));
  PetscCallMPI(MPI_Bcast(&due, 1, MPI_INT, 0, PetscObjectComm((PetscObject)run.dm)));
  if (!due) PetscFunctionReturn(0);
  std::string path;
  PetscCall(writeCheckpoint(run, X, &path));
  const std::string previous = r.path;
  r.path = path;
  run.checkpoint_step = run.step;
  run.latest_checkpoint = path;
  if (previous != path) removeFile(PetscObjectComm((PetscObject)run.dm), previous);
  r.last_wall = MPI_Wtime();
  r.cost = r.last_wall - start;
  r.total_cost += r.cost;
  ++r.written;
  PetscFunctionReturn(0);
}

PetscErrorCode dropRollingCheckpoint(Run &run)
{
  PetscFunctionBeginUser;
  removeFile(PetscObjectComm((PetscObject)run.dm), run.rolling.path);
  run.rolling.path.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode reportRollingCheckpoints(Run &run)
{
  const RollingCheckpoint &r = run.rolling;
  PetscFunctionBeginUser;
  if (r.written == 0) PetscFunctionReturn(0);
  PetscCall(
      PetscPrintf(PetscObjectComm((PetscObject)run.dm),
                  "rolling checkpoints: %d written, %.3f s each on average (%.1f %% of the "
                  "time steps' wall time)\n",
                  r.written, r.total_cost / r.written,
                  100.0 * r.total_cost / std::max(1e-300, MPI_Wtime() - run.loop_start_wall)));
  PetscFunctionReturn(0);
}

PetscErrorCode endRollingCheckpoint(Run &run)
{
  PetscMPIInt rank;
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (run.rolling.path.empty()) PetscFunctionReturn(0);
  PetscCall(dropRollingCheckpoint(run));
  if (rank == 0) {
    // The folder too if that leaves it empty (a run without kept checkpoints leaves none).
    namespace fs = std::filesystem;
    std::error_code ignored;
    const fs::path folder = fs::path(run.scene.output_dir) / "checkpoints";
    if (!fs::is_symlink(folder, ignored) && fs::is_empty(folder, ignored))
      fs::remove(folder, ignored);
  }
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
