#include "stop_request.hpp"

#include <csignal>

namespace poroseam {
namespace {

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGUSR1};
static_assert(sizeof(kSignals) / sizeof(kSignals[0]) == StopRequest::kCount,
              "one saved handler per signal");

// A signal handler can only reach static storage, and may only set a sig_atomic_t: the one
// piece of process-wide state in poroseam, read by StopRequest::pending between steps.
volatile std::sig_atomic_t received = 0;

extern "C" void onStopSignal(int signal)
{
  if (received == signal) {
    // Asked twice: stop now, the way the signal would have without us.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  received = signal;
}

} // namespace

PetscErrorCode StopRequest::install()
{
  PetscFunctionBeginUser;
  if (installed_) PetscFunctionReturn(0);
  received = 0;
  struct sigaction action = {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART; // system calls (file writes, MPI waits) go on after it
  for (int i = 0; i < kCount; ++i)
    PetscCheck(sigaction(kSignals[i], &action, &previous_[i]) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS,
               "cannot install the handler of signal %d", kSignals[i]);
  installed_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode StopRequest::restore()
{
  PetscFunctionBeginUser;
  if (!installed_) PetscFunctionReturn(0);
  for (int i = 0; i < kCount; ++i)
    sigaction(kSignals[i], &previous_[i], nullptr);
  installed_ = false;
  PetscFunctionReturn(0);
}

PetscErrorCode StopRequest::pending(MPI_Comm comm, int *signal) const
{
  int mine = received, any = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm));
  *signal = any;
  PetscFunctionReturn(0);
}

} // namespace poroseam
