// run.yaml (split from the time loop in simulation.cpp): what ran, with what, and how it
// ended, so that a result can be traced back to its options and build and run again.

#include "poroseam/run_record.hpp"

#include "file_replace.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/options_file.hpp"

#include "poroseam_version.inc" // POROSEAM_VERSION, POROSEAM_GIT_COMMIT (cmake/version.cmake)

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/resource.h>

namespace poroseam {
namespace {

const std::string kHeader =
    "# poroseam run record (docs/scenes.md, \"Run record\"): one segment per run; a run\n"
    "# restarted with -restart appends its own segment.\n"
    "segments:\n";
const char *const kNoValue = "\x01"; // an option given without a value (a flag)

std::string utcNow()
{
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

/// A YAML double-quoted scalar: any text, read back unchanged.
std::string quoted(const std::string &s)
{
  std::string q = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\')
      q += '\\', q += (char)c;
    else if (c < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof(esc), "\\x%02x", c);
      q += esc;
    } else
      q += (char)c;
  }
  return q + "\"";
}

/// A number YAML reads back as the same double.
std::string number(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", v);
  return text;
}

/// The options PETSc holds, in its order: PetscOptionsGetAll's "-name value -flag ..." split
/// where a token is a key (PETSc's own test; "-1e4" is a value). Values of several words are
/// joined again. Querying each option instead would mark it used and hide it from the report
/// of unused options.
PetscErrorCode allOptions(std::vector<std::pair<std::string, std::string>> *out)
{
  char *all;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::istringstream in(all);
  std::string token;
  while (in >> token) {
    PetscBool key;
    PetscCall(PetscOptionsValidKey(token.c_str(), &key));
    if (key || out->empty())
      out->emplace_back(token, kNoValue);
    else if (out->back().second == kNoValue)
      out->back().second = token;
    else
      out->back().second += " " + token;
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

} // namespace

const char *runEndingName(RunEnding ending)
{
  switch (ending) {
  case RunEnding::running:
    return "running";
  case RunEnding::success:
    return "success";
  case RunEnding::failed_step:
    return "failed step";
  case RunEnding::step_limit:
    return "step limit";
  case RunEnding::signal:
    return "signal";
  case RunEnding::error:
    return "error";
  }
  return "error";
}

PetscErrorCode RunRecord::begin(MPI_Comm comm, const std::string &output_dir, bool restart)
{
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank_));
  PetscCallMPI(MPI_Comm_size(comm, &size_));
  begun_ = true;
  start_wall_ = MPI_Wtime();
  start_ = utcNow();
  output_dir_ = output_dir;
  path_ = output_dir + "/run.yaml";
  restart_ = restart;
  PetscCall(allOptions(&options_));
  int argc;
  char **argv;
  PetscCall(PetscGetArgs(&argc, &argv));
  // PETSc's arguments hold the options files read in place (options_file.hpp): the record
  // names the command as it was typed.
  const std::vector<std::string> args =
      startedCommandLine(std::vector<std::string>(argv, argv + argc));
  for (std::size_t i = 0; i < args.size(); ++i) {
    command_line_ += (i ? " " : "") + args[i];
    if (i + 1 < args.size() && args[i] == "-options_file")
      scene_files_ += (scene_files_.empty() ? "" : " ") + args[i + 1];
  }
  if (rank_ == 0 && restart) {
    // The interrupted run's segments stay as they are (text of our own making: no parser).
    std::ifstream in(path_);
    std::stringstream old;
    old << in.rdbuf();
    if (old.str().rfind(kHeader, 0) == 0) earlier_ = old.str().substr(kHeader.size());
  }
  PetscCall(writeOnRankZero(comm));
  PetscFunctionReturn(0);
}

PetscErrorCode RunRecord::setUnknowns(MPI_Comm comm,
                                      const std::vector<std::pair<std::string, long>> &fields)
{
  PetscFunctionBeginUser;
  unknowns_ = fields;
  PetscCall(writeOnRankZero(comm));
  PetscFunctionReturn(0);
}

PetscErrorCode RunRecord::setSolver(MPI_Comm comm, const std::string &solver)
{
  PetscFunctionBeginUser;
  solver_ = solver;
  PetscCall(writeOnRankZero(comm));
  PetscFunctionReturn(0);
}

PetscErrorCode RunRecord::finish(MPI_Comm comm, RunEnding ending, const std::string &message,
                                 RunSummary summary, int stop_signal)
{
  PetscFunctionBeginUser;
  if (stop_signal)
    signal_ = std::to_string(stop_signal) + " (SIG" + sigabbrev_np(stop_signal) + ")";
  // ru_maxrss: the process's peak resident memory in KiB (Linux), with no option needed,
  // where PetscMemoryGetMaximumUsage counts only with -memory_view.
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  double mine = usage.ru_maxrss / 1024.0;
  summary.peak_memory_mb.assign(size_, 0.0);
  PetscCallMPI(
      MPI_Gather(&mine, 1, MPI_DOUBLE, summary.peak_memory_mb.data(), 1, MPI_DOUBLE, 0, comm));
  summary.wall = elapsed();
  summary_ = summary;
  has_summary_ = true;
  ending_ = ending;
  exit_status_ = ending == RunEnding::success ? 0 : 1;
  message_ = message;
  end_ = utcNow();
  finished_ = true;
  has_progress_ = false; // the summary and the message say where it ended
  // The record first: a stopped run may be killed, or block on a stdout nobody reads any
  // more, while it prints.
  PetscCall(writeOnRankZero(comm));
  double peak = 0.0;
  for (double m : summary.peak_memory_mb)
    peak = std::max(peak, m);
  char time[32]; // PetscPrintf's %g would add a '.' to whole numbers ("1. s")
  std::snprintf(time, sizeof(time), "%g", summary.time);
  PetscCall(PetscPrintf(comm,
                        "summary: %d steps (%d cut back, %ld attempts rejected), %ld Newton and "
                        "%ld Krylov iterations, t = %s s\n",
                        summary.steps, summary.steps_cut_back, summary.rejected, summary.newton,
                        summary.krylov, time));
  PetscCall(PetscPrintf(comm,
                        "summary: wall time %.2f s (time steps %.2f s), peak memory %.1f MB per "
                        "rank (largest of %d), record in %s\n",
                        summary.wall, summary.stepping_wall, peak, size_, path_.c_str()));
  PetscFunctionReturn(0);
}

bool RunRecord::progress(const RunProgress &progress)
{
  progress_ = progress;
  has_progress_ = true;
  progress_at_ = utcNow();
  if (ending_ == RunEnding::running)
    message_ = "running, or killed: if no process of this run is left, it ended after step " +
               std::to_string(progress.step) +
               (progress.checkpoint.empty() ? std::string(" (no checkpoint)")
                                            : "; continue with -restart " + output_dir_);
  return rank_ != 0 || write();
}

std::string RunRecord::stoppedMessage(const std::string &signal) const
{
  char text[256];
  std::snprintf(text, sizeof(text),
                "stopped by signal %s during step %d, which is lost. Results up to step %d, t = "
                "%g s, are in ",
                signal.c_str(), progress_.step + 1, progress_.step, progress_.time);
  std::string m = text + output_dir_;
  if (progress_.checkpoint.empty())
    return m + "; no checkpoint was written (-checkpoint_rolling 0): run it again";
  return m + "; the checkpoint " + progress_.checkpoint + " remains: continue with -restart " +
         output_dir_;
}

std::string RunRecord::textIfStopped(char signal_mark) const
{
  RunRecord stopped = *this;
  stopped.ending_ = RunEnding::signal;
  stopped.exit_status_ = -1; // killed later, or not: not ours to say
  stopped.message_ = stoppedMessage("\x01signal\x01");
  stopped.signal_ = std::string(1, signal_mark);
  std::string segment = stopped.text();
  // quoted() wrote the placeholder's control characters as "\x01": the mark goes there, in
  // the message line only (user text elsewhere could hold the same characters).
  const std::string escaped = "\\x01signal\\x01", key = "\n    message: ";
  const size_t line = segment.find(key);
  const size_t at = segment.find(escaped, line);
  if (line != std::string::npos && at != std::string::npos && at < segment.find('\n', line + 1))
    segment.replace(at, escaped.size(), 1, signal_mark);
  return kHeader + earlier_ + segment;
}

void RunRecord::abandon(PetscErrorCode error)
{
  if (!begun_ || finished_) return;
  const char *text = nullptr;
  char *specific = nullptr;
  PetscErrorMessage(error, &text, &specific);
  ending_ = RunEnding::error;
  exit_status_ = 1;
  message_ = specific && *specific ? specific : (text ? text : "error");
  end_ = utcNow();
  finished_ = true;
  if (rank_ == 0) write(); // nothing more to do if it fails: the run is ending in an error
}

double RunRecord::elapsed() const
{
  return MPI_Wtime() - start_wall_;
}

std::string RunRecord::text() const
{
  std::ostringstream y;
  const std::string in = "    ";
  PetscInt major = 0, minor = 0, sub = 0, release = 0;
  PetscGetVersionNumber(&major, &minor, &sub, &release);
  y << "  - status: " << (ending_ == RunEnding::running ? "running" : "ended") << "\n";
  y << in << "ending: " << quoted(runEndingName(ending_)) << "\n";
  if (ending_ != RunEnding::running)
    y << in << "exit_status: " << (exit_status_ < 0 ? "null" : std::to_string(exit_status_))
      << "\n";
  y << in << "message: " << quoted(message_) << "\n";
  // A stop signal in an armed record (stop_request.hpp) is written by the handler: plain text.
  if (!signal_.empty()) y << in << "signal: \"" << signal_ << "\"\n";
  y << in << "start: " << quoted(start_) << "\n";
  y << in << "end: " << (end_.empty() ? "null" : quoted(end_)) << "\n";
  y << in << "poroseam_version: " << quoted(POROSEAM_VERSION) << "\n";
  y << in << "git_commit: " << quoted(POROSEAM_GIT_COMMIT) << "\n";
  y << in << "petsc_version: "
    << quoted(std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(sub))
    << "\n";
  y << in << "ranks: " << size_ << "\n";
  y << in << "restart: " << (restart_ ? "true" : "false") << "\n";
  y << in << "output_dir: " << quoted(output_dir_) << "\n";
  y << in << "scene_file: " << quoted(scene_files_) << "\n";
  y << in << "command_line: " << quoted(command_line_) << "\n";
  y << in << "unknowns:" << (unknowns_.empty() ? " {}" : "") << "\n";
  long total = 0;
  for (const auto &[name, n] : unknowns_)
    y << in << "  " << quoted(name) << ": " << n << "\n", total += n;
  if (!unknowns_.empty()) y << in << "  total: " << total << "\n";
  y << in << "solver: " << (solver_.empty() ? "null" : quoted(solver_)) << "\n";
  if (has_progress_) {
    // Rewritten after each accepted step: what a run killed now leaves, and how to go on.
    y << in << "progress:\n";
    y << in << "  last_step: " << progress_.step << "\n";
    y << in << "  time: " << number(progress_.time) << "\n";
    y << in << "  recorded: " << quoted(progress_at_) << "\n";
    y << in
      << "  checkpoint: " << (progress_.checkpoint.empty() ? "null" : quoted(progress_.checkpoint))
      << "\n";
    y << in << "  restart: "
      << (progress_.checkpoint.empty() ? "null" : quoted("-restart " + output_dir_)) << "\n";
  }
  if (has_summary_) {
    const RunSummary &s = summary_;
    y << in << "summary:\n";
    y << in << "  steps: " << s.steps << "\n";
    y << in << "  first_step: " << s.first_step << "\n";
    y << in << "  last_step: " << s.last_step << "\n";
    y << in << "  time: " << number(s.time) << "\n";
    y << in << "  steps_cut_back: " << s.steps_cut_back << "\n";
    y << in << "  rejected_attempts: " << s.rejected << "\n";
    y << in << "  newton_iterations: " << s.newton << "\n";
    y << in << "  krylov_iterations: " << s.krylov << "\n";
    y << in << "  wall_time_s: " << number(s.wall) << "\n";
    y << in << "  time_steps_wall_time_s: " << number(s.stepping_wall) << "\n";
    y << in << "  peak_memory_mb_per_rank: [";
    for (size_t r = 0; r < s.peak_memory_mb.size(); ++r)
      y << (r ? ", " : "") << number(s.peak_memory_mb[r]);
    y << "]\n";
  }
  // Every option as PETSc holds it, value as text (null: a flag), in PETSc's order: an
  // options file of these lines runs the same scene again.
  y << in << "options:" << (options_.empty() ? " {}" : "") << "\n";
  for (const auto &[name, value] : options_)
    y << in << "  " << quoted(name) << ": " << (value == kNoValue ? "null" : quoted(value)) << "\n";
  return y.str();
}

bool RunRecord::write() const
{
  return replaceFileContents(path_, kHeader + earlier_ + text(), &write_error_);
}

PetscErrorCode RunRecord::writeOnRankZero(MPI_Comm comm) const
{
  PetscFunctionBeginUser;
  // One line on every rank together (a full disk, run.yaml replaced by a directory).
  const bool ok = rank_ != 0 || write();
  PetscCall(checkOnAllRanks(comm, ok ? "" : "cannot write " + path_ + ": " + write_error_));
  PetscFunctionReturn(0);
}

} // namespace poroseam
