/* Reference solve for scripts/bench: what PETSc's own CG + GAMG does on an easy problem of the
 * same size as a caisson run, measured on the same machine in the same benchmark run, so the
 * caisson's linear solve can be priced against it.
 *
 * 3D linear elasticity (E = 200 MPa, nu = 0.3, rho = 2000 kg/m3, g = 9.81 m/s2 along -z) on a
 * box of Q1 hexahedra with 1 m edges (a DMDA with 3 dofs per node), clamped on its bottom face
 * z = 0 and loaded by its weight. CG + smoothed-aggregation GAMG with the six rigid-body modes
 * (MatNullSpaceCreateRigidBody from the DMDA coordinates) as near null space, block size 3,
 * relative tolerance 1e-8. Any -ksp_* / -pc_* option overrides these.
 *
 *   mpiexec -n R reference_elasticity -unknowns N [-repeat 3]
 *
 * chooses a box of about N unknowns (nx = ny, nz close to them), solves it `repeat` times with
 * fresh solver objects and prints one line:
 *   reference_elasticity unknowns N grid nx ny nz ranks R assembly_s A setup_s S solve_s T
 *   iterations I reason C
 * assembly_s: matrix and right-hand side (once); setup_s: KSPSetUp (the GAMG hierarchy) and
 * solve_s: KSPSolve, each the minimum over the repetitions. Wall times, the slowest rank. The
 * clamped dofs stay in the matrix as identity rows scaled like the diagonal (MatZeroRowsColumns),
 * so N counts them too. */
#include <math.h>
#include <petscdmda.h>
#include <petscksp.h>

static const double kYoung = 2e8, kPoisson = 0.3, kDensity = 2000.0, kGravity = 9.81;

/* Stiffness of a cube of edge h, nodes (ia, ja, ka) in {0,1}^3 numbered ia + 2 ja + 4 ka, dofs
 * 3 a + component, 2 x 2 x 2 Gauss points. */
static void cubeStiffness(double h, double K[24][24])
{
  const double lambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
  const double mu = kYoung / (2 * (1 + kPoisson));
  const double g = 1.0 / sqrt(3.0);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j)
      K[i][j] = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double xi[3] = {(q & 1) ? g : -g, (q & 2) ? g : -g, (q & 4) ? g : -g};
    double dN[8][3]; /* d N_a / d x = (2/h) d N_a / d xi */
    for (int a = 0; a < 8; ++a) {
      const double s[3] = {(a & 1) ? 1.0 : -1.0, (a & 2) ? 1.0 : -1.0, (a & 4) ? 1.0 : -1.0};
      for (int d = 0; d < 3; ++d) {
        double v = 0.125 * s[d] * 2.0 / h;
        for (int e = 0; e < 3; ++e)
          if (e != d) v *= 1.0 + s[e] * xi[e];
        dN[a][d] = v;
      }
    }
    const double w = h * h * h / 8.0; /* det J times the Gauss weight 1 */
    /* K_ab,ij = int lambda dNa_i dNb_j + mu (dNa_j dNb_i + delta_ij dNa . dNb) */
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        const double dot = dN[a][0] * dN[b][0] + dN[a][1] * dN[b][1] + dN[a][2] * dN[b][2];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            K[3 * a + i][3 * b + j] += w * (lambda * dN[a][i] * dN[b][j] +
                                            mu * (dN[a][j] * dN[b][i] + (i == j ? dot : 0.0)));
      }
  }
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscInt target = 37000, repeat = 3;
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-unknowns", &target, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-repeat", &repeat, NULL));
  /* A box nx = ny, nz: as close to a cube as the target allows. */
  const PetscInt nodes = PetscMax(8, target / 3);
  PetscInt nx = (PetscInt)floor(cbrt((double)nodes) + 0.5);
  nx = PetscMax(2, nx);
  PetscInt nz = PetscMax(2, (PetscInt)floor((double)nodes / (double)(nx * nx) + 0.5));
  MPI_Comm comm = PETSC_COMM_WORLD;
  PetscMPIInt ranks;
  PetscCallMPI(MPI_Comm_size(comm, &ranks));

  DM da;
  PetscCall(DMDACreate3d(comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE,
                         DMDA_STENCIL_BOX, nx, nx, nz, PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE, 3,
                         1, NULL, NULL, NULL, &da));
  PetscCall(DMSetFromOptions(da));
  PetscCall(DMSetUp(da));
  PetscCall(
      DMDAGetInfo(da, NULL, &nx, NULL, &nz, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
  const double h = 1.0;
  PetscCall(DMDASetUniformCoordinates(da, 0.0, (nx - 1) * h, 0.0, (nx - 1) * h, 0.0, (nz - 1) * h));

  Mat A;
  Vec x, b;
  PetscCall(DMCreateMatrix(da, &A)); /* block size 3 from the DMDA's dofs */
  PetscCall(DMCreateGlobalVector(da, &x));
  PetscCall(DMCreateGlobalVector(da, &b));

  PetscCallMPI(MPI_Barrier(comm));
  double t0 = MPI_Wtime();
  double K[24][24];
  cubeStiffness(h, K);
  PetscInt xs, ys, zs, xm, ym, zm;
  PetscCall(DMDAGetCorners(da, &xs, &ys, &zs, &xm, &ym, &zm));
  Vec bl;
  PetscCall(DMGetLocalVector(da, &bl));
  PetscCall(VecSet(bl, 0.0));
  PetscScalar ****f;
  PetscCall(DMDAVecGetArrayDOF(da, bl, &f));
  const double nodal_weight = kDensity * kGravity * h * h * h / 8.0;
  /* Each rank assembles the elements whose lowest corner it owns; the ghost layer holds the
   * other corners. */
  for (PetscInt k = zs; k < zs + zm && k < nz - 1; ++k)
    for (PetscInt j = ys; j < ys + ym && j < nx - 1; ++j)
      for (PetscInt i = xs; i < xs + xm && i < nx - 1; ++i) {
        MatStencil idx[24];
        for (int a = 0; a < 8; ++a)
          for (int c = 0; c < 3; ++c) {
            idx[3 * a + c].i = i + (a & 1);
            idx[3 * a + c].j = j + ((a >> 1) & 1);
            idx[3 * a + c].k = k + ((a >> 2) & 1);
            idx[3 * a + c].c = c;
          }
        PetscCall(MatSetValuesStencil(A, 24, idx, 24, idx, &K[0][0], ADD_VALUES));
        for (int a = 0; a < 8; ++a)
          f[k + ((a >> 2) & 1)][j + ((a >> 1) & 1)][i + (a & 1)][2] -= nodal_weight;
      }
  PetscCall(DMDAVecRestoreArrayDOF(da, bl, &f));
  PetscCall(VecSet(b, 0.0));
  PetscCall(DMLocalToGlobal(da, bl, ADD_VALUES, b));
  PetscCall(DMRestoreLocalVector(da, &bl));
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  /* Clamp z = 0: identity rows and columns, scaled like an interior diagonal (8 elements). */
  {
    const PetscInt count = (zs == 0) ? 3 * xm * ym : 0;
    MatStencil *rows;
    PetscCall(PetscMalloc1(count + 1, &rows));
    PetscInt n = 0;
    for (PetscInt j = ys; j < ys + ym && count; ++j)
      for (PetscInt i = xs; i < xs + xm; ++i)
        for (int c = 0; c < 3; ++c) {
          rows[n].i = i, rows[n].j = j, rows[n].k = 0, rows[n].c = c;
          ++n;
        }
    PetscCall(VecSet(x, 0.0));
    PetscCall(MatZeroRowsColumnsStencil(A, n, rows, 8.0 * K[0][0], x, b));
    PetscCall(PetscFree(rows));
  }
  PetscCall(MatSetOption(A, MAT_SPD, PETSC_TRUE));
  MatNullSpace rigid;
  Vec coords;
  PetscCall(DMGetCoordinates(da, &coords));
  PetscCall(MatNullSpaceCreateRigidBody(coords, &rigid));
  PetscCall(MatSetNearNullSpace(A, rigid));
  PetscCall(MatNullSpaceDestroy(&rigid));
  PetscCallMPI(MPI_Barrier(comm));
  const double assembly = MPI_Wtime() - t0;

  /* Fresh solver objects each time; the fastest repetition counts (the machine is shared). */
  double setup = 1e30, solve = 1e30;
  PetscInt its = 0;
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  for (PetscInt r = 0; r < repeat; ++r) {
    KSP ksp;
    PC pc;
    PetscCall(KSPCreate(comm, &ksp));
    PetscCall(KSPSetOperators(ksp, A, A));
    PetscCall(KSPSetType(ksp, KSPCG));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCGAMG));
    PetscCall(KSPSetTolerances(ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 1000));
    PetscCall(KSPSetFromOptions(ksp));
    PetscCall(VecSet(x, 0.0));
    PetscCallMPI(MPI_Barrier(comm));
    t0 = MPI_Wtime();
    PetscCall(KSPSetUp(ksp));
    PetscCallMPI(MPI_Barrier(comm));
    setup = PetscMin(setup, MPI_Wtime() - t0);
    t0 = MPI_Wtime();
    PetscCall(KSPSolve(ksp, b, x));
    PetscCallMPI(MPI_Barrier(comm));
    solve = PetscMin(solve, MPI_Wtime() - t0);
    PetscCall(KSPGetIterationNumber(ksp, &its));
    PetscCall(KSPGetConvergedReason(ksp, &reason));
    PetscCall(KSPDestroy(&ksp));
  }
  PetscInt size;
  PetscCall(MatGetSize(A, &size, NULL));
  PetscCall(PetscPrintf(comm,
                        "reference_elasticity unknowns %" PetscInt_FMT " grid %" PetscInt_FMT
                        " %" PetscInt_FMT " %" PetscInt_FMT " ranks %d assembly_s %.6e setup_s "
                        "%.6e solve_s %.6e iterations %" PetscInt_FMT " reason %s\n",
                        size, nx, nx, nz, (int)ranks, assembly, setup, solve, its,
                        KSPConvergedReasons[reason]));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&A));
  PetscCall(DMDestroy(&da));
  PetscCall(PetscFinalize());
  return 0;
}
