// Choosing the linear solver: the presets of options/solvers/ by name, or by problem size.
//
//   -solver_preset direct|fieldsplit|<name>   insert options/solvers/<name>.opts
//   -solver_preset auto                       MUMPS LU (direct) unless the scene is 3D with more
//                                             than -solver_auto_threshold unknowns (default
//                                             30000 at -displacement_order 1, 70000 at 2),
//                                             then the iterative fieldsplit preset;
//                                             nothing when -ksp_type or -pc_type is given (a
//                                             preset file added with -options_file, say)
// auto is the default: a scene that names no solver (no -solver_preset, -ksp_type, -pc_type)
// gets it, not PETSc's GMRES with ILU(0), slow or failing on these saddle-point systems
// (issue 24: a scene without a solver line ran 9 attempts of 10,000 Krylov iterations each).
// Options already set (scene file or command line) keep their values: a preset only fills in
// what is not set. Measured with scripts/bench on the 3D quarter caisson (2 ranks): at 5k
// unknowns MUMPS is faster, at 37k the fieldsplit preset takes about 0.8 of MUMPS's time per
// step, at 160k about 0.6, and MUMPS's memory grows like N^1.5.
#pragma once

#include <petscsys.h>
#include <string>
#include <vector>

namespace poroseam {

/// The file of the solver preset `name` (options/solvers/<name>.opts of poroseam's source
/// tree, wherever the scene is), or "" when there is no such preset. Not collective.
std::string solverPresetFile(const std::string &name);

/// The names of the presets, "direct, fieldsplit".
std::string solverPresetList();

/// Whether `path` names a file of poroseam's solver presets folder (options/solvers/).
bool isSolverPresetFile(const std::string &path);

/// The names (without '-') of the options the solver presets of options/solvers/ set: PETSc
/// options poroseam's tested configurations use.
std::vector<std::string> solverPresetOptionNames();

/// -solver_auto_threshold's default at a displacement order: where the fieldsplit preset
/// starts to be faster than MUMPS on the 3D quarter caisson (2 ranks). Order 1: 30,000 (at 37k
/// the preset took 0.8 of MUMPS's time per step, at 5k MUMPS was faster). Order 2: 70,000;
/// measured with curved cells (the preset with its order coarsening and stiff bodies, idle,
/// first 2 steps, time per step, bench/order2_caisson.py): MUMPS 1.79x faster at 30k (mesh
/// factor 2), 1.12x at 55k (1.75); the preset 1.15x faster at 87k (1.5), 2.0x at 144k (1.25),
/// 1.05x at 169k on the graded mesh, with a third to a half of MUMPS's memory.
long defaultAutoThreshold(int displacement_order);

/// The preset -solver_preset takes: `preset` as given ("" when not given: auto), or for auto
/// "" when a solver is named (-ksp_type or -pc_type given), else "direct" or "fieldsplit" by
/// `dim` and the global number of `unknowns` against `threshold` (-solver_auto_threshold).
/// Pure: also what the mesh's memory estimate expects (mesh_limits.cpp).
std::string chosenPreset(const std::string &preset, bool solver_named, int dim, double unknowns,
                         long threshold);

/// Reads -solver_preset (default auto); with a preset, inserts its options (those not set
/// already) and says which on stdout; *choice is that line's text for run.yaml ("preset direct
/// (auto, the default: ...)", "as given (-pc_type lu)"). `dim` and `unknowns` (global) decide
/// for auto. Call before the solvers read their options.
PetscErrorCode applySolverPreset(MPI_Comm comm, int dim, int displacement_order, long unknowns,
                                 std::string *choice);

} // namespace poroseam
