#include "poroseam/partition.hpp"

#include "poroseam/interfaces.hpp"
#include "poroseam/scene_options.hpp"

#include <map>
#include <metis.h>
#include <vector>

namespace poroseam {

PetscErrorCode readPartitionerOption(MPI_Comm comm, PartitionerKind *kind, std::string *name)
{
  char value[64] = "ptscotch";
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam partitioning", kSceneDoc);
  const OptionSpec &option = spec(Option::partitioner);
  PetscCall(PetscOptionsString(option.flag, option.help, option.doc, option.default_shown, value,
                               sizeof(value), &set));
  PetscOptionsEnd();
  const std::string v = value;
  if (v == "ptscotch")
    *kind = PartitionerKind::ptscotch;
  else if (v == "metis")
    *kind = PartitionerKind::metis;
  else if (v == "simple")
    *kind = PartitionerKind::simple;
  else
    SETERRQ(comm, PETSC_ERR_USER_INPUT,
            "option -partitioner '%s': expected ptscotch, metis or simple", value);
  *name = v;
  PetscFunctionReturn(0);
}

namespace {

/// Rank 0: METIS k-way partition of the dual graph of the cells of the serial mesh into
/// `nparts`; part[c - cStart] = rank of cell c.
PetscErrorCode metisPartition(DM dm, PetscInt nparts, std::vector<idx_t> &part)
{
  PetscInt dim, cStart, cEnd, fStart, fEnd;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  const PetscInt n = cEnd - cStart;
  part.assign(n, 0);
  if (n == 0 || nparts == 1) PetscFunctionReturn(0);
  std::vector<char> cohesive(n, 0);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(dm, c, &t));
    cohesive[c - cStart] = isCohesive(t) ? 1 : 0;
  }
  // Cells sharing a face (its support): interior faces join two bulk cells, an interface face
  // joins a bulk cell and its cohesive cell, a lateral face of a cohesive cell joins two
  // cohesive cells. Repeated pairs are merged (weights added).
  std::vector<std::map<PetscInt, idx_t>> adjacent(n);
  for (PetscInt f = fStart; f < fEnd; ++f) {
    const PetscInt *support;
    PetscInt size;
    PetscCall(DMPlexGetSupportSize(dm, f, &size));
    PetscCall(DMPlexGetSupport(dm, f, &support));
    for (PetscInt i = 0; i < size; ++i)
      for (PetscInt j = i + 1; j < size; ++j) {
        const PetscInt a = support[i] - cStart, b = support[j] - cStart;
        if (a < 0 || a >= n || b < 0 || b >= n || a == b) continue;
        const idx_t w = cohesive[a] != cohesive[b] ? kCohesiveEdgeWeight : 1;
        adjacent[a][b] += w;
        adjacent[b][a] += w;
      }
  }
  std::vector<idx_t> xadj(n + 1, 0), adjncy, adjwgt;
  for (PetscInt c = 0; c < n; ++c) {
    for (const auto &[other, w] : adjacent[c]) {
      adjncy.push_back((idx_t)other);
      adjwgt.push_back(w);
    }
    xadj[c + 1] = (idx_t)adjncy.size();
  }
  idx_t nvtxs = (idx_t)n, ncon = 1, np = (idx_t)nparts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 0; // the same partition on every run
  if (adjncy.empty()) {           // METIS needs at least one edge: deal the cells out in blocks
    for (PetscInt c = 0; c < n; ++c)
      part[c] = (idx_t)(c * nparts / n);
    PetscFunctionReturn(0);
  }
  const int status =
      METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr,
                          adjwgt.data(), &np, nullptr, nullptr, options, &objval, part.data());
  PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB,
             "METIS_PartGraphKway failed (status %d) on a graph of %d cells", status, (int)n);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode configurePartitioner(DM dm, PartitionerKind kind)
{
  PetscPartitioner part;
  MPI_Comm comm;
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(DMPlexGetPartitioner(dm, &part));
  if (kind != PartitionerKind::metis) {
    PetscCall(PetscPartitionerSetType(
        part, kind == PartitionerKind::simple ? PETSCPARTITIONERSIMPLE : PETSCPARTITIONERPTSCOTCH));
    PetscCall(PetscPartitionerSetFromOptions(part));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  // The serial mesh lives on rank 0; any other rank holding cells would be a distributed
  // mesh, which METIS here does not partition.
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  int localError = 0, anyError = 0;
  std::vector<PetscInt> sizes(size, 0), points;
  if (rank == 0) {
    std::vector<idx_t> owner;
    PetscErrorCode ierr = metisPartition(dm, size, owner);
    if (ierr)
      localError = 1;
    else {
      for (idx_t r : owner)
        ++sizes[r];
      std::vector<PetscInt> next(size, 0);
      for (PetscMPIInt r = 1; r < size; ++r)
        next[r] = next[r - 1] + sizes[r - 1];
      points.assign(owner.size(), 0);
      for (size_t c = 0; c < owner.size(); ++c)
        points[next[owner[c]]++] = (PetscInt)c; // cell number, counted from cStart
    }
  } else if (cEnd > cStart) {
    localError = 2;
  }
  PetscCallMPI(MPI_Allreduce(&localError, &anyError, 1, MPI_INT, MPI_MAX, comm));
  PetscCheck(anyError != 1, comm, PETSC_ERR_LIB, "-partitioner metis: METIS failed on rank 0");
  PetscCheck(anyError != 2, comm, PETSC_ERR_SUP,
             "-partitioner metis needs the serial mesh (all cells on rank 0)");
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes.data(),
                                              points.empty() ? nullptr : points.data()));
  PetscFunctionReturn(0);
}

PetscErrorCode countSeparatedCohesiveCells(DM dm, PetscInt *separated, PetscInt *total)
{
  MPI_Comm comm;
  PetscInt cStart, cEnd;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscInt local[2] = {0, 0}, sum[2] = {0, 0};
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(dm, c, &t));
    if (!isCohesive(t)) continue;
    ++local[1];
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    bool apart = false;
    for (int s = 0; s < 2; ++s) { // faces of side - and side +: is their bulk cell here?
      const PetscInt *support;
      PetscInt n;
      PetscCall(DMPlexGetSupportSize(dm, cone[s], &n));
      PetscCall(DMPlexGetSupport(dm, cone[s], &support));
      bool found = false;
      for (PetscInt i = 0; i < n; ++i) {
        DMPolytopeType st;
        PetscCall(DMPlexGetCellType(dm, support[i], &st));
        if (!isCohesive(st)) found = true;
      }
      if (!found) apart = true;
    }
    if (apart) ++local[0];
  }
  PetscCallMPI(MPI_Allreduce(local, sum, 2, MPIU_INT, MPI_SUM, comm));
  *separated = sum[0];
  *total = sum[1];
  PetscFunctionReturn(0);
}

} // namespace poroseam
