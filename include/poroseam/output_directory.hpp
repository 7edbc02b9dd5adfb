// The output directory belongs to one run at a time, and poroseam writes and deletes only its
// own files there, never through a symbolic link (docs/input_errors.md, "Output directory and
// I/O faults").
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

/// An advisory lock (flock) on `<dir>/.poroseam.lock`, held by rank 0 for the run's life: a
/// second run in the same directory is refused at its start. The kernel releases the lock when
/// the process ends, however it ends (kill -9 too): no stale lock to clean up.
class OutputDirectoryLock {
public:
  OutputDirectoryLock() = default;
  OutputDirectoryLock(const OutputDirectoryLock &) = delete;
  OutputDirectoryLock &operator=(const OutputDirectoryLock &) = delete;
  ~OutputDirectoryLock();

  /// Collective. The run's directory is -restart's when given (the run continues there), else
  /// -output_dir's (which checkOutputDirectory has created). Rank 0 takes the lock, then checks
  /// the names the run writes or deletes: none may be a symbolic link (poroseam would write or
  /// delete in the link's target), a file name may not be a directory or other non-file, and
  /// `checkpoints` and `mesh`, when present, must be directories holding only plain files.
  /// Fails with PETSC_ERR_USER_INPUT and one line naming the directory or the entry.
  PetscErrorCode acquire(MPI_Comm comm);

private:
  int fd_ = -1;
};

} // namespace poroseam
