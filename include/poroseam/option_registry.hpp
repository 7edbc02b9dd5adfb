// One declaration per option: every option of poroseam's own is declared once, in
// options.def, with its kind, the default -help shows, a one-line help with its SI unit, the
// docs page that describes it, whether a restart may change it, and whether its name is in
// poroseam's namespace or PETSc's. Everything else comes from that declaration:
//   - the readers take the name and help from it (spec(Option::gravity).flag, .help, .doc);
//   - the check of misspelt names (option_check.cpp) takes the names in poroseam's namespace;
//   - the check of numbers before the run (run_options.cpp) takes the integer, whole-number
//     and real options marked before_run;
//   - the restart check (restart_check.cpp) takes those a restart may change;
//   - the test optdecl.registry_docs checks that each is in its docs page, and that every
//     option a reader in src/ names is declared here.
// Adding an option: one POROSEAM_OPTION line in options.def, then read it with spec(...).
// The families named after the scene's parts (-region_<r>_*, -bc_<b>_*, -interface_<i>_*,
// -probe_<name>) and the options of PETSc's own objects are not here (option_check.cpp,
// run_options.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace poroseam {

enum class OptionKind { integer, whole_number, real, flag, text, choice, list };
/// Who checks a bad value: the reader (naming the option), or run_options.cpp before the run
/// (the reader is PETSc's parser, which casts an overlong integer silently and names only the
/// value of a bad one).
enum class OptionCheck { by_reader, before_run };
enum class OptionRestart { fixed, may_change };
/// poroseam: a name of its own, checked for misspellings. petsc: a name in PETSc's namespace
/// (-snes_kink_linesearch), where a near miss may be PETSc's own option.
enum class OptionSpace { poroseam, petsc };

struct OptionSpec {
  const char *flag; ///< "-gravity": the name as given, for the readers and messages
  OptionKind kind;
  const char *choices; ///< a choice's values, space-separated; "" for other kinds
  OptionCheck check;
  const char *default_shown; ///< the default as -help and the docs show it
  const char *help;          ///< one line, with the SI unit
  const char *doc;           ///< the docs page that describes it ("docs/scenes.md")
  OptionRestart restart;
  OptionSpace space;
  /// The name without its '-' ("gravity"), as the option checks compare names.
  const char *name() const { return flag + 1; }
};

/// Every declared option, by its name in options.def: spec(Option::gravity).
enum class Option {
#define POROSEAM_OPTION(name, ...) name,
#include "poroseam/options.def"
#undef POROSEAM_OPTION
};

/// The keys of the families named after a scene's parts (options.def): -region_<r>_E is
/// "-region_" + name + "_" + key(RegionKey::E).
enum class RegionKey {
#define POROSEAM_REGION_KEY(key) key,
#include "poroseam/options.def"
#undef POROSEAM_REGION_KEY
};
enum class BoundaryKey {
#define POROSEAM_BOUNDARY_KEY(key) key,
#include "poroseam/options.def"
#undef POROSEAM_BOUNDARY_KEY
};
enum class InterfaceKey {
#define POROSEAM_INTERFACE_KEY(key) key,
#include "poroseam/options.def"
#undef POROSEAM_INTERFACE_KEY
};
const char *key(RegionKey k);
const char *key(BoundaryKey k);
const char *key(InterfaceKey k);

/// Every key of a family, in the order of options.def.
std::vector<std::string> regionKeys();
std::vector<std::string> boundaryQuantities();
std::vector<std::string> interfaceKeys();

/// The declaration of `option`.
const OptionSpec &spec(Option option);

/// Every declaration, in the order of options.def.
const std::vector<OptionSpec> &optionRegistry();

/// The declaration whose name (without '-') is `name`, or null.
const OptionSpec *findOption(const std::string &name);

/// The values a choice option takes ("ptscotch", "metis", "simple"); empty for other kinds.
std::vector<std::string> optionChoices(Option option);

} // namespace poroseam
