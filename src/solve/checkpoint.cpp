#include "checkpoint.hpp"
#include "poroseam/option_registry.hpp"

#include "poroseam/disk_space.hpp"

#include "restart_check.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <petscviewerhdf5.h>
#include <regex>
#include <utility>
#include <vector>

namespace poroseam {
namespace simulation_detail {
namespace {

std::string checkpointDir(const std::string &output_dir)
{
  return output_dir + "/checkpoints";
}

std::string checkpointName(int step)
{
  char name[32];
  std::snprintf(name, sizeof(name), "step-%06d.h5", step);
  return name;
}

/// What ties the checkpoint to a partition: per rank, the owned unknowns, the history values
/// (interfaces and skeleton) and the 1-norm of the rank's local vertex coordinates (which
/// vertices it holds).
PetscErrorCode layoutOf(Run &run, Vec X, double layout[3])
{
  PetscInt n;
  Vec coordinates;
  PetscReal norm;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(DMGetCoordinatesLocal(run.dm, &coordinates));
  PetscCall(VecNorm(coordinates, NORM_1, &norm));
  layout[0] = (double)n;
  layout[1] =
      (double)(run.problem.interfaces().historyValues() + run.problem.skeletonHistoryValues());
  layout[2] = norm;
  PetscFunctionReturn(0);
}

/// A plain MPI vector of `local` entries (not the DM's: DMPlex's VecView/VecLoad would move
/// the data into its own groups and orderings).
PetscErrorCode plainVec(MPI_Comm comm, PetscInt local, const char *name, Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(comm, local, PETSC_DETERMINE, v));
  PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscFunctionReturn(0);
}

PetscErrorCode writeValues(PetscViewer viewer, MPI_Comm comm, const char *name,
                           const double *values, PetscInt n)
{
  Vec v;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(plainVec(comm, n, name, &v));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt i = 0; i < n; ++i)
    a[i] = values[i];
  PetscCall(VecRestoreArray(v, &a));
  PetscCall(VecView(v, viewer));
  PetscCall(VecDestroy(&v));
  std::string sum;
  PetscCall(valuesChecksum(comm, values, n, &sum));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, name, "checksum", PETSC_STRING, sum.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode writeVec(PetscViewer viewer, const char *name, Vec x)
{
  const PetscScalar *a;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(writeValues(viewer, PetscObjectComm((PetscObject)x), name, a, n));
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode readValues(PetscViewer viewer, MPI_Comm comm, const char *name, PetscInt n,
                          std::vector<double> &values)
{
  Vec v;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(plainVec(comm, n, name, &v));
  PetscCall(VecLoad(v, viewer));
  PetscCall(VecGetArrayRead(v, &a));
  values.assign(a, a + n);
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscCall(VecDestroy(&v));
  // findCheckpoint verified the file; this catches one changed since.
  std::string sum;
  char *stored = nullptr;
  PetscCall(valuesChecksum(comm, values.data(), n, &sum));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, name, "checksum", PETSC_STRING, nullptr, &stored));
  const bool same = sum == stored;
  PetscCall(PetscFree(stored));
  PetscCheck(same, comm, PETSC_ERR_USER_INPUT,
             "checkpoint dataset '%s' no longer matches its checksum: the file changed while the "
             "restart read it",
             name);
  PetscFunctionReturn(0);
}

PetscErrorCode readVec(PetscViewer viewer, const char *name, Vec x)
{
  PetscInt n;
  std::vector<double> values;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(readValues(viewer, PetscObjectComm((PetscObject)x), name, n, values));
  PetscCall(VecGetArray(x, &a));
  std::copy(values.begin(), values.end(), a);
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode writeCheckpoint(Run &run, Vec X, std::string *path)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const std::string dir = checkpointDir(run.scene.output_dir);
  {
    std::error_code failed;
    if (rank == 0) std::filesystem::create_directories(dir, failed);
    int ok = !failed;
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
    PetscCheck(ok, comm, PETSC_ERR_FILE_OPEN, "cannot create the checkpoint directory %s",
               dir.c_str());
  }
  *path = dir + "/" + checkpointName(run.step);
  const std::string partial = *path + ".partial";
  double layout[3];
  PetscCall(layoutOf(run, X, layout));
  const std::vector<double> history = run.problem.interfaces().committedHistory();
  const std::vector<double> times = run.fields.times();
  const std::vector<double> interface_times = run.interface_fields.times();
  std::vector<double> steady, steady_conditions;
  PetscCall(run.steady.kept(steady, steady_conditions));
  PetscInt has_steady = steady.empty() ? 0 : 1, all_steady = 0;
  PetscCallMPI(MPI_Allreduce(&has_steady, &all_steady, 1, MPIU_INT, MPI_MIN, comm));
  { // a full disk ends the run here, on every rank, before a partial checkpoint
    PetscInt n;
    PetscCall(VecGetLocalSize(X, &n));
    const double values =
        2.0 * n + history.size() + run.problem.skeletonHistoryValues() + 3 + steady.size();
    const double listed = rank == 0 ? times.size() + interface_times.size() : 0;
    PetscCall(reserveSpace(comm, dir, *path, 8.0 * (values + listed),
                           "the checkpoint of step " + std::to_string(run.step)));
  }

  PetscViewer viewer;
  PetscCall(PetscViewerHDF5Open(comm, partial.c_str(), FILE_MODE_WRITE, &viewer));
  PetscCall(writeValues(viewer, comm, "layout", layout, 3));
  PetscCall(writeVec(viewer, "solution", X));
  PetscCall(writeVec(viewer, "last_increment", run.last_increment));
  PetscCall(
      writeValues(viewer, comm, "interface_history", history.data(), (PetscInt)history.size()));
  if (run.problem.hasSkeletonHistory()) { // scenes without plastic regions write none
    const std::vector<double> skeleton = run.problem.committedSkeletonHistory();
    PetscCall(
        writeValues(viewer, comm, "skeleton_history", skeleton.data(), (PetscInt)skeleton.size()));
  }
  PetscCall(writeValues(viewer, comm, "output_times", times.data(),
                        rank == 0 ? (PetscInt)times.size() : 0));
  if (all_steady) { // the steady pore pressure kept (steady_pressure.hpp), for an exact restart
    PetscCall(writeValues(viewer, comm, "steady_pressure", steady.data(), (PetscInt)steady.size()));
    PetscCall(writeValues(viewer, comm, "steady_conditions", steady_conditions.data(),
                          rank == 0 ? (PetscInt)steady_conditions.size() : 0));
  }
  CheckpointHeader header;
  PetscCall(writeValues(viewer, comm, "interface_output_times", interface_times.data(),
                        rank == 0 ? (PetscInt)interface_times.size() : 0));
  header.ranks = size, header.step = run.step, header.output_count = (PetscInt)times.size();
  header.interface_output_count = (PetscInt)interface_times.size();
  PetscCall(TSGetTime(run.ts, &header.time));
  PetscCall(TSGetTimeStep(run.ts, &header.next_dt));
  header.last_dt = run.last_dt, header.first_contraction = run.first_contraction;
  header.integrator = run.time.name();
  // What a restart must keep (restart_check.hpp): the run's options, the content of the files
  // they name, and the output files it continues.
  header.options = run.given_options, header.option_files = run.given_option_files;
  PetscCall(presentOutputFiles(comm, run.scene.output_dir, &header.output_files));
  PetscCall(writeHeader(viewer, header));
  PetscCall(PetscViewerDestroy(&viewer)); // collective: the file is complete on every rank
  int ok = 1;
  if (rank == 0) {
    std::error_code failed;
    std::filesystem::rename(partial, *path, failed);
    ok = !failed;
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCheck(ok, comm, PETSC_ERR_FILE_WRITE, "cannot rename %s to %s", partial.c_str(),
             path->c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode findCheckpoint(MPI_Comm comm, const std::string &dir, int step, std::string *path)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::string where = checkpointDir(dir);
  std::vector<int> steps; // newest first (a .partial file is a checkpoint never completed)
  if (rank == 0) {
    std::error_code failed;
    const std::regex pattern("step-([0-9]{6})\\.h5");
    for (const auto &entry : std::filesystem::directory_iterator(where, failed)) {
      std::smatch m;
      const std::string name = entry.path().filename().string();
      if (!std::regex_match(name, m, pattern)) continue;
      const int k = std::stoi(m[1].str());
      if (step < 0 || k == step) steps.push_back(k);
    }
    std::sort(steps.rbegin(), steps.rend());
  }
  int count = (int)steps.size();
  PetscCallMPI(MPI_Bcast(&count, 1, MPI_INT, 0, comm));
  steps.resize(count);
  if (count) PetscCallMPI(MPI_Bcast(steps.data(), count, MPI_INT, 0, comm));
  if (step < 0)
    PetscCheck(count > 0, comm, PETSC_ERR_USER_INPUT,
               "-restart %s: no checkpoint in %s (a run writes them with -checkpoint_every N, "
               "and when it stops early)",
               dir.c_str(), where.c_str());
  else
    PetscCheck(count > 0, comm, PETSC_ERR_USER_INPUT,
               "-restart_step %d: %s has no checkpoint of step %d", step, where.c_str(), step);
  // The newest whole one. A damaged checkpoint (a disk error, a copy cut short) would
  // continue another computation, or stop HDF5 with a traceback.
  std::string skipped;                                      // "step-000020.h5 (why), ..."
  std::vector<std::pair<std::string, std::string>> damaged; // warned about once one is whole
  for (int k : steps) {
    const std::string candidate = where + "/" + checkpointName(k);
    std::string damage;
    int regular = 0; // HDF5 would wait forever on a FIFO of that name
    if (rank == 0) {
      std::error_code failed;
      regular = std::filesystem::is_regular_file(candidate, failed);
    }
    PetscCallMPI(MPI_Bcast(&regular, 1, MPI_INT, 0, comm));
    if (regular)
      PetscCall(verifyCheckpoint(comm, candidate, &damage));
    else
      damage = "not a regular file";
    if (damage.empty()) {
      for (const auto &[name, why] : damaged)
        PetscCall(PetscPrintf(comm,
                              "poroseam: warning: checkpoint %s is damaged (%s): restarting from "
                              "%s instead\n",
                              name.c_str(), why.c_str(), checkpointName(k).c_str()));
      *path = candidate;
      PetscFunctionReturn(0);
    }
    PetscCheck(step < 0, comm, PETSC_ERR_USER_INPUT,
               "-restart_step %d: checkpoint %s is damaged (%s): choose another step, or leave "
               "out -restart_step for the latest whole checkpoint",
               step, candidate.c_str(), damage.c_str());
    damaged.emplace_back(candidate, damage);
    skipped += (skipped.empty() ? "" : ", ") + checkpointName(k) + " (" + damage + ")";
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT,
          "-restart %s: no whole checkpoint in %s, all %d are damaged: %s; start the run anew "
          "(without -restart)",
          dir.c_str(), where.c_str(), count, skipped.c_str());
}

PetscErrorCode readCheckpointHeader(MPI_Comm comm, const std::string &path,
                                    CheckpointHeader *header)
{
  PetscMPIInt size;
  PetscViewer viewer;
  bool intact = false;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscViewerHDF5Open(comm, path.c_str(), FILE_MODE_READ, &viewer));
  PetscCall(readHeader(viewer, header, &intact));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCheck(header->version == kCheckpointVersion, comm, PETSC_ERR_USER_INPUT,
             "checkpoint %s: format version %d, this poroseam reads version %d", path.c_str(),
             (int)header->version, (int)kCheckpointVersion);
  PetscCheck(intact, comm, PETSC_ERR_USER_INPUT,
             "checkpoint %s: its attributes do not match their checksum (the file changed while "
             "the restart read it)",
             path.c_str());
  PetscCheck(header->ranks == size, comm, PETSC_ERR_USER_INPUT,
             "checkpoint %s was written by %d MPI ranks: restart it on %d (mpiexec -n %d); a "
             "checkpoint holds each rank's part of the mesh as it was partitioned",
             path.c_str(), (int)header->ranks, (int)size, (int)header->ranks);
  PetscFunctionReturn(0);
}

PetscErrorCode readCheckpoint(Run &run, const std::string &path, Vec X, CheckpointInfo *info)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  CheckpointHeader header;
  PetscCall(readCheckpointHeader(comm, path, &header));
  PetscCheck(header.integrator == run.time.name(), comm, PETSC_ERR_USER_INPUT,
             "checkpoint %s was written with %s; this run integrates with %s (-ts_type)",
             path.c_str(), header.integrator.c_str(), run.time.name());
  PetscViewer viewer;
  PetscCall(PetscViewerHDF5Open(comm, path.c_str(), FILE_MODE_READ, &viewer));
  {
    double mine[3], theirs_local[3];
    std::vector<double> theirs;
    PetscCall(layoutOf(run, X, mine));
    PetscCall(readValues(viewer, comm, "layout", 3, theirs));
    std::copy(theirs.begin(), theirs.end(), theirs_local);
    int same = mine[0] == theirs_local[0] && mine[1] == theirs_local[1] &&
               std::abs(mine[2] - theirs_local[2]) <= 1e-12 * std::max(1.0, std::abs(mine[2]));
    int all = 0;
    PetscCallMPI(MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, comm));
    PetscCheck(all, comm, PETSC_ERR_USER_INPUT,
               "checkpoint %s belongs to another mesh or partition (on this rank %.0f unknowns "
               "and %.0f history values, the checkpoint has %.0f and %.0f): restart "
               "with the scene, -mesh_size_factor and number of ranks of the run that wrote it",
               path.c_str(), mine[0], mine[1], theirs_local[0], theirs_local[1]);
  }
  PetscCall(readVec(viewer, "solution", X));
  PetscCall(readVec(viewer, "last_increment", run.last_increment));
  {
    std::vector<double> history;
    PetscCall(readValues(viewer, comm, "interface_history",
                         (PetscInt)run.problem.interfaces().historyValues(), history));
    PetscCall(run.problem.restoreHistory(history));
  }
  if (run.problem.hasSkeletonHistory()) {
    PetscBool has = PETSC_FALSE;
    PetscCall(PetscViewerHDF5HasDataset(viewer, "skeleton_history", &has));
    PetscCheck(has, comm, PETSC_ERR_USER_INPUT,
               "checkpoint %s has no skeleton history, but this scene has regions whose law "
               "keeps one (e.g. mohr_coulomb): restart with the scene of the run that wrote it",
               path.c_str());
    std::vector<double> skeleton;
    PetscCall(readValues(viewer, comm, "skeleton_history",
                         (PetscInt)run.problem.skeletonHistoryValues(), skeleton));
    PetscCall(run.problem.restoreSkeletonHistory(skeleton));
  }
  {
    std::vector<double> times;
    const PetscInt output_count = header.output_count;
    PetscCall(readValues(viewer, comm, "output_times", rank == 0 ? output_count : 0, times));
    times.resize(output_count);
    PetscCallMPI(MPI_Bcast(times.data(), (int)output_count, MPI_DOUBLE, 0, comm));
    info->output_times = times;
    // Checkpoints written before -output_interfaces_every have no interface times: the
    // interfaces were written with the fields then.
    const PetscInt interface_count = header.interface_output_count;
    if (interface_count < 0) {
      info->interface_output_times = times;
    } else {
      std::vector<double> interface_times;
      PetscCall(readValues(viewer, comm, "interface_output_times", rank == 0 ? interface_count : 0,
                           interface_times));
      interface_times.resize(interface_count);
      PetscCallMPI(MPI_Bcast(interface_times.data(), (int)interface_count, MPI_DOUBLE, 0, comm));
      info->interface_output_times = interface_times;
    }
  }
  {
    PetscBool has = PETSC_FALSE;
    PetscCall(PetscViewerHDF5HasDataset(viewer, "steady_pressure", &has));
    if (has) { // checkpoints before the steady pressure have none: it is solved anew then
      PetscInt n, count = 0;
      Vec probe;
      std::vector<double> values, conditions;
      PetscCall(DMGetLocalVector(run.dm, &probe));
      PetscCall(VecGetLocalSize(probe, &n));
      PetscCall(DMRestoreLocalVector(run.dm, &probe));
      PetscCall(readValues(viewer, comm, "steady_pressure", n, values));
      // The conditions' count: every rank knows it from the dataset's size.
      PetscCall(PetscViewerHDF5PushGroup(viewer, "/"));
      {
        Vec all;
        PetscCall(VecCreate(comm, &all));
        PetscCall(PetscObjectSetName((PetscObject)all, "steady_conditions"));
        PetscCall(VecLoad(all, viewer));
        PetscCall(VecGetSize(all, &count));
        PetscCall(VecDestroy(&all));
      }
      PetscCall(PetscViewerHDF5PopGroup(viewer));
      PetscCall(readValues(viewer, comm, "steady_conditions", rank == 0 ? count : 0, conditions));
      conditions.resize(count);
      PetscCallMPI(MPI_Bcast(conditions.data(), (int)count, MPI_DOUBLE, 0, comm));
      PetscCall(run.steady.restore(values, conditions));
    }
  }
  PetscCall(PetscViewerDestroy(&viewer));
  info->step = (int)header.step;
  info->time = header.time;
  info->next_dt = header.next_dt;
  run.last_dt = header.last_dt;
  run.first_contraction = header.first_contraction;
  // The last accepted local state, with the prescribed values of its time.
  PetscCall(DMGlobalToLocal(run.dm, X, INSERT_VALUES, run.previous));
  PetscCall(run.problem.insertBoundaryValues(info->time, run.previous));
  PetscFunctionReturn(0);
}

PetscErrorCode readCheckpointOptions(MPI_Comm comm, Run &run, RestartOptions *restart)
{
  char dir[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE, step_set = PETSC_FALSE;
  PetscInt every = 0, step = -1;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam checkpoints and restarts", "docs/checkpoints.md");
  const OptionSpec &every_option = spec(Option::checkpoint_every);
  const OptionSpec &restart_option = spec(Option::restart);
  const OptionSpec &step_option = spec(Option::restart_step);
  PetscCall(PetscOptionsInt(every_option.flag, every_option.help, every_option.doc, every, &every,
                            nullptr));
  PetscCall(PetscOptionsString(restart_option.flag, restart_option.help, restart_option.doc,
                               restart_option.default_shown, dir, sizeof(dir), &set));
  PetscCall(
      PetscOptionsInt(step_option.flag, step_option.help, step_option.doc, step, &step, &step_set));
  PetscOptionsEnd();
  PetscCheck(every >= 0, comm, PETSC_ERR_USER_INPUT,
             "-checkpoint_every %d: expected a number of steps >= 0 (0: checkpoints only when a "
             "run stops early)",
             (int)every);
  run.checkpoint_every = (int)every;
  PetscCheck(!step_set || set, comm, PETSC_ERR_USER_INPUT,
             "-restart_step %d needs -restart <output directory of the run to continue>",
             (int)step);
  PetscCheck(!step_set || step >= 1, comm, PETSC_ERR_USER_INPUT,
             "-restart_step %d: expected the step number of a checkpoint (>= 1)", (int)step);
  if (!set) PetscFunctionReturn(0);
  PetscCheck(dir[0], comm, PETSC_ERR_USER_INPUT,
             "-restart: expected the output directory of the run to continue");
  std::error_code failed;
  PetscCheck(std::filesystem::is_directory(dir, failed), comm, PETSC_ERR_USER_INPUT,
             "-restart %s: no such directory (expected the output directory of the run to "
             "continue)",
             dir);
  restart->restart = true;
  restart->dir = dir;
  restart->step = step_set ? (int)step : -1;
  PetscFunctionReturn(0);
}

/// A new run (not a restart) first removes what an earlier run left in its output directory
/// and this one might not overwrite: field and interface files (when this run writes none),
/// the time series, and checkpoints (which a later -restart would otherwise mistake for its
/// own). Only these names are touched.
PetscErrorCode clearEarlierRun(MPI_Comm comm, const std::string &dir)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    namespace fs = std::filesystem;
    std::error_code ignored;
    // interfaces.xmf: the single index of earlier versions, now interface_cells.xmf and
    // interface_points.xmf.
    std::vector<std::string> names = outputFileNames();
    names.emplace_back("interfaces.xmf");
    for (const std::string &name : names)
      fs::remove(fs::path(dir) / name, ignored);
    const fs::path checkpoints = fs::path(dir) / "checkpoints";
    if (fs::is_directory(checkpoints, ignored)) {
      std::vector<fs::path> old;
      for (const auto &entry : fs::directory_iterator(checkpoints, ignored)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("step-", 0) == 0) old.push_back(entry.path());
      }
      for (const auto &path : old)
        fs::remove(path, ignored);
      fs::remove(checkpoints, ignored); // only if now empty
    }
  }
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
