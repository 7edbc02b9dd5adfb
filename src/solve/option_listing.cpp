// -help with a scene: list the options of a set-up run, write nothing (option_listing.hpp).
#include "poroseam/option_listing.hpp"

#include "poroseam/collective_check.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <vector>

namespace poroseam {

PetscErrorCode listingOptions(bool *listing)
{
  PetscBool help = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  *listing = help;
  PetscFunctionReturn(0);
}

OptionListing::~OptionListing()
{
  remove(true);
}

void OptionListing::remove(bool failed)
{
  if (!owner_) return;
  owner_ = false;
  std::error_code ignored;
  // A listing that failed in gmsh points to gmsh's log in the scratch directory: keep that
  // file (and only it) for the user to read. gmsh -v 1 writes nothing when it succeeds.
  const std::filesystem::path log = std::filesystem::path(scratch_) / "mesh" / "gmsh.log";
  if (failed && std::filesystem::file_size(log, ignored) > 0 && !ignored) {
    for (const auto &entry : std::filesystem::directory_iterator(log.parent_path(), ignored))
      if (entry.path() != log) std::filesystem::remove_all(entry.path(), ignored);
    for (const auto &entry : std::filesystem::directory_iterator(scratch_, ignored))
      if (entry.path() != log.parent_path()) std::filesystem::remove_all(entry.path(), ignored);
    return;
  }
  std::filesystem::remove_all(scratch_, ignored);
}

PetscErrorCode OptionListing::begin(MPI_Comm comm, std::string *output_dir)
{
  PetscMPIInt rank;
  std::string error;
  std::vector<char> name(PETSC_MAX_PATH_LEN, '\0');
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const char *tmp = std::getenv("TMPDIR");
    const std::string pattern = std::string(tmp && tmp[0] ? tmp : "/tmp") + "/poroseam-help-XXXXXX";
    if (pattern.size() >= name.size())
      error = "the scratch directory name " + pattern + " is too long";
    else if (std::copy(pattern.begin(), pattern.end(), name.begin()), !mkdtemp(name.data()))
      error = "cannot create a scratch directory " + pattern + " for -help (set TMPDIR)";
    else
      owner_ = true;
  }
  PetscCall(checkOnAllRanks(comm, error));
  PetscCallMPI(MPI_Bcast(name.data(), (int)name.size(), MPI_CHAR, 0, comm));
  scratch_ = name.data();
  *output_dir = scratch_;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionListing::end(MPI_Comm comm, const std::string &output_dir)
{
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Barrier(comm)); // every rank is done with the mesh file
  remove(false);
  PetscCall(PetscPrintf(comm,
                        "poroseam: -help: the scene was read and checked and the solvers set "
                        "up; the options above show their values. Nothing was run or written "
                        "to '%s' (docs/scenes.md describes every option)\n",
                        output_dir.c_str()));
  PetscFunctionReturn(0);
}

} // namespace poroseam
