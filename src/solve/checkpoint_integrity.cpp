#include "checkpoint_integrity.hpp"

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <petsclayouthdf5.h>
#include <petscvec.h>
#include <petscviewerhdf5.h>
#include <vector>

namespace poroseam {
namespace simulation_detail {
namespace {

/// The datasets every checkpoint has; `skeleton_history` only with plastic regions.
const char *const kDatasets[] = {"layout", "solution", "last_increment", "interface_history",
                                 "output_times"};

/// HDF5 keeps an attribute in the object header, at most 64 kB: a longer text (600 probes)
/// is kept in parts of this many characters, <name>_0, <name>_1, ... with <name>_parts.
constexpr std::size_t kTextPart = 32000;

/// SplitMix64's finaliser: every input bit changes about half of the output bits.
std::uint64_t mix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::string hex(std::uint64_t h)
{
  char text[24];
  std::snprintf(text, sizeof(text), "%016" PRIx64, h);
  return text;
}

/// FNV-1a over the header's values in a fixed order (each text with its length first).
class HeaderHash {
public:
  void add(const void *data, std::size_t n)
  {
    const unsigned char *p = static_cast<const unsigned char *>(data);
    for (std::size_t i = 0; i < n; ++i)
      h_ = (h_ ^ p[i]) * 0x100000001b3ULL;
  }
  void add(PetscInt v) { add(&v, sizeof v); }
  void add(double v) { add(&v, sizeof v); }
  void add(const std::string &s)
  {
    const std::uint64_t n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  std::string value() const { return hex(h_); }

private:
  std::uint64_t h_ = 0xcbf29ce484222325ULL;
};

std::string headerChecksum(const CheckpointHeader &h)
{
  HeaderHash hash;
  for (PetscInt v : {h.version, h.ranks, h.step, h.output_count})
    hash.add(v);
  if (h.interface_output_count >= 0) hash.add(h.interface_output_count); // newer checkpoints
  for (double v : {h.time, h.next_dt, h.last_dt, h.first_contraction})
    hash.add(v);
  for (const std::string *s : {&h.integrator, &h.options, &h.option_files, &h.output_files})
    hash.add(*s);
  return hash.value();
}

PetscErrorCode writeText(PetscViewer viewer, const std::string &name, const std::string &text)
{
  PetscFunctionBeginUser;
  const PetscInt parts = (PetscInt)((text.size() + kTextPart - 1) / kTextPart);
  PetscCall(
      PetscViewerHDF5WriteAttribute(viewer, "/", (name + "_parts").c_str(), PETSC_INT, &parts));
  for (PetscInt i = 0; i < parts; ++i) {
    const std::string part = text.substr(i * kTextPart, kTextPart);
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", (name + "_" + std::to_string(i)).c_str(),
                                            PETSC_STRING, part.c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readString(PetscViewer viewer, const char *parent, const std::string &name,
                          std::string *value)
{
  char *text = nullptr;
  PetscFunctionBeginUser;
  PetscCall(
      PetscViewerHDF5ReadAttribute(viewer, parent, name.c_str(), PETSC_STRING, nullptr, &text));
  *value = text ? text : "";
  PetscCall(PetscFree(text));
  PetscFunctionReturn(0);
}

PetscErrorCode readText(PetscViewer viewer, const std::string &name, std::string *text)
{
  PetscInt parts = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", (name + "_parts").c_str(), PETSC_INT, nullptr,
                                         &parts));
  text->clear();
  for (PetscInt i = 0; i < parts; ++i) {
    std::string part;
    PetscCall(readString(viewer, "/", name + "_" + std::to_string(i), &part));
    *text += part;
  }
  PetscFunctionReturn(0);
}

/// Loads dataset `name` whole, spread over the ranks as PETSc chooses, and compares it with
/// its checksum. *v is the caller's to destroy (also after an error).
PetscErrorCode checkDataset(MPI_Comm comm, PetscViewer viewer, const char *name, Vec *v,
                            bool *intact)
{
  PetscInt bs, size, n;
  const PetscScalar *a;
  std::string sum, stored;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5ReadSizes(viewer, name, &bs, &size));
  PetscCall(VecCreateMPI(comm, PETSC_DECIDE, size, v));
  PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscCall(VecLoad(*v, viewer));
  PetscCall(VecGetLocalSize(*v, &n));
  PetscCall(VecGetArrayRead(*v, &a));
  PetscCall(valuesChecksum(comm, a, n, &sum));
  PetscCall(VecRestoreArrayRead(*v, &a));
  PetscCall(readString(viewer, name, "checksum", &stored));
  *intact = sum == stored;
  PetscFunctionReturn(0);
}

/// The checks of verifyCheckpoint on an open file; an error here is HDF5 failing to read.
PetscErrorCode checkContents(MPI_Comm comm, PetscViewer viewer, std::string *damage)
{
  CheckpointHeader header;
  bool intact = false;
  PetscFunctionBeginUser;
  PetscCall(readHeader(viewer, &header, &intact));
  if (header.version != kCheckpointVersion) PetscFunctionReturn(0); // not ours: the reader says
  if (!intact) {
    *damage = "its attributes do not match their checksum";
    PetscFunctionReturn(0);
  }
  std::vector<std::string> names(std::begin(kDatasets), std::end(kDatasets));
  PetscBool skeleton = PETSC_FALSE;
  PetscCall(PetscViewerHDF5HasDataset(viewer, "skeleton_history", &skeleton));
  if (skeleton) names.emplace_back("skeleton_history");
  if (header.interface_output_count >= 0) names.emplace_back("interface_output_times");
  for (const std::string &name : names) {
    PetscBool has = PETSC_FALSE;
    PetscCall(PetscViewerHDF5HasDataset(viewer, name.c_str(), &has));
    if (!has) {
      *damage = "dataset '" + name + "' is missing";
      PetscFunctionReturn(0);
    }
    Vec v = nullptr;
    const PetscErrorCode failed = checkDataset(comm, viewer, name.c_str(), &v, &intact);
    PetscCall(VecDestroy(&v));
    PetscCall(failed);
    if (!intact) {
      *damage = "dataset '" + name + "' does not match its checksum";
      PetscFunctionReturn(0);
    }
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode writeHeader(PetscViewer viewer, const CheckpointHeader &h)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "version", PETSC_INT, &h.version));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "ranks", PETSC_INT, &h.ranks));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "step", PETSC_INT, &h.step));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "output_count", PETSC_INT, &h.output_count));
  if (h.interface_output_count >= 0)
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "interface_output_count", PETSC_INT,
                                            &h.interface_output_count));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "time", PETSC_REAL, &h.time));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "next_dt", PETSC_REAL, &h.next_dt));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "last_dt", PETSC_REAL, &h.last_dt));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "first_contraction", PETSC_REAL,
                                          &h.first_contraction));
  PetscCall(
      PetscViewerHDF5WriteAttribute(viewer, "/", "integrator", PETSC_STRING, h.integrator.c_str()));
  PetscCall(writeText(viewer, "options", h.options));
  PetscCall(writeText(viewer, "option_files", h.option_files));
  PetscCall(writeText(viewer, "output_files", h.output_files));
  const std::string sum = headerChecksum(h);
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "checksum", PETSC_STRING, sum.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode readHeader(PetscViewer viewer, CheckpointHeader *h, bool *intact)
{
  PetscBool has = PETSC_FALSE;
  PetscFunctionBeginUser;
  *intact = false;
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "version", PETSC_INT, nullptr, &h->version));
  PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "checksum", &has));
  if (!has) PetscFunctionReturn(0); // earlier versions have none
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "ranks", PETSC_INT, nullptr, &h->ranks));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "step", PETSC_INT, nullptr, &h->step));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "output_count", PETSC_INT, nullptr,
                                         &h->output_count));
  PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "interface_output_count", &has));
  h->interface_output_count = -1;
  if (has)
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "interface_output_count", PETSC_INT,
                                           nullptr, &h->interface_output_count));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "time", PETSC_REAL, nullptr, &h->time));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "next_dt", PETSC_REAL, nullptr, &h->next_dt));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "last_dt", PETSC_REAL, nullptr, &h->last_dt));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "first_contraction", PETSC_REAL, nullptr,
                                         &h->first_contraction));
  PetscCall(readString(viewer, "/", "integrator", &h->integrator));
  PetscCall(readText(viewer, "options", &h->options));
  PetscCall(readText(viewer, "option_files", &h->option_files));
  PetscCall(readText(viewer, "output_files", &h->output_files));
  std::string stored;
  PetscCall(readString(viewer, "/", "checksum", &stored));
  *intact = stored == headerChecksum(*h);
  PetscFunctionReturn(0);
}

PetscErrorCode valuesChecksum(MPI_Comm comm, const double *values, PetscInt n, std::string *sum)
{
  PetscMPIInt rank;
  long long count = n, first = 0;
  std::uint64_t mine = 0, all = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Exscan(&count, &first, 1, MPI_LONG_LONG, MPI_SUM, comm));
  if (rank == 0) first = 0; // MPI_Exscan leaves rank 0's result undefined
  for (PetscInt i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, &values[i], sizeof bits);
    mine += mix(bits ^ mix((std::uint64_t)(first + i))); // modulo 2^64
  }
  PetscCallMPI(MPI_Allreduce(&mine, &all, 1, MPI_UINT64_T, MPI_SUM, comm));
  *sum = hex(all);
  PetscFunctionReturn(0);
}

PetscErrorCode verifyCheckpoint(MPI_Comm comm, const std::string &path, std::string *damage)
{
  PetscFunctionBeginUser;
  // A damaged file makes HDF5 print its error stack and PETSc its traceback: silence both
  // while looking, and say what was found in one line (the caller).
  H5E_auto2_t hdf5_report = nullptr;
  void *hdf5_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &hdf5_report, &hdf5_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  PetscViewer viewer = nullptr;
  std::string found;
  // Every rank reads the same bytes of the header and metadata, so HDF5 fails (or not) on
  // every rank at the same call; a checksum is summed over all ranks, so all see a mismatch.
  // HDF5 alone first (each rank, no MPI-IO): a file it cannot open, cut short for one, would
  // leave PETSc a viewer it cannot destroy.
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  PetscErrorCode failed = file < 0;
  if (file >= 0) H5Fclose(file);
  if (!failed) failed = PetscViewerHDF5Open(comm, path.c_str(), FILE_MODE_READ, &viewer);
  if (!failed) failed = checkContents(comm, viewer, &found);
  if (viewer) (void)PetscViewerDestroy(&viewer); // its error, if any, is the one above
  PetscCall(PetscPopErrorHandler());
  H5Eset_auto2(H5E_DEFAULT, hdf5_report, hdf5_data);
  if (failed) found = "HDF5 cannot read it: cut short or corrupted";
  int bad = !found.empty(), any = 0;
  PetscCallMPI(MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, comm));
  *damage = any && found.empty() ? "another rank cannot read its part" : found;
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
