#include "restart_check.hpp"

#include "poroseam/option_check.hpp"
#include "poroseam/option_registry.hpp"
#include "poroseam/scene_options.hpp"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <petscviewerhdf5.h>
#include <sstream>

namespace poroseam {
namespace simulation_detail {
namespace {

/// Options of PETSc and its objects a restart may change, by the start of their name (without
/// '-'); poroseam's own a restart may change are declared so (options.def, may_change).
/// Anything else a run was given is compared, so that a physics option added later is safe by
/// default.
const char *const kMayChange[] = {
    // How the equations are solved: the choice of Newton, Krylov method and preconditioner
    // (also inside splits) and their tolerances. A tolerance changes the answer within itself
    // (docs/checkpoints.md): loosening one on a restart is the user's choice, as on a new run.
    "ksp_", "pc_", "snes_", "mat_", "fieldsplit_", "mg_", "sub_", "redundant_", "vertex_blocks_",
    "schur_selfp_", "esteig_",
    // What is written.
    "ts_monitor", "ts_view", "ts_adapt_monitor", "dm_view",
    // The run's guards against a run that does not end.
    "ts_max_steps", "ts_max_reject", "ts_max_snes_failures", "ts_error_if_step_fails",
    // Profiling, debugging and PETSc's runtime.
    "log", "malloc", "options_", "help", "info", "version", "viewer", "draw", "on_error",
    "no_signal_handler", "history", "debugger", "start_in_debugger", "stop_for_debugger",
    "memory_view", "objects_dump", "fp_trap", "check_pointer_intensity", "nox", "saws", "mpi",
    "petsc", "use_gpu_aware_mpi", "skip_petscrc"};

/// Checked on its own (checkFinalTime): a later final time extends the run.
const char *const kFinalTime = "ts_max_time";

std::string hex(std::uint64_t h)
{
  char text[24];
  std::snprintf(text, sizeof(text), "%016" PRIx64, h);
  return text;
}

/// FNV-1a of a file's content; false when it cannot be read.
bool fileHash(const std::string &path, std::string *hash)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::uint64_t h = 0xcbf29ce484222325ULL;
  std::vector<char> buffer(1 << 20);
  while (in) {
    in.read(buffer.data(), (std::streamsize)buffer.size());
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i)
      h = (h ^ (unsigned char)buffer[i]) * 0x100000001b3ULL;
  }
  if (in.bad()) return false;
  *hash = hex(h);
  return true;
}

/// A regular file (not a FIFO or a device: reading those could hang or never end).
bool namesFile(const std::string &value)
{
  if (value.empty() || value.size() > 4096) return false;
  std::error_code failed;
  return std::filesystem::is_regular_file(value, failed);
}

PetscErrorCode broadcastText(MPI_Comm comm, std::string *text)
{
  unsigned long long n = text->size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, comm));
  text->resize(n);
  if (n) PetscCallMPI(MPI_Bcast(&(*text)[0], (int)n, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

/// "-name value" lines (an options file) as name -> value.
std::map<std::string, std::string> parseOptions(const std::string &text)
{
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] != '-') continue;
    const auto cut = line.find(' ');
    out[line.substr(1, cut == std::string::npos ? std::string::npos : cut - 1)] =
        cut == std::string::npos ? "" : line.substr(cut + 1);
  }
  return out;
}

std::string lower(std::string s)
{
  for (char &c : s)
    c = (char)std::tolower((unsigned char)c);
  return s;
}

/// PETSc's reading of a flag's value; -1 when it is not one.
int truth(const std::string &value)
{
  const std::string v = lower(value);
  if (v.empty() || v == "true" || v == "1" || v == "yes" || v == "on") return 1;
  if (v == "false" || v == "0" || v == "no" || v == "off") return 0;
  return -1;
}

/// Whether two values of an option mean the same: the same text, the same numbers however
/// written (2e8 and 200000000, lists item by item), or the same flag (true and 1).
bool sameValue(const std::string &a, const std::string &b)
{
  if (a == b) return true;
  if (truth(a) >= 0 && truth(a) == truth(b)) return true;
  std::istringstream ia(a), ib(b);
  std::string x, y;
  bool any = false;
  while (true) {
    const bool more_a = (bool)std::getline(ia, x, ','), more_b = (bool)std::getline(ib, y, ',');
    if (more_a != more_b) return false;
    if (!more_a) return any;
    double u, v;
    if (!parseNumber(x, &u) || !parseNumber(y, &v) || u != v) return false;
    any = true;
  }
}

std::string shown(const std::string &value)
{
  return value.empty() ? "given (a flag)" : value;
}

PetscErrorCode compareOptions(MPI_Comm comm, const CheckpointHeader &checkpoint,
                              const std::string &options, const std::string &option_files,
                              const std::string &path)
{
  PetscFunctionBeginUser;
  const auto then = parseOptions(checkpoint.options), now = parseOptions(options);
  const auto then_files = parseOptions(checkpoint.option_files),
             now_files = parseOptions(option_files);
  std::map<std::string, int> names; // both sides, in order
  for (const auto &o : then)
    names[o.first] = 1;
  for (const auto &o : now)
    names[o.first] = 1;
  const std::string why = "a restart continues that run's computation and keeps the options "
                          "that change its physics or discretisation (docs/checkpoints.md)";
  for (const auto &entry : names) {
    const std::string &name = entry.first;
    if (name == kFinalTime || restartMayChange(name)) continue;
    const auto a = then.find(name), b = now.find(name);
    const auto fa = then_files.find(name), fb = now_files.find(name);
    PetscCheck(a != then.end(), comm, PETSC_ERR_USER_INPUT,
               "-restart: option -%s is %s here, but was not given (its default) in the run that "
               "wrote %s; %s",
               name.c_str(), shown(b->second).c_str(), path.c_str(), why.c_str());
    PetscCheck(b != now.end(), comm, PETSC_ERR_USER_INPUT,
               "-restart: option -%s is not given here (its default), but was %s in the run "
               "that wrote %s; %s",
               name.c_str(), shown(a->second).c_str(), path.c_str(), why.c_str());
    if (fa != then_files.end() && fb != now_files.end()) {
      // Both name a file: what counts is its content, not its name.
      PetscCheck(fa->second == fb->second, comm, PETSC_ERR_USER_INPUT,
                 "-restart: option -%s %s: the file's content differs from that of %s read by "
                 "the run that wrote %s (content hash %s here, %s then); %s",
                 name.c_str(), b->second.c_str(), a->second.c_str(), path.c_str(),
                 fb->second.c_str(), fa->second.c_str(), why.c_str());
      continue;
    }
    PetscCheck(sameValue(a->second, b->second), comm, PETSC_ERR_USER_INPUT,
               "-restart: option -%s is %s here, but was %s in the run that wrote %s; %s",
               name.c_str(), shown(b->second).c_str(), shown(a->second).c_str(), path.c_str(),
               why.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkOutputFiles(MPI_Comm comm, const std::string &dir,
                                const CheckpointHeader &checkpoint, const std::string &path)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string missing;
  if (rank == 0) {
    std::istringstream in(checkpoint.output_files);
    std::string name;
    std::error_code failed;
    while (missing.empty() && std::getline(in, name))
      if (!name.empty() &&
          !std::filesystem::is_regular_file(std::filesystem::path(dir) / name, failed))
        missing = name;
  }
  PetscCall(broadcastText(comm, &missing));
  PetscCheck(missing.empty(), comm, PETSC_ERR_USER_INPUT,
             "-restart %s: the output file %s/%s is missing; the run that wrote %s had written "
             "it, and a restart continues that run's output files: put it back, or start a new "
             "run",
             dir.c_str(), dir.c_str(), missing.c_str(), path.c_str());
  PetscFunctionReturn(0);
}

} // namespace

bool restartMayChange(const std::string &name)
{
  const OptionSpec *declared = findOption(name);
  if (declared) return declared->restart == OptionRestart::may_change;
  return std::any_of(std::begin(kMayChange), std::end(kMayChange), [&](const char *prefix) {
    return name.compare(0, std::char_traits<char>::length(prefix), prefix) == 0;
  });
}

PetscErrorCode givenOptions(MPI_Comm comm, std::string *options, std::string *option_files)
{
  PetscMPIInt rank;
  std::vector<std::pair<std::string, std::string>> all;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(allOptions(all)); // the same on every rank
  options->clear();
  option_files->clear();
  for (const auto &[name, value] : all) {
    *options += "-" + name + (value.empty() ? "" : " " + value) + "\n";
    std::string hash;
    if (rank == 0 && !restartMayChange(name) && namesFile(value) && fileHash(value, &hash))
      *option_files += "-" + name + " " + hash + "\n";
  }
  PetscCall(broadcastText(comm, option_files));
  PetscFunctionReturn(0);
}

const std::vector<std::string> &outputFileNames()
{
  static const std::vector<std::string> names = {
      "timeseries.csv", "timeseries.csv.units", "fields.h5",           "fields.xmf",
      "interfaces.h5",  "interface_cells.xmf",  "interface_points.xmf"};
  return names;
}

PetscErrorCode presentOutputFiles(MPI_Comm comm, const std::string &dir, std::string *names)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  names->clear();
  if (rank == 0)
    for (const std::string &name : outputFileNames()) {
      std::error_code failed;
      if (std::filesystem::is_regular_file(std::filesystem::path(dir) / name, failed))
        *names += name + "\n";
    }
  PetscCall(broadcastText(comm, names));
  PetscFunctionReturn(0);
}

PetscErrorCode chooseRestartCheckpoint(MPI_Comm comm, const RestartOptions &restart,
                                       const std::string &options, const std::string &option_files,
                                       std::string *path)
{
  CheckpointHeader checkpoint;
  PetscFunctionBeginUser;
  PetscCall(findCheckpoint(comm, restart.dir, restart.step, path));
  PetscCall(readCheckpointHeader(comm, *path, &checkpoint));
  PetscCall(compareOptions(comm, checkpoint, options, option_files, *path));
  PetscCall(checkOutputFiles(comm, restart.dir, checkpoint, *path));
  // -ts_max_time as given (the run checks TS's value again, default included, once it is set).
  PetscReal t_end;
  PetscBool set = PETSC_FALSE;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ts_max_time", &t_end, &set));
  if (set) PetscCall(checkFinalTime(comm, t_end, checkpoint.time, *path));
  PetscFunctionReturn(0);
}

PetscErrorCode checkFinalTime(MPI_Comm comm, double t_end, double t_checkpoint,
                              const std::string &path)
{
  PetscFunctionBeginUser;
  char end[32], at[32]; // as given, not PETSc's "12."
  std::snprintf(end, sizeof end, "%.12g", t_end);
  std::snprintf(at, sizeof at, "%.12g", t_checkpoint);
  PetscCheck(t_end > t_checkpoint, comm, PETSC_ERR_USER_INPUT,
             "-ts_max_time %s: the checkpoint %s is at t = %s s already; a restart continues "
             "to a later final time (that is how a run is extended)",
             end, path.c_str(), at);
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
