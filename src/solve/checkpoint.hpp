// Checkpoints of a run and restarts from them (docs/checkpoints.md). A checkpoint is one HDF5
// file <output_dir>/checkpoints/step-NNNNNN.h5 with everything the next step depends on:
// the solution, the last accepted increment and its step (Newton's extrapolated start), time,
// the next step size, the committed interface history at every integration point, Newton's
// forcing memory, and how far the time series and field files had got. It is written to a
// temporary name and renamed, so a run killed while writing leaves the previous checkpoint.
// Internal to src/solve.
#pragma once

#include "checkpoint_integrity.hpp"
#include "run.hpp"

#include <string>

namespace poroseam {
namespace simulation_detail {

/// Writes the checkpoint of the last accepted step (run.step, solution X). Collective.
PetscErrorCode writeCheckpoint(Run &run, Vec X, std::string *path);

/// The checkpoint file of `dir` (an output directory) for step `step`, or the latest whole one
/// when step < 0: a damaged one (checkpoint_integrity.hpp) is named in a warning and the one
/// before it used. A PETSC_ERR_USER_INPUT error naming the options when there is none, when
/// none is whole, or when that of `step` is damaged. Collective.
PetscErrorCode findCheckpoint(MPI_Comm comm, const std::string &dir, int step, std::string *path);

/// The header of the (whole) checkpoint `path`; refuses, in one line, a checkpoint of another
/// format version or written by another number of ranks. Collective.
PetscErrorCode readCheckpointHeader(MPI_Comm comm, const std::string &path,
                                    CheckpointHeader *header);

/// What a checkpoint says about the run besides the vectors.
struct CheckpointInfo {
  int step = 0;
  double time = 0.0;
  double next_dt = 0.0;
  std::vector<double> output_times; ///< times already in the field files
  std::vector<double> interface_output_times; ///< ... in the interface files
};

/// Restores the run's state from `path` into X, run.previous (boundary values at the
/// checkpoint's time inserted), run.last_increment/last_dt, run.first_contraction and the
/// interface history; refuses checkpoints of another partition or scene. Collective.
PetscErrorCode readCheckpoint(Run &run, const std::string &path, Vec X, CheckpointInfo *info);

/// What a run reads about checkpoints and restarts: -checkpoint_every (into the run),
/// -restart and -restart_step.
struct RestartOptions {
  bool restart = false;
  std::string dir; ///< -restart: output directory of the interrupted run
  int step = -1;   ///< -restart_step (-1: the latest checkpoint)
};
PetscErrorCode readCheckpointOptions(MPI_Comm comm, Run &run, RestartOptions *restart);

/// A new run (not a restart) first removes what an earlier run left in its output directory
/// that it might not overwrite (see the definition). Collective.
PetscErrorCode clearEarlierRun(MPI_Comm comm, const std::string &dir);

} // namespace simulation_detail
} // namespace poroseam
