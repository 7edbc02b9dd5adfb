// A full disk or quota must end a run before a partial write, with every file readable up to
// the last complete step, and on every rank together (docs/input_errors.md, "Output directory
// and I/O faults").
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

/// Collective, before a write of `local_bytes` on each rank into `file` (in `dir`): rank 0
/// reserves their sum (and a margin for HDF5's own records) with posix_fallocate, which counts
/// against quotas too, and frees it at once. Fails on every rank together
/// (PETSC_ERR_USER_INPUT, one line) with "no space left for <what> in <file> ...".
PetscErrorCode reserveSpace(MPI_Comm comm, const std::string &dir, const std::string &file,
                            double local_bytes, const std::string &what);

} // namespace poroseam
