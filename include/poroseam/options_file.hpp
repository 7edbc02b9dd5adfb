// Options files, read by poroseam before PETSc starts (docs/scenes.md, "Paths").
//
// PETSc reads -options_file itself in PetscInitialize, and trusts the file: a file that
// includes itself recursed until the stack overflowed, /dev/zero or a binary file ran out of
// memory, a FIFO blocked forever, and a relative path inside a file named a file relative to
// wherever the run was started. Here every -options_file of the command line (and every one
// inside those files) is read first, with these rules:
//   - a regular file only (not a directory, FIFO, device or socket), at most 1 MiB, of text
//     (UTF-8, no NUL byte); a file that includes itself, directly or through others, is
//     refused naming the chain;
//   - one option per line, "-name [value]", '#' starts a comment, a value with spaces is
//     quoted ("a b"), -prefix_push/-prefix_pop as PETSc has them;
//   - a relative path in a file (the value of -options_file, -mesh, -bc_<b>_<q>_table) is
//     relative to the folder of that file; when no such file is there, to the working
//     directory (as before); -options_file solvers/<name>.opts (or options/solvers/...)
//     found in neither is the solver preset <name> of poroseam's options/solvers/.
// PETSc is then given the command line with each -options_file replaced, in place, by the
// options of its file: the same order, so an option later on the command line still overrides
// the file, and one earlier is overridden by it.
#pragma once

#include <string>
#include <vector>

namespace poroseam {

/// One option as given, after the options files are read in place.
struct GivenOption {
  std::string name;       ///< with its '-' and the -prefix_push prefix in force
  std::string value;      ///< the value (a path from a file resolved), "" when none
  bool has_value = false; ///< "-drained" alone has none
  std::string where;      ///< "on the command line", "on line 3 of 'scene.opts'"
  bool preset = false;    ///< from a solver preset's file (options/solvers/), not typed
};

/// The command line as PETSc is to see it.
struct ExpandedCommandLine {
  std::vector<std::string> args;    ///< argv[0], then every argument with files read in place
  std::vector<GivenOption> options; ///< the options among them, in order
};

/// Reads the command line's options files as described above. `environment` is the text of
/// PETSC_OPTIONS (or null): PETSc inserts it before the command line, so its options come
/// first in `out->args` (and the caller unsets it). Returns "" or the one-line error (naming
/// the file, the line and the option). Not collective: rank 0 reads, and broadcasts the
/// result (main.cpp), as PETSc does.
std::string expandOptionsFiles(int argc, char **argv, const char *environment,
                               ExpandedCommandLine *out);

/// The command line the process was started with (PETSc's copy holds the options files read
/// in place): from /proc/self/cmdline, or `fallback` where that cannot be read.
std::vector<std::string> startedCommandLine(const std::vector<std::string> &fallback);

} // namespace poroseam
