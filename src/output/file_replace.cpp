// Whole-file writes (file_replace.hpp).
#include "file_replace.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace poroseam {

bool replaceFileContents(const std::string &path, const std::string &text, std::string *why)
{
  const std::string tmp = path + ".tmp";
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) {
    *why = std::string(std::strerror(errno)) + (errno == ELOOP ? " (" + tmp + " is a link)" : "");
    return false;
  }
  bool ok = true;
  for (size_t done = 0; ok && done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      ok = false, *why = std::strerror(n < 0 ? errno : ENOSPC);
    else
      done += (size_t)n;
  }
  if (close(fd) != 0 && ok) ok = false, *why = std::strerror(errno); // NFS reports late
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) ok = false, *why = std::strerror(errno);
  if (!ok) unlink(tmp.c_str()); // the previous text stays whole
  return ok;
}

} // namespace poroseam
