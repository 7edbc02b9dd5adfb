// `poroseam -options_file <scene> -help`: the run is set up as far as every option is read
// (scene, mesh, partitioning, time stepping, Newton, linear solver), so that PETSc's -help
// lists each option with its current value and description, and stops before the first step.
// Nothing is written to the output directory: the mesh gmsh makes from a .geo goes to a
// scratch directory, removed at the end (gmsh's log is kept there when gmsh failed).
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

/// Whether this run only lists its options (-help was given).
PetscErrorCode listingOptions(bool *listing);

/// The scratch directory (under $TMPDIR or /tmp) that stands in for the output directory
/// while the options are listed. Rank 0 removes it when the listing goes out of scope, also
/// after an error (a bad option found while listing), except gmsh's log after a listing that
/// failed with one (a .geo gmsh could not mesh): the error message names that file.
class OptionListing {
public:
  OptionListing() = default;
  OptionListing(const OptionListing &) = delete;
  OptionListing &operator=(const OptionListing &) = delete;
  ~OptionListing();

  /// Collective. Rank 0 creates the scratch directory; every rank learns its name, which
  /// replaces *output_dir.
  PetscErrorCode begin(MPI_Comm comm, std::string *output_dir);

  /// Collective. Removes the scratch directory and says what -help did; `output_dir` is the
  /// directory the scene names (untouched).
  PetscErrorCode end(MPI_Comm comm, const std::string &output_dir);

private:
  void remove(bool failed);
  std::string scratch_;
  bool owner_ = false; ///< rank 0, which created it
};

} // namespace poroseam
