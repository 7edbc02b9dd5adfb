// Krylov convergence test of the Newton solves with an iterative solver: PETSc's test on the
// residual as assembled (force units, what Newton's own test measures), and, once that passes,
// the same tolerance for the mass-balance rows weighted by their diagonal.
//
// Why both. Krylov methods minimise the norm of the system they are given. Newton's test
// (-snes_reference_rtol) measures the residual as assembled, where every row is a force (the
// mass balance is multiplied by -dt S, docs/physics.md), so a linear solve stopped on that norm
// is what the next Newton iterate can use. But next to a stiff interface (K_N h/E in the
// thousands) the force rows are so large that the mass-balance rows hardly count in that norm:
// a stiff joint column's impervious bottom leaked 1.7e-9 of the top flux (MUMPS: 0;
// tests/mpi/solver_presets.py allows 1e-9, case joint_column_2d, variant fieldsplit_unscaled).
// PETSc's -ksp_diagonal_scale (the fieldsplit preset) fixes that differently, by weighing every
// row by |a_ii|^-1/2 in the norm the Krylov method minimises; the force rows then count unlike
// in Newton's norm (the caisson's steel rows 30 times less). Measured on the 3D quarter
// caisson, 2 ranks, same session: 37k unknowns, whole 24-step run, scaled 60 Newton and 1310
// outer iterations (97-116 s), unscaled with this check 52 and 1160 (89-91 s); 160k, first
// three steps, scaled 18 and 434 (171 s), unscaled with this check 14 and 568 (184 s). The
// preset keeps the scaling; this check makes every other iterative solve (no scaling) keep
// the water.
//
// The check: the true residual r = b - A x (KSPBuildResidual) restricted to the pressure rows
// (bulk and interface), weighted by D = |diag A|^-1/2, must be below
// max(rtol ||D b||, atol) with the solve's own rtol and atol: what -ksp_diagonal_scale would
// ask of these rows. It runs only when PETSc's test has passed; until both pass, the Krylov
// method iterates on.
//
// On by default for iterative solves (not -ksp_type preonly) of scenes with pressure unknowns;
// -mass_balance_krylov_test 0 leaves PETSc's test alone; not used with -ksp_diagonal_scale
// (whose norm already weighs these rows).
#pragma once

#include <petscdm.h>
#include <petscksp.h>

namespace poroseam {

/// Installs the test on `ksp` (the Newton solver's KSP, after its options are read) when the
/// scene has pressure unknowns, the KSP iterates, no -ksp_diagonal_scale is set and
/// -mass_balance_krylov_test is on (default). Collective.
PetscErrorCode configureMassBalanceTest(KSP ksp, DM dm);

} // namespace poroseam
