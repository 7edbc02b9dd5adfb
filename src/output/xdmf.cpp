// Helpers shared by the HDF5 + XDMF writers (see xdmf.hpp).
#include "xdmf.hpp"

#include "file_replace.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/option_registry.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace poroseam::xdmf {

std::string formatDouble(double x)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

PetscErrorCode createDirectory(MPI_Comm comm, const std::string &dir, const char *who)
{
  PetscMPIInt rank;
  int ok = 1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && !dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) ok = 0;
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCheck(ok, comm, kAgreedIoError, "%s: cannot create directory %s", who, dir.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode readAgreementTimeout(PetscReal *grace)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, spec(Option::io_agreement_timeout).flag, grace,
                                nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode agreeOn(MPI_Comm comm, const std::string &file, PetscErrorCode error, bool *failed)
{
  PetscFunctionBeginUser;
  std::string message;
  if (error) {
    const char *text = nullptr;
    char *specific = nullptr;
    PetscErrorMessage(error, &text, &specific);
    message = "cannot write " + file + ": " +
              (specific && *specific ? specific
               : text                ? text
                                     : "error") +
              " (disk full, quota exceeded or a read-only file system?)";
  }
  int mine = error != 0, any = 0;
  MPI_Request request;
  PetscCallMPI(MPI_Iallreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm, &request));
  if (!error) {
    PetscCallMPI(MPI_Wait(&request, MPI_STATUS_IGNORE));
  } else {
    // The other ranks may never come: an HDF5 call that failed here only can leave them
    // inside the library's own collective calls, waiting for this rank. After a grace
    // (-io_agreement_timeout, seconds) this rank says what failed and ends them all: the one
    // case where a run ends in MPI_Abort, rather than a hang.
    PetscReal grace = 120.0;
    PetscCall(readAgreementTimeout(&grace));
    const double start = MPI_Wtime();
    for (int done = 0; !done;) {
      PetscCallMPI(MPI_Test(&request, &done, MPI_STATUS_IGNORE));
      if (done) break;
      if (MPI_Wtime() - start > grace) {
        std::fprintf(stderr,
                     "poroseam: error: %s; the other ranks did not end with this one within "
                     "%g s (-io_agreement_timeout): ending the run\n",
                     message.c_str(), (double)grace);
        std::fflush(stderr);
        MPI_Abort(comm, 1);
      }
      usleep(10000);
    }
  }
  if (!any) PetscFunctionReturn(0);
  *failed = true;
  PetscCall(checkOnAllRanks(comm, message));
  PetscFunctionReturn(0);
}

Rendezvous::~Rendezvous()
{
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (comm_ != MPI_COMM_NULL && !pending_ && !finalized) MPI_Comm_free(&comm_);
}

PetscErrorCode Rendezvous::init(MPI_Comm comm)
{
  PetscFunctionBeginUser;
  if (comm_ == MPI_COMM_NULL) PetscCallMPI(MPI_Comm_dup(comm, &comm_));
  PetscFunctionReturn(0);
}

bool Rendezvous::allThere(double seconds)
{
  if (comm_ == MPI_COMM_NULL) return false;
  MPI_Request request;
  if (MPI_Ibarrier(comm_, &request) != MPI_SUCCESS) return false;
  const double start = MPI_Wtime();
  for (int done = 0;;) {
    if (MPI_Test(&request, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS) return false;
    if (done) return true;
    if (MPI_Wtime() - start > seconds) {
      pending_ = true;
      return false;
    }
    usleep(1000);
  }
}

PetscErrorCode replaceFile(MPI_Comm comm, const std::string &path, const std::string &text,
                           const char *who)
{
  PetscMPIInt rank;
  bool ok = true;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string why;
  if (rank == 0) ok = replaceFileContents(path, text, &why);
  (void)who; // the path says which file; the writer's name would say nothing to a user
  PetscCall(checkOnAllRanks(comm, ok ? "" : "cannot write " + path + ": " + why));
  PetscFunctionReturn(0);
}

PetscErrorCode writeReals(PetscViewer viewer, MPI_Comm comm, const std::string &group,
                          const std::string &name, PetscInt bs,
                          const std::vector<PetscScalar> &values, const char *units,
                          const double *time)
{
  Vec v;
  PetscScalar *a;
  const PetscInt n = static_cast<PetscInt>(values.size());

  PetscFunctionBeginUser;
  PetscCheck(bs >= 1 && n % bs == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "%s/%s: %" PetscInt_FMT " values for block size %" PetscInt_FMT, group.c_str(),
             name.c_str(), n, bs);
  PetscCall(VecCreate(comm, &v));
  PetscCall(VecSetSizes(v, n, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(v, bs));
  PetscCall(VecSetType(v, VECMPI));
  PetscCall(PetscObjectSetName((PetscObject)v, name.c_str()));
  PetscCall(VecGetArray(v, &a));
  std::copy(values.begin(), values.end(), a);
  PetscCall(VecRestoreArray(v, &a));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group.c_str()));
  PetscCall(VecView(v, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  {
    const std::string path = group + "/" + name;

    PetscCall(writeText(viewer, path, "units", units));
    if (time) {
      PetscReal t = static_cast<PetscReal>(*time);

      PetscCall(PetscViewerHDF5WriteAttribute(viewer, path.c_str(), "time", PETSC_REAL, &t));
    }
  }
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode writeInts(PetscViewer viewer, MPI_Comm comm, const std::string &group,
                         const std::string &name, PetscInt bs, const std::vector<PetscInt> &values,
                         const char *units, const double *time)
{
  IS is;
  const PetscInt n = static_cast<PetscInt>(values.size());

  PetscFunctionBeginUser;
  PetscCheck(bs >= 1 && n % bs == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "%s/%s: %" PetscInt_FMT " values for block size %" PetscInt_FMT, group.c_str(),
             name.c_str(), n, bs);
  PetscCall(ISCreateGeneral(comm, n, values.data(), PETSC_COPY_VALUES, &is));
  PetscCall(ISSetBlockSize(is, bs));
  PetscCall(PetscObjectSetName((PetscObject)is, name.c_str()));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group.c_str()));
  PetscCall(ISView(is, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  {
    const std::string path = group + "/" + name;

    PetscCall(writeText(viewer, path, "units", units));
    if (time) {
      PetscReal t = static_cast<PetscReal>(*time);

      PetscCall(PetscViewerHDF5WriteAttribute(viewer, path.c_str(), "time", PETSC_REAL, &t));
    }
  }
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

PetscErrorCode writeText(PetscViewer viewer, const std::string &path, const char *attribute,
                         const std::string &value)
{
  PetscFunctionBeginUser;
  PetscCall(
      PetscViewerHDF5WriteAttribute(viewer, path.c_str(), attribute, PETSC_STRING, value.c_str()));
  PetscFunctionReturn(0);
}

std::string dataItem(const std::string &dims, bool integer, const std::string &h5file,
                     const std::string &path)
{
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + (integer ? "Int" : "Float") +
         "\" Precision=\"" + std::to_string(integer ? sizeof(PetscInt) : sizeof(double)) +
         "\" Format=\"HDF\">" + h5file + ":" + path + "</DataItem>";
}

} // namespace poroseam::xdmf
