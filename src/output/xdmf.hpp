// Helpers shared by the HDF5 + XDMF writers (bulk fields, interfaces): collective datasets
// written through PETSc's HDF5 viewer, and the XDMF index that rank 0 replaces atomically.
// Internal to src/output.
#pragma once

#include "poroseam/disk_space.hpp"

#include <petscis.h>
#include <petscvec.h>
#include <petscviewerhdf5.h>
#include <string>
#include <vector>

namespace poroseam::xdmf {

/// %.17g: a double that reads back exactly.
std::string formatDouble(double x);

/// The error of an I/O failure that every rank has agreed on (disk full, a file that cannot be
/// written): main.cpp reports it in one line and every rank ends together.
constexpr PetscErrorCode kAgreedIoError = PETSC_ERR_USER_INPUT;

/// Rank 0 creates `dir` (and parents); collective. `who` prefixes the error message.
PetscErrorCode createDirectory(MPI_Comm comm, const std::string &dir, const char *who);

/// Rank 0 writes `text` to `path` + ".tmp" and renames it to `path`, so that a reader never
/// sees a partial file; collective (the outcome is broadcast). Only rank 0's text is used.
PetscErrorCode replaceFile(MPI_Comm comm, const std::string &path, const std::string &text,
                           const char *who);

/// Collective: runs `body` (PETSc calls writing `file`) with PETSc's errors returned quietly,
/// then agrees on the outcome: when it failed on any rank, `*failed` is set on every rank and
/// every rank fails with kAgreedIoError and one message naming the file. An error on one rank
/// (the HDF5 library's, a write refused) can otherwise leave the others waiting for it.
template <class Body>
PetscErrorCode agreed(MPI_Comm comm, const std::string &file, bool *failed, Body body);
PetscErrorCode agreeOn(MPI_Comm comm, const std::string &file, PetscErrorCode error, bool *failed);

/// -io_agreement_timeout [s]: how long a rank whose output failed waits for the others in
/// agreeOn before it ends them all (*grace unchanged when not given). Not collective.
PetscErrorCode readAgreementTimeout(PetscReal *grace);

template <class Body>
PetscErrorCode agreed(MPI_Comm comm, const std::string &file, bool *failed, Body body)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode error = body();
  PetscCall(PetscPopErrorHandler());
  PetscCall(agreeOn(comm, file, error, failed));
  PetscFunctionReturn(0);
}

/// For a writer's destructor: whether every rank is there to close its file together. A
/// writer destroyed after an error on one rank only (main.cpp then ends the run with
/// MPI_Abort) must not start a collective close that the other ranks never join: that was
/// the hang of issue 23 (rank 1 closing fields.h5, rank 0 flushing it elsewhere).
class Rendezvous {
public:
  Rendezvous() = default;
  Rendezvous(const Rendezvous &) = delete;
  Rendezvous &operator=(const Rendezvous &) = delete;
  ~Rendezvous();
  /// Collective: a communicator of its own, so that no other operation can match the barrier.
  PetscErrorCode init(MPI_Comm comm);
  /// A nonblocking barrier, given `seconds` to complete; false when some rank did not come.
  bool allThere(double seconds);

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  bool pending_ = false; // a barrier left unfinished: the communicator is not freed
};

/// Collective: writes the rank-ordered concatenation of every rank's `values` (bs values per
/// row) as `<group>/<name>`, shape [N] when bs == 1, else [N, bs] (PETSc Vec, doubles). The
/// dataset carries the string attribute "units" (SI, UDUNITS spelling: "m", "Pa", "m2/s";
/// "1" for dimensionless numbers and indices) and, with `time` given, the attribute "time".
PetscErrorCode writeReals(PetscViewer viewer, MPI_Comm comm, const std::string &group,
                          const std::string &name, PetscInt bs,
                          const std::vector<PetscScalar> &values, const char *units,
                          const double *time);

/// Same for PetscInt values (PETSc IS): shape [N, bs], also when bs == 1 (PETSc's ISView).
PetscErrorCode writeInts(PetscViewer viewer, MPI_Comm comm, const std::string &group,
                         const std::string &name, PetscInt bs, const std::vector<PetscInt> &values,
                         const char *units, const double *time = nullptr);

/// Collective: the string attribute `attribute` = `value` on the dataset or group `path`.
PetscErrorCode writeText(PetscViewer viewer, const std::string &path, const char *attribute,
                         const std::string &value);

/// `<DataItem Dimensions="dims" NumberType=... Precision=... Format="HDF">file:path</DataItem>`
/// (no indentation, no newline). `integer` selects Int with sizeof(PetscInt), else Float 8.
std::string dataItem(const std::string &dims, bool integer, const std::string &h5file,
                     const std::string &path);

} // namespace poroseam::xdmf
