// `poroseam -options_file <scene> -help`: the run is set up as far as every option is read
// (scene, mesh, partitioning, time stepping, Newton, linear solver), so that PETSc's -help
// lists each option with its current value and description, and stops before the first step.
// Nothing is written to the output directory: the mesh gmsh makes from a .geo goes to a
// scratch directory, removed at the end.
#pragma once

#include <petscsys.h>
#include <string>

namespace poroseam {

/// Whether this run only lists its options (-help was given).
PetscErrorCode listingOptions(bool *listing);

/// Collective. Rank 0 creates a scratch directory (under $TMPDIR or /tmp) that stands in for
/// the output directory while the options are listed; every rank learns its name.
PetscErrorCode beginOptionListing(MPI_Comm comm, std::string *scratch_dir);

/// Collective. Removes the scratch directory and says what -help did.
PetscErrorCode endOptionListing(MPI_Comm comm, const std::string &scratch_dir,
                                const std::string &output_dir);

} // namespace poroseam
