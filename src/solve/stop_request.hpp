// A user's request to stop a run early (SIGTERM, SIGINT, SIGUSR1): the run finishes the step
// it is in, writes a checkpoint and exits with a non-zero status and a restart command.
// Internal to src/solve.
#pragma once

#include <petscsys.h>
#include <signal.h>

namespace poroseam {

class StopRequest {
public:
  static constexpr int kCount = 3; ///< signals caught: SIGTERM, SIGINT, SIGUSR1
  /// Catches SIGTERM, SIGINT and SIGUSR1 until restore() (or destruction). A second signal
  /// of the same kind while the first is pending ends the process at once, as without us.
  PetscErrorCode install();
  PetscErrorCode restore();
  ~StopRequest() { (void)restore(); }

  /// Collective: has any rank received a stop signal? (The signal that did, or 0.)
  PetscErrorCode pending(MPI_Comm comm, int *signal) const;

private:
  bool installed_ = false;
  struct sigaction previous_[kCount] = {}; ///< the handlers we replaced, one per signal
};

} // namespace poroseam
