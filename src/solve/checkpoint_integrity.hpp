// Whether a checkpoint file is whole (docs/checkpoints.md, "Damaged checkpoints"). Every
// dataset of a checkpoint carries a checksum of its values (attribute `checksum`), and the file's
// attributes one of them all (root attribute `checksum`): a bit flipped on disk, a file cut
// short or one HDF5 cannot read is found before a restart uses it, and the restart falls back
// to the checkpoint before it instead of continuing a different computation. Internal to
// src/solve.
#pragma once

#include <petscviewer.h>
#include <string>

namespace poroseam {
namespace simulation_detail {

/// Format of the file; a checkpoint of another version is refused, not misread.
/// 2: the interface history holds the accumulated plastic slip (5 values per point).
/// 3: checksums of every dataset and of the attributes; the run's options, the files its
///    options name (content hashes) and the output files it was writing.
constexpr PetscInt kCheckpointVersion = 3;

/// What a checkpoint says about its run besides the vectors: its root attributes.
struct CheckpointHeader {
  PetscInt version = kCheckpointVersion, ranks = 0, step = 0, output_count = 0;
  /// Times in the interface files (-1: a checkpoint written before -output_interfaces_every,
  /// without the attribute and its dataset `interface_output_times`).
  PetscInt interface_output_count = -1;
  double time = 0.0, next_dt = 0.0, last_dt = 0.0, first_contraction = 0.0;
  std::string integrator;
  /// The options the run was given, one "-name value" a line (an options file: restart_check.hpp)
  std::string options;
  /// "-name <content hash>" a line, for each of those options whose value names a file
  std::string option_files;
  /// The output files (names in the output directory) that existed when it was written
  std::string output_files;
};

/// Writes the header's attributes and their checksum. Collective (the header is the same on
/// every rank).
PetscErrorCode writeHeader(PetscViewer viewer, const CheckpointHeader &header);

/// Reads the header. *intact says whether the attributes match their checksum (false also
/// for a file without one: another version, see header->version). Collective.
PetscErrorCode readHeader(PetscViewer viewer, CheckpointHeader *header, bool *intact);

/// The checksum of a distributed array (this rank's `n` values; the ranks hold consecutive
/// parts in rank order): each value hashed with its global index and the hashes summed, so
/// that the checksum does not depend on how the array is split among ranks and a file can be
/// verified whatever the layout of the reader. 16 hexadecimal digits. Collective.
PetscErrorCode valuesChecksum(MPI_Comm comm, const double *values, PetscInt n, std::string *sum);

/// Whether the checkpoint file `path` is whole: HDF5 opens it, every dataset reads back and
/// matches its checksum, and so do the attributes. *damage is empty when it is, otherwise
/// what is wrong, in a few words. Prints nothing (neither HDF5's error stack nor PETSc's
/// traceback). Collective: every rank gets the same verdict.
PetscErrorCode verifyCheckpoint(MPI_Comm comm, const std::string &path, std::string *damage);

} // namespace simulation_detail
} // namespace poroseam
