// The order in which the writers put vertices, cells and integration points into the HDF5
// files: by a partition-independent number (the serial mesh's point numbers,
// serialPointNumbers in mesh.hpp), not by rank, so that the same run writes the same files on
// any number of ranks and any partition (issue 23). Internal to src/output.
#pragma once

#include <petscsf.h>
#include <vector>

namespace poroseam {

/// Global positions of the entries of keyed blocks: every rank has blocks (e.g. cells) with a
/// unique key and a length (1 for the cell itself, its node count for its nodes, ...); the
/// blocks of all ranks are put in increasing key order and their entries numbered through.
/// position[j] is the global position of this rank's j-th entry (its blocks in its order, each
/// block's entries in order). Collective.
PetscErrorCode positionsByKey(MPI_Comm comm, const std::vector<PetscInt> &keys,
                              const std::vector<PetscInt> &lengths,
                              std::vector<PetscInt> &position);

/// Moves rows to their global positions: a rank's rows (in its order) go to the rank and place
/// that hold their position, each rank holding as many rows as it gives, in position order
/// (rank 0 the first ones). Then writing every rank's rows in rank order writes them in
/// position order.
class OutputOrder {
public:
  OutputOrder() = default;
  OutputOrder(const OutputOrder &) = delete;
  OutputOrder &operator=(const OutputOrder &) = delete;
  ~OutputOrder() { (void)PetscSFDestroy(&sf_); }

  /// position[i]: global position of this rank's row i; together a permutation of 0..N-1.
  /// Collective.
  PetscErrorCode setup(MPI_Comm comm, const std::vector<PetscInt> &position);
  /// Rows of bs values, in place (collective).
  PetscErrorCode permute(std::vector<PetscScalar> &rows, PetscInt bs) const;
  PetscErrorCode permute(std::vector<PetscInt> &rows, PetscInt bs) const;
  PetscErrorCode destroy() { return PetscSFDestroy(&sf_); }

private:
  template <class T> PetscErrorCode move(std::vector<T> &rows, PetscInt bs, MPI_Datatype) const;
  PetscSF sf_ = nullptr;
  PetscInt rows_ = 0;
};

} // namespace poroseam
