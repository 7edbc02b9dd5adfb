// poroseam: hydro-mechanical finite elements for saturated soils, on PETSc.
//   mpiexec -n 2 poroseam -options_file options/<scene>.opts [PETSc options]
#include "poroseam/scene.hpp"
#include "poroseam/simulation.hpp"

#include <petscsys.h>

static const char help[] = "poroseam: Biot consolidation with zero-thickness hydro-mechanical "
                           "interfaces.\nUsage: poroseam -options_file options/<scene>.opts\n";

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscBool help_requested = PETSC_FALSE, has_mesh = PETSC_FALSE;
  PetscCall(PetscOptionsHasHelp(nullptr, &help_requested));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-mesh", &has_mesh));
  if (help_requested) poroseam::printSceneHelp(PETSC_COMM_WORLD);
  if (!help_requested || has_mesh) PetscCall(poroseam::runSimulation(PETSC_COMM_WORLD));
  PetscCall(PetscFinalize());
  return 0;
}
