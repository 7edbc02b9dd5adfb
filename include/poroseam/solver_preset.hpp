// Choosing the linear solver: the presets of options/solvers/ by name, or by problem size.
//
//   -solver_preset direct|fieldsplit|<name>   insert options/solvers/<name>.opts
//   -solver_preset auto                       MUMPS LU (direct) unless the scene is 3D with more
//                                             than -solver_auto_threshold unknowns (default
//                                             30000 at -displacement_order 1, 150000 at 2),
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
/// the preset took 0.8 of MUMPS's time per step, at 5k MUMPS was faster). Order 2: 150,000;
/// measured (first step, the preset with its order coarsening): MUMPS 2.9x faster at 30k (mesh
/// factor 2, idle machine), 1.56x at 87k (factor 1.5, load 6.5), 2.4x at 169k (the graded
/// mesh, idle: 65 s against 158 s). So the threshold is set by memory, not speed: MUMPS took
/// 2.8 GB per rank at 169k (fieldsplit 1.3 GB), and 150k keeps it well inside a 16 GB machine.
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
