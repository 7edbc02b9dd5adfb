// A request from outside to stop a run (SIGTERM, SIGINT, SIGHUP, SIGUSR1: a batch scheduler,
// a terminal, mpiexec forwarding them): the run stops at its next safe point (after the step
// in progress, or between two Newton iterations of a long step), keeps its work, says so in
// run.yaml and exits with a non-zero status and a restart command (docs/checkpoints.md).
// Open MPI's mpiexec answers SIGTERM, SIGINT and SIGHUP by sending the ranks SIGCONT, then
// SIGTERM a second later, then SIGKILL a second after that: the ranks have about one second.
// So that nothing depends on reaching a safe point in time, rank 0 arms, after each accepted
// step, the run.yaml of a run stopped there: the signal handler itself writes it (open,
// write and rename are async-signal-safe), and the checkpoint of that step is on disk already
// (rolling_checkpoint.hpp), after every step from the SIGCONT that precedes mpiexec's SIGTERM.
// Internal to src/solve.
#pragma once

#include <petscsys.h>
#include <signal.h>
#include <string>

namespace poroseam {

class StopRequest {
public:
  static constexpr int kCount = 4; ///< signals caught: SIGTERM, SIGINT, SIGHUP, SIGUSR1
  /// In an armed record, where the handler writes the signal ("15 (SIGTERM)").
  static constexpr char kSignalMark = '\x02';

  /// Catches SIGTERM, SIGINT, SIGHUP and SIGUSR1, and ignores SIGPIPE (a reader of stdout that
  /// is gone is an EPIPE for the writer, not the end of the run), until restore() (or
  /// destruction). A second signal of the same kind while the first is pending ends the process
  /// at once, as without us.
  PetscErrorCode install();
  PetscErrorCode restore();
  ~StopRequest() { (void)restore(); }

  /// Collective: has any rank received a stop signal? (The signal that did, or 0.)
  PetscErrorCode pending(MPI_Comm comm, int *signal) const;

  /// This process has received a stop signal (no communication: for a wait that must give
  /// up at once, e.g. a write to a stdout nobody reads any more).
  static bool received();

  /// A stop may be near: a SIGCONT has come (Open MPI's mpiexec, like Slurm, sends the ranks
  /// SIGCONT a second before its SIGTERM; a job resumed after SIGTSTP gets one too), or a
  /// stop signal. No communication.
  static bool warned();

  /// Rank 0: the file `text` is to be written to `path` (atomically, through path.signal.tmp)
  /// as soon as a stop signal comes, each kSignalMark replaced by the signal. False (nothing
  /// armed) if the text is longer than the handler's static buffer. Replaces the record armed
  /// before; if a signal has come already, writes it now.
  static bool armRecord(const std::string &path, const std::string &text);
  /// Nothing is written on a signal any more (the run writes its own record from here).
  static void disarmRecord();

private:
  bool installed_ = false;
  struct sigaction previous_[kCount] = {}; ///< the handlers we replaced, one per signal
  struct sigaction previous_pipe_ = {};    ///< SIGPIPE's
  struct sigaction previous_cont_ = {};    ///< SIGCONT's
};

} // namespace poroseam
