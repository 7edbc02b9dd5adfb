/* The displacement block alone: how fast does an AMG solve it?
 *
 * Reads what `-fieldsplit_displacement_vertex_blocks_dump_operator FILE` wrote during a run
 * of poroseam with options/solvers/fieldsplit.opts (src/solve/vertex_blocks.cpp): the
 * displacement block with whole vertex blocks (block size -dim), its near-null-space vectors
 * (rigid-body modes, scaled like the operator), the unscaled Jacobian diagonal and the vertex
 * coordinates. Solves A x = A x_random (seed 7) to -ksp_rtol 1e-8 with GMRES and the
 * preconditioner given on the command line (default GAMG with the near null space), and prints
 * iterations, set-up and solve times and the true relative residual. Any KSP/PC option
 * applies, e.g. -pc_type ml, -pc_type hypre, -pc_gamg_threshold 0.05, -ksp_view_eigenvalues.
 *
 *   mpiexec -n 2 build/bench/displacement_block -f block.bin -pc_gamg_threshold 0.05 \
 *     -mg_levels_ksp_max_it 3
 *
 * Used for the measurements of README "Solvers" (the displacement block's AMG rate against
 * PETSc's elastic box of the same size, bench/reference_elasticity.c). Wall times: one run,
 * the machine's noise applies; compare iteration counts.
 */
#include <petscksp.h>

int main(int argc, char **argv)
{
  char file[PETSC_MAX_PATH_LEN] = "";
  PetscInt dim = 3, nmodes = -1, N, its;
  PetscBool set, use_modes = PETSC_TRUE;
  PetscViewer viewer;
  Mat A;
  Vec modes[6], x, b, r;
  KSP ksp;
  PetscRandom rnd;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-f", file, sizeof file, &set));
  PetscCheck(set, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "give -f FILE, written by poroseam's "
             "-fieldsplit_displacement_vertex_blocks_dump_operator FILE");
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-dim", &dim, NULL));
  PetscCheck(dim == 2 || dim == 3, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "-dim %" PetscInt_FMT ": expected 2 or 3", dim);
  nmodes = dim == 3 ? 6 : 3;
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-nmodes", &nmodes, NULL)); /* axisymmetric runs: 2 */
  PetscCheck(nmodes >= 0 && nmodes <= 6, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "-nmodes %" PetscInt_FMT ": expected 0..6", nmodes);
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-use_modes", &use_modes, NULL));

  PetscCall(PetscViewerBinaryOpen(PETSC_COMM_WORLD, file, FILE_MODE_READ, &viewer));
  PetscCall(MatCreate(PETSC_COMM_WORLD, &A));
  PetscCall(MatSetBlockSize(A, dim));
  PetscCall(MatSetFromOptions(A));
  PetscCall(MatLoad(A, viewer));
  for (PetscInt m = 0; m < nmodes; ++m) {
    PetscCall(MatCreateVecs(A, &modes[m], NULL));
    PetscCall(VecLoad(modes[m], viewer));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  if (use_modes && nmodes > 0) {
    MatNullSpace space;
    PetscCall(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, nmodes, modes, &space));
    PetscCall(MatSetNearNullSpace(A, space));
    PetscCall(MatNullSpaceDestroy(&space));
  }
  PetscCall(MatGetSize(A, &N, NULL));

  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(PetscRandomSetSeed(rnd, 7));
  PetscCall(PetscRandomSeed(rnd));
  PetscCall(VecSetRandom(x, rnd));
  PetscCall(MatMult(A, x, b));
  PetscCall(VecSet(x, 0.0));

  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  {
    PC pc;
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCGAMG));
  }
  PetscCall(KSPSetTolerances(ksp, 1e-8, 1e-50, PETSC_DEFAULT, 1000));
  PetscCall(KSPSetFromOptions(ksp));
  {
    PetscLogDouble t0, t1, t2;
    PetscReal rnorm, bnorm;
    KSPConvergedReason reason;
    PetscCall(PetscTime(&t0));
    PetscCall(KSPSetUp(ksp));
    PetscCall(PetscTime(&t1));
    PetscCall(KSPSolve(ksp, b, x));
    PetscCall(PetscTime(&t2));
    PetscCall(KSPGetIterationNumber(ksp, &its));
    PetscCall(KSPGetConvergedReason(ksp, &reason));
    PetscCall(MatMult(A, x, r));
    PetscCall(VecAYPX(r, -1.0, b));
    PetscCall(VecNorm(r, NORM_2, &rnorm));
    PetscCall(VecNorm(b, NORM_2, &bnorm));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                          "displacement_block unknowns %" PetscInt_FMT " iterations %" PetscInt_FMT
                          " reason %s setup_s %.3f solve_s %.3f "
                          "us_per_unknown_per_iteration %.3f true_relative_residual %.2e\n",
                          N, its, KSPConvergedReasons[reason], t1 - t0, t2 - t1,
                          1e6 * (t2 - t1) / (double)N / (double)(its ? its : 1),
                          (double)(rnorm / bnorm)));
  }
  PetscCall(KSPDestroy(&ksp));
  for (PetscInt m = 0; m < nmodes; ++m)
    PetscCall(VecDestroy(&modes[m]));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&r));
  PetscCall(MatDestroy(&A));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(PetscFinalize());
  return 0;
}
