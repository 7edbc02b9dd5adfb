// Partition-independent order of the output rows (see output_order.hpp).
#include "output_order.hpp"

#include <algorithm>
#include <numeric>

namespace poroseam {

PetscErrorCode positionsByKey(MPI_Comm comm, const std::vector<PetscInt> &keys,
                              const std::vector<PetscInt> &lengths, std::vector<PetscInt> &position)
{
  PetscMPIInt size, rank;
  PetscFunctionBeginUser;
  PetscCheck(keys.size() == lengths.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "positionsByKey: %zu keys, %zu lengths", keys.size(), lengths.size());
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // Every rank's (key, length) pairs on every rank: the outputs of poroseam's meshes are small
  // enough (a million cells: 16 MB) for the simplest exact way.
  const PetscMPIInt mine = (PetscMPIInt)(2 * keys.size());
  std::vector<PetscMPIInt> count(size), displ(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&mine, 1, MPI_INT, count.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r)
    displ[r + 1] = displ[r] + count[r];
  std::vector<PetscInt> pairs(mine), all(displ[size]);
  for (size_t i = 0; i < keys.size(); ++i)
    pairs[2 * i] = keys[i], pairs[2 * i + 1] = lengths[i];
  PetscCallMPI(MPI_Allgatherv(pairs.data(), mine, MPIU_INT, all.data(), count.data(), displ.data(),
                              MPIU_INT, comm));
  const size_t blocks = all.size() / 2;
  std::vector<size_t> order(blocks);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return all[2 * a] < all[2 * b]; });
  for (size_t k = 1; k < blocks; ++k)
    PetscCheck(all[2 * order[k]] != all[2 * order[k - 1]], PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "positionsByKey: key %" PetscInt_FMT " given twice", all[2 * order[k]]);
  std::vector<PetscInt> start(blocks); // first position of each block, by gathered index
  PetscInt next = 0;
  for (size_t b : order)
    start[b] = next, next += all[2 * b + 1];
  position.clear();
  const size_t base = (size_t)displ[rank] / 2;
  for (size_t i = 0; i < keys.size(); ++i)
    for (PetscInt k = 0; k < lengths[i]; ++k)
      position.push_back(start[base + i] + k);
  PetscFunctionReturn(0);
}

PetscErrorCode OutputOrder::setup(MPI_Comm comm, const std::vector<PetscInt> &position)
{
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCall(PetscSFDestroy(&sf_));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  rows_ = (PetscInt)position.size();
  std::vector<PetscInt> first(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&rows_, 1, MPIU_INT, first.data() + 1, 1, MPIU_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r)
    first[r + 1] += first[r];
  std::vector<PetscSFNode> target(rows_);
  for (PetscInt i = 0; i < rows_; ++i) {
    const PetscInt p = position[i];
    PetscCheck(p >= 0 && p < first[size], PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "OutputOrder: position %" PetscInt_FMT " outside 0..%" PetscInt_FMT, p,
               first[size] - 1);
    const PetscInt r =
        (PetscInt)(std::upper_bound(first.begin(), first.end(), p) - first.begin()) - 1;
    target[i].rank = r;
    target[i].index = p - first[r];
  }
  PetscCall(PetscSFCreate(comm, &sf_));
  PetscCall(PetscSFSetGraph(sf_, rows_, rows_, nullptr, PETSC_COPY_VALUES, target.data(),
                            PETSC_COPY_VALUES));
  PetscCall(PetscSFSetUp(sf_));
  PetscFunctionReturn(0);
}

template <class T>
PetscErrorCode OutputOrder::move(std::vector<T> &rows, PetscInt bs, MPI_Datatype type) const
{
  PetscFunctionBeginUser;
  PetscCheck(sf_, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "OutputOrder: not set up");
  PetscCheck(bs >= 1 && (PetscInt)rows.size() == rows_ * bs, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "OutputOrder: %zu values for %" PetscInt_FMT " rows of %" PetscInt_FMT, rows.size(),
             rows_, bs);
  std::vector<T> from(rows_), to(rows_);
  for (PetscInt k = 0; k < bs; ++k) { // one component at a time: plain MPI types
    for (PetscInt i = 0; i < rows_; ++i)
      from[i] = rows[i * bs + k];
    PetscCall(PetscSFReduceBegin(sf_, type, from.data(), to.data(), MPI_REPLACE));
    PetscCall(PetscSFReduceEnd(sf_, type, from.data(), to.data(), MPI_REPLACE));
    for (PetscInt i = 0; i < rows_; ++i)
      rows[i * bs + k] = to[i];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutputOrder::permute(std::vector<PetscScalar> &rows, PetscInt bs) const
{
  return move(rows, bs, MPIU_SCALAR);
}

PetscErrorCode OutputOrder::permute(std::vector<PetscInt> &rows, PetscInt bs) const
{
  return move(rows, bs, MPIU_INT);
}

} // namespace poroseam
