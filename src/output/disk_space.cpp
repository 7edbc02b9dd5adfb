// Room on the disk before a step's data is written (disk_space.hpp).
#include "poroseam/disk_space.hpp"

#include "poroseam/collective_check.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace poroseam {

PetscErrorCode reserveSpace(MPI_Comm comm, const std::string &dir, const std::string &file,
                            double local_bytes, const std::string &what)
{
  PetscMPIInt rank;
  double bytes = 0.0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Allreduce(&local_bytes, &bytes, 1, MPI_DOUBLE, MPI_SUM, comm));
  // HDF5's own records (object headers, attributes, B-trees) on top of the values.
  bytes = 1.25 * bytes + 64.0 * 1024.0;
  std::string error;
  if (rank == 0) {
    const std::string reserve = (dir.empty() ? std::string(".") : dir) + "/.poroseam.reserve";
    const int fd =
        open(reserve.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    int why = fd < 0 ? errno : posix_fallocate(fd, 0, (off_t)bytes);
    if (fd >= 0) close(fd);
    unlink(reserve.c_str());
    // EINVAL/EOPNOTSUPP: a file system without fallocate (glibc then writes the blocks
    // itself); anything else but a lack of space is left to the write to report.
    if (why == ENOSPC || why == EDQUOT) {
      char size[32];
      std::snprintf(size, sizeof size, "%.0f kB", bytes / 1000.0);
      error = "no space left for " + what + " in " + file + " (" + size +
              " needed: " + std::strerror(why) + "); the files hold every step before it";
    }
  }
  PetscCall(checkOnAllRanks(comm, error)); // kAgreedIoError
  PetscFunctionReturn(0);
}

} // namespace poroseam
