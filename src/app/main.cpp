// poroseam: hydro-mechanical finite elements for saturated soils, on PETSc.
//   mpiexec -n 2 poroseam -options_file options/<scene>.opts [PETSc options]
#include "poroseam/scene.hpp"
#include "poroseam/simulation.hpp"

#include <cstdio>
#include <petscsys.h>

static const char help[] = "poroseam: Biot consolidation with zero-thickness hydro-mechanical "
                           "interfaces.\nUsage: poroseam -options_file options/<scene>.opts\n";

/// Bad input and a run that cannot go on are the user's to fix, not ours to debug: say what
/// is wrong in one line, without PETSc's traceback. Everything else keeps the traceback.
static PetscErrorCode reportError(MPI_Comm comm, int line, const char *func, const char *file,
                                  PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  if (n != PETSC_ERR_USER_INPUT && n != PETSC_ERR_NOT_CONVERGED)
    return PetscTraceBackErrorHandler(comm, line, func, file, n, p, mess, ctx);
  if (p == PETSC_ERROR_INITIAL) {
    int rank = 0;
    if (comm != MPI_COMM_NULL && comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
    if (rank == 0) std::fprintf(stderr, "poroseam: error: %s\n", mess);
  }
  return n;
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PetscPushErrorHandler(reportError, nullptr));
  PetscBool help_requested = PETSC_FALSE, has_mesh = PETSC_FALSE;
  PetscCall(PetscOptionsHasHelp(nullptr, &help_requested));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-mesh", &has_mesh));
  if (help_requested) poroseam::printSceneHelp(PETSC_COMM_WORLD);
  PetscErrorCode error = 0;
  if (!help_requested || has_mesh) error = poroseam::runSimulation(PETSC_COMM_WORLD);
  if (error && error != PETSC_ERR_USER_INPUT && error != PETSC_ERR_NOT_CONVERGED) {
    // An internal error may be on one rank only: the others cannot be waited for.
    MPI_Abort(PETSC_COMM_WORLD, (int)error);
  }
  // Input errors and failed runs are detected on every rank together: finish cleanly.
  PetscCall(PetscFinalize());
  return error ? 1 : 0;
}
