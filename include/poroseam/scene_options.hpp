// Reading poroseam's options through PETSc's options API, so that -help lists each one with
// its current value and a description, grouped by scene part, as PETSc lists its own:
//
//   PetscOptionsBegin(comm, nullptr, "Region soil (-region_soil_*)", kSceneDoc);
//   PetscCall(getReal(PetscOptionsObject, "-region_soil_E", "Young's modulus E [Pa]", &E, &set));
//   PetscOptionsEnd();
//
// prints, with -help,
//   Region soil (-region_soil_*):
//     -region_soil_E <now 1e7 : formerly 0>: Young's modulus E [Pa] (docs/scenes.md)
//
// The getters take the section's PetscOptionsObject (the name PetscOptionsBegin declares) and
// a one-line description with units. Numbers are read as text and parsed here, so that a bad
// value ends in poroseam's one line naming the option and the value ("option -region_soil_E
// abc: expected a number"), not in PETSc's message, which names the value only.
#pragma once

#include "poroseam/option_registry.hpp"

#include <petscsys.h>
#include <string>
#include <vector>

namespace poroseam {

/// The manual section named at the end of each -help line of a scene option.
inline constexpr const char *kSceneDoc = "docs/scenes.md";

/// Parses a number, accepting what PETSc accepts for reals (1e7, 2.5, -3); false for anything
/// else (text, "nan", "inf", trailing characters), so that the error can name the option.
bool parseNumber(const std::string &text, double *value);

/// A real number; *value holds the default on entry (shown by -help) and is left unchanged
/// when the option is not given. `set` may be null. `unset`, when given, is what -help shows
/// as the default instead of *value ("none" for a boundary condition that is not given).
PetscErrorCode getReal(PetscOptionItems *PetscOptionsObject, const std::string &option,
                       const std::string &help, double *value, bool *set,
                       const char *unset = nullptr);

/// A real number that must be given: "missing option <option>: <help> is required".
PetscErrorCode getRequiredReal(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                               const std::string &option, const std::string &help, double *value);

/// Text, as given; *value holds the default on entry (shown by -help). `set` may be null.
PetscErrorCode getString(PetscOptionItems *PetscOptionsObject, const std::string &option,
                         const std::string &help, std::string &value, bool *set);

/// Comma-separated numbers ("0,-1e4"); each must parse. `values` is cleared.
PetscErrorCode getRealList(PetscOptionItems *PetscOptionsObject, const std::string &option,
                           const std::string &help, std::vector<double> &values, bool *set);

/// Comma-separated names ("top,bottom"); an empty item ("a,,b") is kept, as an empty name,
/// for the caller to refuse. `values` is cleared.
PetscErrorCode getStringList(PetscOptionItems *PetscOptionsObject, const std::string &option,
                             const std::string &help, std::vector<std::string> &values, bool *set);

/// A flag (-drained, -drained true/false/1/0/yes/no); *value holds the default on entry.
/// PETSc parses it; a bad value is named by main's error handler.
PetscErrorCode getFlag(PetscOptionItems *PetscOptionsObject, const std::string &option,
                       const std::string &help, bool *value, bool *set);

// The same getters for a declared option (options.def): its name, help and docs page come
// from the declaration.
PetscErrorCode getReal(PetscOptionItems *PetscOptionsObject, const OptionSpec &option,
                       double *value, bool *set);
PetscErrorCode getString(PetscOptionItems *PetscOptionsObject, const OptionSpec &option,
                         std::string &value, bool *set);
PetscErrorCode getStringList(PetscOptionItems *PetscOptionsObject, const OptionSpec &option,
                             std::vector<std::string> &values, bool *set);
PetscErrorCode getFlag(PetscOptionItems *PetscOptionsObject, const OptionSpec &option, bool *value,
                       bool *set);

} // namespace poroseam
