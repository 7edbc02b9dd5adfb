// One run per output directory, and no writes through symbolic links (output_directory.hpp).
#include "poroseam/output_directory.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/option_registry.hpp"
#include "poroseam/scene.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <sys/file.h>
#include <unistd.h>

namespace poroseam {
namespace {

namespace fs = std::filesystem;

/// Files poroseam writes (or, at the start of a new run, deletes) in the output directory,
/// with the temporary names it writes them under before renaming.
const char *const kFiles[] = {"run.yaml",
                              "run.yaml.tmp",
                              "timeseries.csv",
                              "timeseries.csv.tmp",
                              "timeseries.csv.units",
                              "timeseries.csv.units.tmp",
                              "fields.h5",
                              "fields.xmf",
                              "fields.xmf.tmp",
                              "interfaces.h5",
                              "interfaces.xmf",
                              "interface_cells.xmf",
                              "interface_cells.xmf.tmp",
                              "interface_points.xmf",
                              "interface_points.xmf.tmp",
                              ".poroseam.reserve"};
/// Folders poroseam writes into: restart files, and the mesh gmsh makes from a .geo.
const char *const kFolders[] = {"checkpoints", "mesh"};

/// The directory this run writes to: -restart's (a restart continues there) or -output_dir's.
std::string runDirectory()
{
  char buffer[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  if (!PetscOptionsGetString(nullptr, nullptr, spec(Option::restart).flag, buffer, sizeof buffer,
                             &set) &&
      set && buffer[0])
    return buffer;
  set = PETSC_FALSE;
  if (!PetscOptionsGetString(nullptr, nullptr, spec(Option::output_dir).flag, buffer, sizeof buffer,
                             &set) &&
      set)
    return buffer;
  return Scene().output_dir;
}

/// "" if the entry may be written: absent, or of the kind poroseam writes there.
std::string checkEntry(const fs::path &path, bool folder)
{
  std::error_code failed;
  const fs::file_status s = fs::symlink_status(path, failed);
  if (failed || s.type() == fs::file_type::not_found) return "";
  const std::string name = "'" + path.string() + "'";
  if (s.type() == fs::file_type::symlink)
    return name + " is a symbolic link: poroseam does not write or delete through links " +
           "(it would change the link's target); remove the link or choose another " +
           "-output_dir";
  if (folder && s.type() != fs::file_type::directory)
    return name + " is not a directory: poroseam keeps its " + path.filename().string() +
           " folder there; remove or rename it";
  if (!folder && s.type() != fs::file_type::regular)
    return name + (s.type() == fs::file_type::directory ? " is a directory" : " is not a file") +
           " where poroseam writes its file " + path.filename().string() +
           "; remove or rename it, or choose another -output_dir";
  return "";
}

/// Rank 0: the lock, then every entry the run writes. Returns the error line or "".
std::string lockAndCheck(const std::string &dir, int *fd)
{
  std::error_code failed;
  if (!fs::is_directory(dir, failed)) return ""; // -restart's own check names it
  const std::string lock = dir + "/.poroseam.lock";
  *fd = open(lock.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (*fd < 0)
    return "cannot create the lock file '" + lock +
           "' in the output directory: " + std::strerror(errno) +
           (errno == ELOOP ? " (it is a symbolic link)" : "");
  if (flock(*fd, LOCK_EX | LOCK_NB) != 0) {
    const int why = errno;
    char holder[128] = "";
    const ssize_t n = pread(*fd, holder, sizeof holder - 1, 0);
    std::string pid = n > 0 ? std::string(holder, n) : "";
    while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
      pid.pop_back();
    close(*fd);
    *fd = -1;
    if (why != EWOULDBLOCK) return "cannot lock '" + lock + "': " + std::strerror(why);
    return "output directory '" + dir + "' is in use by another run (pid " +
           (pid.empty() ? "unknown" : pid) + "): wait for it to end, or choose another " +
           "-output_dir";
  }
  // Whose lock it is, for the message of a run refused later ("pid 1234 on node7").
  char host[64] = "";
  gethostname(host, sizeof host - 1);
  const std::string holder = std::to_string(getpid()) + " on " + host + "\n";
  if (ftruncate(*fd, 0) != 0 || pwrite(*fd, holder.data(), holder.size(), 0) < 0) {
    // The lock holds without its text: a refused run then says "pid unknown".
  }
  for (const char *name : kFiles) {
    const std::string error = checkEntry(fs::path(dir) / name, false);
    if (!error.empty()) return error;
  }
  for (const char *name : kFolders) {
    const fs::path folder = fs::path(dir) / name;
    std::string error = checkEntry(folder, true);
    if (!error.empty()) return error;
    if (!fs::is_directory(folder, failed)) continue;
    // checkpoints/step-*.h5 are replaced and deleted, mesh/* overwritten by gmsh.
    for (const auto &entry : fs::directory_iterator(folder, failed)) {
      error = checkEntry(entry.path(), false);
      if (!error.empty()) return error;
    }
  }
  return "";
}

} // namespace

OutputDirectoryLock::~OutputDirectoryLock()
{
  if (fd_ >= 0) close(fd_); // releases the lock; the file stays (see acquire)
}

PetscErrorCode OutputDirectoryLock::acquire(MPI_Comm comm)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string error;
  // The lock file is never deleted: a run removing it at its end could let two later runs
  // lock two different files of the same name.
  if (rank == 0) error = lockAndCheck(runDirectory(), &fd_);
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

} // namespace poroseam
