// Running an external program (gmsh) without a shell: the arguments go to the program as they
// are, so no path or option text a user gives is ever interpreted by a shell.
#pragma once

#include <string>
#include <vector>

namespace poroseam {

/// Runs argv[0] (searched on PATH) with the arguments argv[1..], its standard output and error
/// going to the file `log_path`, and waits for it. Returns "" on exit status 0, otherwise what
/// went wrong (not found, killed by a signal, exit status). The program is started through
/// this executable as a launcher that sets PR_SET_PDEATHSIG: it dies when the caller dies (a
/// killed run leaves no gmsh behind).
std::string runProgram(const std::vector<std::string> &argv, const std::string &log_path);

} // namespace poroseam
