// Checks of every option as given (on the command line and in options files), before PETSc
// starts: what PETSc would otherwise cut short, crash on, or let through into the outputs.
//   - control characters (a newline, a tab, ...) in a name or a value: a path holding one
//     would break run.yaml, the XDMF and the CSV files; no value needs one;
//   - a value longer than PETSc reads: 255 characters for a number, a name or a type (PETSc
//     and poroseam read them into 256-character buffers and silently cut the rest: E =
//     1.000...0001e7 became 1 Pa), 4095 for a path (PETSC_MAX_PATH_LEN); a name too;
//   - more options than PETSc 3.18's table holds (512, of which 64 are kept for the solver
//     preset and PETSc's own): PETSc stopped with "Out of memory" and a traceback.
#pragma once

#include "poroseam/options_file.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace poroseam {

/// The most characters of a value that is no path, and of one that is.
constexpr std::size_t kMaxOptionValue = 255;
constexpr std::size_t kMaxOptionPath = 4095;
/// The most options (distinct names, as PETSc counts them: case aside) a run may be given.
constexpr std::size_t kMaxGivenOptions = 512 - 64;

/// Returns "" or the one-line error naming the option and where it was given.
std::string checkGivenOptions(const std::vector<GivenOption> &options);

} // namespace poroseam
