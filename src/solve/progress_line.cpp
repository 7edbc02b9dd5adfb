#include "progress_line.hpp"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

namespace poroseam {

void ProgressLine::print(MPI_Comm comm, const std::string &line, bool (*give_up)())
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0) return;
  if (gone_) {
    ++dropped_;
    return;
  }
  const int fd = fileno(stdout);
  std::fflush(stdout); // what PETSc printed before us, in order (it flushes each print itself)
  // Non-blocking for this write only: the file description may be shared (a terminal with
  // the shell, stderr), which must not see the flag.
  const int flags = fcntl(fd, F_GETFL);
  if (flags < 0 || (!(flags & O_NONBLOCK) && fcntl(fd, F_SETFL, flags | O_NONBLOCK) < 0)) {
    gone_ = true; // no stdout at all
    ++dropped_;
    return;
  }
  const char *data = line.data();
  size_t left = line.size();
  while (left > 0) {
    const ssize_t w = write(fd, data, left);
    if (w > 0) {
      data += w, left -= (size_t)w;
      continue;
    }
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (give_up()) break; // a stop has come: the run must reach its stop, not this line
      pollfd wait = {fd, POLLOUT, 0};
      const int r = poll(&wait, 1, 100);
      if (r > 0 && (wait.revents & (POLLERR | POLLHUP | POLLNVAL))) {
        gone_ = true;
        break;
      }
      continue;
    }
    gone_ = true; // EPIPE (SIGPIPE is ignored while the run steps), EIO, ...
    break;
  }
  if (left > 0) ++dropped_;
  if (!(flags & O_NONBLOCK)) fcntl(fd, F_SETFL, flags);
}

} // namespace poroseam
