#include "poroseam/external_program.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char **environ;

namespace poroseam {
namespace {

/// The first argument by which the executable re-starts itself as the launcher of a child
/// program (see runProgram). Nobody types it.
constexpr const char kLauncherFlag[] = "--poroseam-launch-child-of";

/// Runs before main, in every executable linked with this file (poroseam and the unit tests
/// that mesh .geo files): when started as `exe --poroseam-launch-child-of <pid> program
/// args...`, ask the kernel to kill this process when its parent dies, make sure the parent
/// is still the one that started it, and become `program`. The death signal survives exec,
/// so gmsh dies with a killed run instead of meshing on alone.
__attribute__((constructor)) void launchChildIfAsked()
{
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  for (size_t start = 0; start < all.size();) {
    const size_t end = all.find('\0', start);
    args.push_back(all.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (args.size() < 4 || args[1] != kLauncherFlag) return;
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) _exit(126);
  if (std::to_string(getppid()) != args[2]) _exit(126); // the parent died before prctl
  std::vector<char *> argv;
  for (size_t i = 3; i < args.size(); ++i)
    argv.push_back(const_cast<char *>(args[i].c_str()));
  argv.push_back(nullptr);
  execvp(argv[0], argv.data());
  std::fprintf(stderr, "cannot run '%s': %s\n", argv[0], std::strerror(errno));
  _exit(errno == ENOENT ? 127 : 126);
}

} // namespace

std::string runProgram(const std::vector<std::string> &argv, const std::string &log_path,
                       double time_limit, ProgramEnd *end)
{
  ProgramEnd ignored;
  if (!end) end = &ignored;
  *end = ProgramEnd();
  if (argv.empty()) return "no program to run";
  // Not the program itself but this executable as its launcher (launchChildIfAsked above),
  // which ties the program's life to ours. No shell anywhere: arguments go as they are.
  const std::string parent = std::to_string(getpid());
  // The executable's path, not "/proc/self/exe" itself (under valgrind that is valgrind's
  // tool; valgrind answers readlink with the program's path).
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0) return "cannot find poroseam's own executable to start '" + argv[0] + "'";
  self[length] = '\0';
  std::vector<char *> args = {self, const_cast<char *>(kLauncherFlag),
                              const_cast<char *>(parent.c_str())};
  for (const auto &a : argv)
    args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid;
  const int spawned = posix_spawn(&pid, self, &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return "cannot start '" + argv[0] + "': " + std::strerror(spawned);
  int status = 0;
  // Polls, so a program that never ends (a .geo with an endless loop) is killed at the limit.
  const auto start = std::chrono::steady_clock::now();
  auto pause = std::chrono::milliseconds(2);
  while (true) {
    const pid_t done = waitpid(pid, &status, time_limit > 0 ? WNOHANG : 0);
    if (done == pid) break;
    if (done < 0 && errno != EINTR)
      return "lost track of '" + argv[0] + "': " + std::strerror(errno);
    if (done == 0) {
      const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start;
      if (spent.count() > time_limit) {
        kill(pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        end->timed_out = true;
        return "'" + argv[0] + "' was still running after its time limit and was stopped";
      }
      std::this_thread::sleep_for(pause);
      pause = std::min(2 * pause, std::chrono::milliseconds(100));
    }
  }
  if (WIFSIGNALED(status)) {
    end->signal = WTERMSIG(status);
    return "'" + argv[0] + "' was killed by signal " + std::to_string(WTERMSIG(status));
  }
  if (WIFEXITED(status)) end->exit_status = WEXITSTATUS(status);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    return "cannot run '" + argv[0] + "': not found (is it installed and on PATH?)";
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return "'" + argv[0] + "' exited with status " + std::to_string(WEXITSTATUS(status));
  return "";
}

} // namespace poroseam
