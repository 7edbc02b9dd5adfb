// Misspelt scene options: an option with a poroseam prefix (-region_, -bc_, -interface_,
// -probe_, the scene's own names, the solver splits -fieldsplit_<field>_) that no code would
// read stops the run before it starts, naming the option and the one probably meant. A
// misspelt -bc_top_trction would otherwise run the scene without its load.
#pragma once

#include "poroseam/scene.hpp"

#include <petscsys.h>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace poroseam {

/// The names a scene gives to the parts of its mesh: an option is checked against them.
struct SceneNames {
  int dim = 0;
  std::vector<std::string> regions;     ///< -regions
  std::vector<std::string> boundaries;  ///< -boundaries
  std::vector<std::string> interfaces;  ///< -interfaces
  std::vector<PhysicalName> mesh_names; ///< the mesh's physical groups (what could be listed)
};

/// Edit distance with adjacent transpositions (optimal string alignment): "trction" is 1 from
/// "traction", "rigth" 1 from "right".
std::size_t editDistance(const std::string &a, const std::string &b);

/// The closest of `candidates` to `word`, within a tolerance that grows with the length of
/// the candidate (one edit up to 5 characters, two up to 12, three beyond), or "".
std::string closestName(const std::string &word, const std::vector<std::string> &candidates);

/// The scene-wide option names of poroseam (-mesh, -drained, ..., -options_unused_ok).
std::vector<std::string> sceneOptionNames();

/// Whether `name` (without '-') is one of poroseam's scene options: a scene-wide name or one
/// of the families -region_*, -bc_*, -interface_*, -probe_* (checked by checkOptionNames).
bool isSceneOption(const std::string &name);

/// The one-line error for option `name` (without its '-') with value `value`, or "" when
/// the option is poroseam's and spelt right or is none of poroseam's business (PETSc's own,
/// or unknown and close to no name of poroseam: those are left to the check of options nothing
/// reads, unused_options.hpp).
/// `given` holds the names of every option set (for -bc_<b>_<q>_ramp without -bc_<b>_<q>).
std::string misspeltOption(const std::string &name, const std::string &value,
                           const SceneNames &names, const std::set<std::string> &given);

/// Every option set, as (name without '-', value) in the order PETSc lists them.
PetscErrorCode allOptions(std::vector<std::pair<std::string, std::string>> &out);

/// Collective (the options are the same on every rank). Fails with PETSC_ERR_USER_INPUT and
/// misspeltOption's message at the first option it refuses. With `names` empty (before the
/// mesh is read) it checks the scene-wide names only (-mseh, -gravty).
PetscErrorCode checkOptionNames(MPI_Comm comm, const SceneNames &names);

} // namespace poroseam
