#include "poroseam/mesh_limits.hpp"
#include "poroseam/solver_preset.hpp"

#include "poroseam/auto_threshold.hpp"

#include "poroseam/scene_options.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace poroseam {
namespace {

/// Memory of the iterative preset (options/solvers/fieldsplit.opts) over all ranks [bytes]:
/// 0.1 GB per rank plus 12.5 kB per unknown. Calibrated on the 3D quarter caisson, 2 ranks
/// (README, docs/bench): peak per rank 0.28 GB at 37k unknowns, 0.52 at 76k, 1.05 at 160k,
/// 2.1-2.2 at 344k; the model gives 0.33, 0.57, 1.1, 2.25.
double iterativeBytes(double unknowns, int ranks)
{
  return 0.1e9 * ranks + 12.5e3 * unknowns;
}

/// Memory of MUMPS LU (options/solvers/direct.opts) over all ranks [bytes]: its fill grows
/// faster than the unknowns in 3D. 3D quarter caisson, 2 ranks (README): 0.50 GB per rank at
/// 37,334 unknowns, 1.34 at 75,883 (exponent ln(2.68)/ln(2.03) = 1.4). 2D (axisymmetric
/// caisson, options/caisson_axisym_partially_drained.opts, 2 ranks, one step, measured for
/// this model): 109 MB per rank at 26,146 unknowns (factor 0.5), 304 MB at 103,396 (0.25);
/// the model gives 115 and 308.
double directBytes(double unknowns, int dim, int ranks)
{
  if (dim == 3) return 0.1e9 * ranks + 0.9e9 * std::pow(unknowns / 37334.0, 1.4);
  return 0.05e9 * ranks + 5.0e3 * unknowns;
}

/// What /proc/meminfo says is available (MemAvailable, else MemTotal) [bytes]; 0 if unknown.
double machineMemory(std::string *which)
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0, available = 0, total = 0;
  std::string unit;
  while (in >> key >> kb) {
    std::getline(in, unit);
    if (key == "MemAvailable:") available = kb * 1024.0;
    if (key == "MemTotal:") total = kb * 1024.0;
  }
  *which = available > 0 ? "MemAvailable" : "MemTotal";
  return available > 0 ? available : total;
}

std::string gigabytes(double bytes)
{
  std::ostringstream s;
  s.precision(bytes < 1e10 ? 2 : 3);
  s << bytes / 1e9 << " GB";
  return s.str();
}

std::string count(double n)
{
  std::ostringstream s;
  s.precision(2);
  if (n >= 1e5)
    s << std::scientific;
  else
    s.precision(6);
  s << std::round(n);
  return s.str();
}

PetscErrorCode readNumber(const char *option, const std::string &text, double min,
                          const char *expected, MPI_Comm comm, double *value)
{
  PetscFunctionBeginUser;
  const char *buffer = text.c_str();
  char *end = nullptr;
  const double v = std::strtod(buffer, &end);
  PetscCheck(end != buffer && *end == '\0' && std::isfinite(v) && v >= min && v < 9e18, comm,
             PETSC_ERR_USER_INPUT, "option %s %s: expected %s", option,
             buffer[0] ? buffer : "(no value)", expected);
  *value = v;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readMeshLimits(MPI_Comm comm, int displacement_order, MeshLimits *limits)
{
  std::string max_text = "2000000", time_text = "600";
  bool max_set = false, time_set = false;
  bool check = true;
  PetscFunctionBeginUser;
  *limits = MeshLimits();
  PetscOptionsBegin(comm, nullptr, "poroseam scene: mesh size, time and memory limits", kSceneDoc);
  PetscCall(getString(PetscOptionsObject, spec(Option::mesh_max_elements), max_text, &max_set));
  PetscCall(getString(PetscOptionsObject, spec(Option::mesh_time_limit), time_text, &time_set));
  PetscCall(getFlag(PetscOptionsObject, spec(Option::mesh_memory_check), &check, nullptr));
  PetscOptionsEnd();
  if (max_set) {
    double v;
    PetscCall(readNumber(spec(Option::mesh_max_elements).flag, max_text, 1, "a whole number >= 1",
                         comm, &v));
    PetscCheck(v == std::floor(v), comm, PETSC_ERR_USER_INPUT,
               "option -mesh_max_elements %s: expected a whole number >= 1", max_text.c_str());
    limits->max_elements = (long)v;
  }
  if (time_set) {
    PetscCall(readNumber(spec(Option::mesh_time_limit).flag, time_text, 0, "a time in seconds > 0",
                         comm, &limits->time_limit));
    PetscCheck(limits->time_limit > 0, comm, PETSC_ERR_USER_INPUT,
               "option -mesh_time_limit %s: expected a time in seconds > 0", time_text.c_str());
  }
  limits->memory_check = check;
  // What the solver preset will choose (solver_preset.cpp reads these options for real).
  char buffer[256] = "";
  PetscBool set;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, spec(Option::solver_preset).flag, buffer,
                                  sizeof buffer, &set));
  if (set) limits->preset = buffer;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-pc_type", buffer, sizeof buffer, &set));
  if (set) limits->pc_type = buffer;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-ksp_type", buffer, sizeof buffer, &set));
  if (set) limits->ksp_type = buffer;
  PetscInt threshold;
  PetscCall(readAutoThreshold(nullptr, comm, displacement_order, &threshold));
  limits->auto_threshold = (long)threshold;
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  limits->ranks = size;
  PetscFunctionReturn(0);
}

std::string checkMeshMemory(const MeshLimits &limits, double nodes, int dim,
                            const std::string &what, const std::string &remedy, std::string *note)
{
  note->clear();
  const double unknowns = nodes * (dim + 1);
  // The preset's choice (solver_preset.cpp's chosenPreset): -pc_type given wins; then the
  // preset, auto by default (iterative in 3D above the threshold); a -ksp_type of the user's
  // with PETSc's default preconditioner (ILU) is iterative.
  bool iterative;
  const std::string preset =
      chosenPreset(limits.preset, !limits.pc_type.empty() || !limits.ksp_type.empty(), dim,
                   unknowns, limits.auto_threshold);
  if (!limits.pc_type.empty())
    iterative = limits.pc_type != "lu" && limits.pc_type != "cholesky";
  else
    iterative = preset.empty() || preset == "fieldsplit";
  const double need =
      iterative ? iterativeBytes(unknowns, limits.ranks) : directBytes(unknowns, dim, limits.ranks);
  std::string which;
  const double have = machineMemory(&which);
  const std::string solver = iterative ? "the iterative solver (fieldsplit)" : "MUMPS LU (direct)";
  const std::string estimate = what + " and about " + count(unknowns) + " unknowns; with " +
                               solver + " on " + std::to_string(limits.ranks) + " rank" +
                               (limits.ranks > 1 ? "s" : "") + " that needs about " +
                               gigabytes(need) + " of memory";
  if (have > 0 && need > have && limits.memory_check)
    return estimate + ", more than the " + gigabytes(have) + " this machine has (" + which +
           " in /proc/meminfo): " + remedy + ", or -mesh_memory_check 0 to run anyway";
  if (need > 1e9 || (have > 0 && need > 0.5 * have))
    *note = "memory estimate: " + estimate + " (" + gigabytes(have) + " " + which + ")";
  return "";
}

} // namespace poroseam
