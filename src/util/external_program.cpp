#include "poroseam/external_program.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char **environ;

namespace poroseam {

std::string runProgram(const std::vector<std::string> &argv, const std::string &log_path)
{
  if (argv.empty()) return "no program to run";
  std::vector<char *> args;
  for (const auto &a : argv)
    args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid;
  const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    return "cannot run '" + argv[0] + "': " + std::strerror(spawned) +
           (spawned == ENOENT ? " (is it installed and on PATH?)" : "");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return "lost track of '" + argv[0] + "': " + std::strerror(errno);
  if (WIFSIGNALED(status))
    return "'" + argv[0] + "' was killed by signal " + std::to_string(WTERMSIG(status));
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return "'" + argv[0] + "' exited with status " + std::to_string(WEXITSTATUS(status));
  return "";
}

} // namespace poroseam
