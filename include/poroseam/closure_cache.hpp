// Closure indices of the cells an assembly loop visits, computed once at setup. Reading a
// closure with DMPlexVecGetClosure or adding one with DMPlexVecSetClosure/DMPlexMatSetClosure
// rebuilds the cell's transitive closure (cone walks, cell-type label lookups) on every call:
// on the 3D caisson that was a third of all assembly instructions. The cache holds, per cell,
// the offsets of its closure dofs in the local solution vector and in the local coordinate
// vector, in the order those functions use; global matrix indices come from one
// local-to-global array (one entry per local dof), so the cache costs a few hundred bytes per
// cell.
#pragma once

#include <petscdmplex.h>
#include <vector>

namespace poroseam {

class ClosureCache {
public:
  /// Caches the closures of `points` (cells) of `dm`, which must have its local section.
  PetscErrorCode setup(DM dm, const std::vector<PetscInt> &points);

  size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  /// Number of dofs in the closure of entry i.
  int closureSize(size_t i) const { return (int)(start_[i + 1] - start_[i]); }
  /// Local-vector offsets of entry i's closure dofs, in closure (field by field) order.
  const PetscInt *local(size_t i) const { return &local_[start_[i]]; }
  /// Local coordinate-vector offsets of entry i's closure (vertex by vertex, dim each).
  const PetscInt *coordinates(size_t i) const { return &coordinates_[coordinate_start_[i]]; }
  int coordinateSize(size_t i) const
  {
    return (int)(coordinate_start_[i + 1] - coordinate_start_[i]);
  }
  /// Global row/column indices of entry i's closure, as DMPlexMatSetClosure uses them
  /// (negative for constrained dofs, which MatSetValues skips). `indices` has closureSize(i).
  void globalIndices(size_t i, PetscInt *indices) const
  {
    const PetscInt *l = local(i);
    for (int k = 0, n = closureSize(i); k < n; ++k)
      indices[k] = global_of_local_[l[k]];
  }

private:
  std::vector<PetscInt> start_, local_;
  std::vector<PetscInt> coordinate_start_, coordinates_;
  std::vector<PetscInt> global_of_local_;
};

/// x[k] = array[offsets[k]], k < n: a closure read from a local array.
inline void gatherClosure(const PetscScalar *array, const PetscInt *offsets, int n, double *x)
{
  for (int k = 0; k < n; ++k)
    x[k] = array[offsets[k]];
}

/// array[offsets[k]] += F[k], k < n: DMPlexVecSetClosure with ADD_ALL_VALUES on a local array.
inline void addClosure(const double *F, const PetscInt *offsets, int n, PetscScalar *array)
{
  for (int k = 0; k < n; ++k)
    array[offsets[k]] += F[k];
}

} // namespace poroseam
