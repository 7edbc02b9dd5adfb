// Krylov convergence test with the mass-balance rows checked: see
// include/poroseam/mass_balance_test.hpp for why.

#include "poroseam/mass_balance_test.hpp"
#include "poroseam/option_registry.hpp"

#include "poroseam/layout.hpp"

#include <algorithm>
#include <cmath>

namespace poroseam {
namespace {

struct MassBalanceTest {
  void *petsc_test = nullptr; ///< context of KSPConvergedDefault
  IS mass_rows = nullptr;     ///< pressure and interface pressure rows (global indices)
  Vec weight = nullptr;       ///< D = |diag A|^-1/2 of this solve's operator (1 on zero entries)
  Vec work = nullptr, residual = nullptr;
};

PetscErrorCode destroyTest(void *ctx)
{
  auto *test = static_cast<MassBalanceTest *>(ctx);
  PetscFunctionBeginUser;
  PetscCall(KSPConvergedDefaultDestroy(test->petsc_test));
  PetscCall(ISDestroy(&test->mass_rows));
  PetscCall(VecDestroy(&test->weight));
  PetscCall(VecDestroy(&test->work));
  PetscCall(VecDestroy(&test->residual));
  delete test;
  PetscFunctionReturn(0);
}

/// Whether the weighted mass-balance residual meets the solve's tolerance: ||D r_p|| <=
/// max(rtol ||D b||, atol).
bool massBalanceConverged(double weighted_mass_residual, double weighted_rhs, double rtol,
                          double atol)
{
  return weighted_mass_residual <= std::max(rtol * weighted_rhs, atol);
}

/// D = |diag A|^-1/2 of the operator being solved (1 where the diagonal is 0).
PetscErrorCode computeWeight(KSP ksp, MassBalanceTest &test)
{
  Mat A;
  PetscInt n;
  PetscScalar *d;
  PetscFunctionBeginUser;
  PetscCall(KSPGetOperators(ksp, &A, nullptr));
  if (!test.weight) {
    PetscCall(MatCreateVecs(A, &test.weight, nullptr));
    PetscCall(VecDuplicate(test.weight, &test.work));
    PetscCall(VecDuplicate(test.weight, &test.residual));
  }
  PetscCall(MatGetDiagonal(A, test.weight));
  PetscCall(VecGetLocalSize(test.weight, &n));
  PetscCall(VecGetArray(test.weight, &d));
  for (PetscInt i = 0; i < n; ++i) {
    const double m = std::fabs(PetscRealPart(d[i]));
    d[i] = m > 0.0 ? 1.0 / std::sqrt(m) : 1.0;
  }
  PetscCall(VecRestoreArray(test.weight, &d));
  PetscFunctionReturn(0);
}

PetscErrorCode convergedWithMassBalance(KSP ksp, PetscInt it, PetscReal rnorm,
                                        KSPConvergedReason *reason, void *ctx)
{
  auto &test = *static_cast<MassBalanceTest *>(ctx);
  PetscFunctionBeginUser;
  if (it == 0) PetscCall(computeWeight(ksp, test)); // the operator is new at each solve
  PetscCall(KSPConvergedDefault(ksp, it, rnorm, reason, test.petsc_test));
  if (*reason <= 0 || it == 0) PetscFunctionReturn(0);
  Vec b, r, mass;
  PetscReal rtol, atol, weighted_rhs, weighted_mass;
  PetscCall(KSPGetRhs(ksp, &b));
  PetscCall(KSPBuildResidual(ksp, test.work, test.residual, &r));
  PetscCall(VecPointwiseMult(r, r, test.weight));
  PetscCall(VecGetSubVector(r, test.mass_rows, &mass));
  PetscCall(VecNorm(mass, NORM_2, &weighted_mass));
  PetscCall(VecRestoreSubVector(r, test.mass_rows, &mass));
  PetscCall(VecPointwiseMult(test.work, test.weight, b));
  PetscCall(VecNorm(test.work, NORM_2, &weighted_rhs));
  PetscCall(KSPGetTolerances(ksp, &rtol, &atol, nullptr, nullptr));
  if (!massBalanceConverged(weighted_mass, weighted_rhs, rtol, atol)) {
    PetscCall(PetscInfo(ksp,
                        "poroseam: iteration %" PetscInt_FMT ": mass-balance rows %g above %g, "
                        "iterating on\n",
                        it, (double)weighted_mass, (double)(rtol * weighted_rhs)));
    *reason = KSP_CONVERGED_ITERATING;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode configureMassBalanceTest(KSP ksp, DM dm)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)ksp);
  PetscBool use = PETSC_TRUE, direct, scaled;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam Krylov test",
                    "include/poroseam/mass_balance_test.hpp");
  const OptionSpec &option = spec(Option::mass_balance_krylov_test);
  PetscCall(PetscOptionsBool(option.flag, option.help, option.doc, use, &use, nullptr));
  PetscOptionsEnd();
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPPREONLY, &direct));
  PetscCall(KSPGetDiagonalScale(ksp, &scaled));
  PetscInt nf;
  char **names;
  IS *fields;
  PetscCall(DMCreateFieldIS(dm, &nf, &names, &fields));
  IS mass_rows;
  PetscCall(pressureRows(nf, fields, &mass_rows));
  for (PetscInt f = 0; f < nf; ++f) {
    PetscCall(ISDestroy(&fields[f]));
    PetscCall(PetscFree(names[f]));
  }
  PetscCall(PetscFree(fields));
  PetscCall(PetscFree(names));
  if (!use || direct || scaled || !mass_rows) {
    PetscCall(ISDestroy(&mass_rows));
    PetscFunctionReturn(0);
  }
  auto *test = new MassBalanceTest;
  test->mass_rows = mass_rows;
  PetscCall(KSPConvergedDefaultCreate(&test->petsc_test));
  PetscCall(KSPSetConvergenceTest(ksp, convergedWithMassBalance, test, destroyTest));
  PetscFunctionReturn(0);
}

} // namespace poroseam
