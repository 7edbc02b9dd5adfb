// Choice of the mesh partitioner (option -partitioner) and the METIS partition that keeps
// cohesive cells on the rank of their bulk neighbours.
#pragma once

#include <petscdmplex.h>
#include <string>

namespace poroseam {

/// Partitioners of -partitioner: PETSc's ptscotch (default) and simple, or METIS on the dual
/// graph of the serial mesh with heavy cohesive-bulk edges (through PETSCPARTITIONERSHELL).
enum class PartitionerKind { ptscotch, metis, simple };

/// Reads -partitioner (collective; default ptscotch); a clear error for an unknown name.
PetscErrorCode readPartitionerOption(MPI_Comm comm, PartitionerKind *kind, std::string *name);

/// Weight of a dual-graph edge between a cohesive cell and a bulk neighbour for METIS (a bulk
/// to bulk or cohesive to cohesive edge weighs 1).
constexpr int kCohesiveEdgeWeight = 1000;

/// Collective. Sets the partitioner of the serial mesh `dm` (all cells on rank 0, as before
/// DMPlexDistribute) to the chosen kind. For metis, rank 0 builds the dual graph of the
/// cells (bulk and cohesive; adjacent when they share a face), partitions it with
/// METIS_PartGraphKway into the communicator size and hands the result to a shell
/// partitioner. For ptscotch and simple, PetscPartitionerSetFromOptions follows, so the PETSc
/// options -petscpartitioner_* still apply.
PetscErrorCode configurePartitioner(DM dm, PartitionerKind kind);

/// Collective, on a distributed mesh without overlap: the number of cohesive cells (summed
/// over ranks) that have a bulk neighbour on another rank, and the number of cohesive cells.
PetscErrorCode countSeparatedCohesiveCells(DM dm, PetscInt *separated, PetscInt *total);

} // namespace poroseam
