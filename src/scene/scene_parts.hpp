// The parts of readSceneOptions that live in their own files (one concept per file).
#pragma once

#include "poroseam/scene.hpp"

#include <petscsys.h>

namespace poroseam {

/// A region's options, in its own -help section (PetscOptionsBegin in readSceneOptions).
/// `geostatic`: the scene starts from the geostatic state (K0 is used).
PetscErrorCode readRegion(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, Region &r,
                          bool drained, bool geostatic);

/// An interface's options, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readInterface(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                             const std::vector<PhysicalName> &names, int dim, const Scene &scene,
                             Interface &i);

/// A boundary's conditions, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readBoundary(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const Scene &scene,
                            const Boundary &b, std::vector<BoundaryCondition> &out);

/// A name of -boundaries: a face group (dimension dim - 1), else a physical point (dimension
/// 0) or, in 3D, a physical curve (dimension 1): supports, prescribed displacements only.
PetscErrorCode findBoundaryGroup(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                                 const std::string &name, Boundary *b);

/// A list option names each item once, and no item is empty ("-regions soil,,rock").
PetscErrorCode checkListNames(MPI_Comm comm, const std::string &option,
                              const std::vector<std::string> &items);

/// The tag of the physical group `name` of dimension `dim`, or an error naming `option` and
/// the groups the mesh has.
PetscErrorCode findPhysical(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                            const std::string &name, const char *option, const char *what,
                            int *tag);

/// A number as %g writes it (PETSc's own %g in messages adds a trailing dot: "5.").
std::string number(double v);

/// The names of the mesh's physical groups of dimension `dim`, comma separated ("(none)").
std::string joinNames(const std::vector<PhysicalName> &names, int dim);

} // namespace poroseam
