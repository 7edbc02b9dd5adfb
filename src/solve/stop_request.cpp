#include "stop_request.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace poroseam {
namespace {

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP, SIGUSR1};
static_assert(sizeof(kSignals) / sizeof(kSignals[0]) == StopRequest::kCount,
              "one saved handler per signal");

// A signal handler can only reach static storage, and may only set a sig_atomic_t: the
// process-wide state of poroseam is this flag, read by StopRequest::pending between steps,
// and the record the handler writes (below).
volatile std::sig_atomic_t received_signal = 0;
/// A SIGCONT has come: mpiexec (and Slurm) send it just before their SIGTERM.
volatile std::sig_atomic_t continued = 0;

/// The run.yaml of a run stopped after its last accepted step, ready for the handler: two
/// slots, so that rank 0 fills one while the handler may be reading the other (it can run on
/// any thread of the process).
struct ArmedRecord {
  char path[PETSC_MAX_PATH_LEN];
  char tmp[PETSC_MAX_PATH_LEN + 16];
  char text[1 << 16];
  size_t length;
};
ArmedRecord slots[2];
std::atomic<int> armed{-1}; ///< the slot to write on a signal (-1: none)
static_assert(std::atomic<int>::is_always_lock_free, "the handler reads it");

/// Async-signal-safe: the whole of [data, data + n) to fd, or false.
bool writeAll(int fd, const char *data, size_t n)
{
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w, n -= (size_t)w;
  }
  return true;
}

/// Async-signal-safe: "15 (SIGTERM)" into out (at least 32 chars); its length.
size_t signalText(int signal, char *out)
{
  char digits[12];
  size_t n = 0, k = 0;
  for (unsigned v = (unsigned)signal; n == 0 || v > 0; v /= 10)
    digits[n++] = (char)('0' + v % 10);
  while (n > 0)
    out[k++] = digits[--n];
  const char *name = signal == SIGTERM   ? "SIGTERM"
                     : signal == SIGINT  ? "SIGINT"
                     : signal == SIGHUP  ? "SIGHUP"
                     : signal == SIGUSR1 ? "SIGUSR1"
                                         : "";
  if (*name) {
    out[k++] = ' ', out[k++] = '(';
    while (*name)
      out[k++] = *name++;
    out[k++] = ')';
  }
  return k;
}

/// Async-signal-safe: writes the armed record (if any) with `signal` in it.
void writeArmedRecord(int signal)
{
  const int k = armed.load();
  if (k < 0) return;
  const ArmedRecord &r = slots[k];
  const int saved_errno = errno;
  char sig[32];
  const size_t sig_length = signalText(signal, sig);
  const int fd = ::open(r.tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd >= 0) {
    bool ok = true;
    size_t from = 0;
    for (size_t i = 0; ok && i <= r.length; ++i)
      if (i == r.length || r.text[i] == StopRequest::kSignalMark) {
        ok = writeAll(fd, r.text + from, i - from);
        if (ok && i < r.length) ok = writeAll(fd, sig, sig_length);
        from = i + 1;
      }
    ok = ::close(fd) == 0 && ok;
    if (ok) ::rename(r.tmp, r.path);
  }
  errno = saved_errno;
}

extern "C" void onStopSignal(int signal)
{
  if (received_signal == signal) {
    // Asked twice: stop now, the way the signal would have without us.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  const bool first = received_signal == 0;
  received_signal = signal;
  // The record of a run stopped after its last accepted step, now: mpiexec kills the ranks
  // about a second after it forwards the signal, maybe before the run reaches a safe point.
  if (first) writeArmedRecord(signal);
}

extern "C" void onContinue(int)
{
  continued = 1;
}

} // namespace

PetscErrorCode StopRequest::install()
{
  PetscFunctionBeginUser;
  if (installed_) PetscFunctionReturn(0);
  received_signal = 0;
  struct sigaction action = {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  for (int s : kSignals)
    sigaddset(&action.sa_mask, s); // one handler at a time: the record is written once
  action.sa_flags = SA_RESTART;    // system calls (file writes, MPI waits) go on after it
  for (int i = 0; i < kCount; ++i)
    PetscCheck(sigaction(kSignals[i], &action, &previous_[i]) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS,
               "cannot install the handler of signal %d", kSignals[i]);
  struct sigaction ignore = {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  PetscCheck(sigaction(SIGPIPE, &ignore, &previous_pipe_) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS,
             "cannot ignore SIGPIPE");
  // SIGCONT still resumes a stopped process; the handler only notes that it came.
  continued = 0;
  struct sigaction note = {};
  note.sa_handler = onContinue;
  sigemptyset(&note.sa_mask);
  note.sa_flags = SA_RESTART;
  PetscCheck(sigaction(SIGCONT, &note, &previous_cont_) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS,
             "cannot install the handler of SIGCONT");
  installed_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode StopRequest::restore()
{
  PetscFunctionBeginUser;
  if (!installed_) PetscFunctionReturn(0);
  disarmRecord();
  for (int i = 0; i < kCount; ++i)
    sigaction(kSignals[i], &previous_[i], nullptr);
  sigaction(SIGPIPE, &previous_pipe_, nullptr);
  sigaction(SIGCONT, &previous_cont_, nullptr);
  installed_ = false;
  PetscFunctionReturn(0);
}

PetscErrorCode StopRequest::pending(MPI_Comm comm, int *signal) const
{
  int mine = received_signal, any = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm));
  *signal = any;
  PetscFunctionReturn(0);
}

bool StopRequest::received()
{
  return received_signal != 0;
}

bool StopRequest::warned()
{
  return continued != 0 || received_signal != 0;
}

bool StopRequest::armRecord(const std::string &path, const std::string &text)
{
  const int next = armed.load() == 0 ? 1 : 0;
  ArmedRecord &r = slots[next];
  if (text.size() > sizeof(r.text) || path.size() + 1 > sizeof(r.path)) {
    disarmRecord();
    return false;
  }
  std::memcpy(r.path, path.c_str(), path.size() + 1);
  std::memcpy(r.tmp, path.c_str(), path.size());
  std::memcpy(r.tmp + path.size(), ".signal.tmp", sizeof(".signal.tmp"));
  std::memcpy(r.text, text.data(), text.size());
  r.length = text.size();
  armed.store(next);
  // A signal that came while the run wrote its own "running" record: the stop wins.
  if (received_signal) writeArmedRecord(received_signal);
  return true;
}

void StopRequest::disarmRecord()
{
  armed.store(-1);
}

} // namespace poroseam
