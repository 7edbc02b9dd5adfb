// Running an external program (gmsh) without a shell: the arguments go to the program as they
// are, so no path or option text a user gives is ever interpreted by a shell.
#pragma once

#include <string>
#include <vector>

namespace poroseam {

/// How a program ended, beyond the message: for callers that explain a kill or a time-out.
struct ProgramEnd {
  bool timed_out = false; ///< still running at the time limit: killed (SIGKILL) by us
  int signal = 0;         ///< the signal that ended it (not ours), e.g. 9 from the OOM killer
  int exit_status = 0;    ///< its exit status when it exited
};

/// Runs argv[0] (searched on PATH) with the arguments argv[1..], its standard output and error
/// going to the file `log_path`, and waits for it. Returns "" on exit status 0, otherwise what
/// went wrong (not found, killed by a signal, exit status). The program is started through
/// this executable as a launcher that sets PR_SET_PDEATHSIG: it dies when the caller dies (a
/// killed run leaves no gmsh behind).
/// With `time_limit` > 0 [s], a program still running after it is killed and the message
/// says so (end->timed_out). `end`, when given, tells how it ended.
std::string runProgram(const std::vector<std::string> &argv, const std::string &log_path,
                       double time_limit = 0, ProgramEnd *end = nullptr);

} // namespace poroseam
