// Rank 0's line per time step on stdout, written so that it never holds the run up for good.
// Under mpiexec, stdout is a pseudo-terminal read by mpiexec; once mpiexec has been signalled
// it may stop reading, and a blocking write would then wait until the SIGKILL that follows,
// never reaching the point where the run stops cleanly. The line is written without blocking:
// while the reader is slow (a paused pager) it waits, polling, as long as no stop signal has
// come; it gives up on the line as soon as one has, and writes no more lines once the reader
// is gone (EPIPE, EIO, a hang-up). Internal to src/solve.
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

class ProgressLine {
public:
  /// Rank 0 of comm writes `line`; `give_up()` says when to stop waiting for the reader.
  /// No communication.
  void print(MPI_Comm comm, const std::string &line, bool (*give_up)());
  /// Lines (or their ends) not written because the reader was gone or a stop had come.
  long dropped() const { return dropped_; }

private:
  bool gone_ = false;
  long dropped_ = 0;
};

} // namespace poroseam
