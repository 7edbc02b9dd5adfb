// The rolling checkpoint: a checkpoint of the last accepted step, rewritten after every step
// (or every -checkpoint_rolling_interval seconds of wall time), so that a run stopped or
// killed from outside in the middle of a long step has already kept its work: a restart
// continues from it (docs/checkpoints.md, "A stop from outside"). It is an ordinary checkpoint
// file (checkpoint.hpp: written under a temporary name and renamed); the new one is on disk
// before the previous one is removed. Checkpoints of -checkpoint_every, the one a run was
// restarted from, and the last one of a run that did not reach its final time stay; a run
// that reaches its final time removes its rolling checkpoint. Internal to src/solve.
#pragma once

#include <petscsys.h>
#include <petscvec.h>
#include <string>

namespace poroseam {
namespace simulation_detail {

struct Run;

struct RollingCheckpoint {
  bool enabled = true; ///< -checkpoint_rolling
  /// -checkpoint_rolling_interval: wall seconds between two (0: every step; -1, the default:
  /// every step while they cost less than a tenth of the wall time)
  double interval = -1.0;
  std::string path;       ///< the current rolling checkpoint ("": none)
  double last_wall = 0.0; ///< when it was written (MPI_Wtime)
  double cost = 0.0;      ///< wall time of the last write [s]
  double total_cost = 0.0;
  int written = 0;
};

/// -checkpoint_rolling and -checkpoint_rolling_interval. Collective.
PetscErrorCode readRollingCheckpointOptions(MPI_Comm comm, RollingCheckpoint *rolling);

/// After an accepted step (it took `step_wall` seconds) that has no kept checkpoint: writes the
/// rolling checkpoint of it when due and removes the previous one. Collective.
PetscErrorCode updateRollingCheckpoint(Run &run, Vec X, double step_wall);

/// A kept checkpoint was just written: the rolling one (older) is removed. Collective.
PetscErrorCode dropRollingCheckpoint(Run &run);

/// Prints how many rolling checkpoints were written and what they cost (if any). Collective.
PetscErrorCode reportRollingCheckpoints(Run &run);

/// A run that reached its final time: its rolling checkpoint goes (and the checkpoint
/// folder, if that leaves it empty). Collective.
PetscErrorCode endRollingCheckpoint(Run &run);

} // namespace simulation_detail
} // namespace poroseam
