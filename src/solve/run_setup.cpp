// A run's set-up from its options to its initial state (split from simulate, simulation.cpp):
// the options read before the mesh, the output directory, the mesh and its distribution, the
// unknowns and the solver preset they choose, the initial state or the checkpoint a restart
// continues from.
#include "run_steps.hpp"

#include "restart_check.hpp"
#include "rolling_checkpoint.hpp"

#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/log_events.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/penalty_check.hpp"
#include "poroseam/scene.hpp"
#include "poroseam/solver_preset.hpp"
#include "poroseam/support_check.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace poroseam {
namespace simulation_detail {
namespace {

/// Prints the unknowns of each field (owned dofs less constrained ones, summed over the ranks)
/// and returns them by field name.
PetscErrorCode printFieldSizes(Run &run, std::vector<std::pair<std::string, long>> *fields)
{
  PetscSection gs;
  PetscInt pStart, pEnd, numFields;
  MPI_Comm comm = PetscObjectComm((PetscObject)run.dm);
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(run.dm, &gs));
  PetscCall(PetscSectionGetChart(gs, &pStart, &pEnd));
  PetscCall(PetscSectionGetNumFields(gs, &numFields));
  std::vector<long> local(numFields, 0), total(numFields, 0);
  for (PetscInt p = pStart; p < pEnd; ++p)
    for (PetscInt f = 0; f < numFields; ++f) {
      PetscInt dof, cdof, off;
      PetscCall(PetscSectionGetOffset(gs, p, &off));
      if (off < 0) continue; // not owned
      PetscCall(PetscSectionGetFieldDof(gs, p, f, &dof));
      PetscCall(PetscSectionGetFieldConstraintDof(gs, p, f, &cdof));
      local[f] += dof - cdof;
    }
  PetscCallMPI(MPI_Allreduce(local.data(), total.data(), numFields, MPI_LONG, MPI_SUM, comm));
  PetscSection s;
  PetscCall(DMGetLocalSection(run.dm, &s));
  for (PetscInt f = 0; f < numFields; ++f) {
    const char *name;
    PetscCall(PetscSectionGetFieldName(s, f, &name));
    PetscCall(PetscPrintf(comm, "field %-14s %10ld unknowns\n", name, total[f]));
    fields->emplace_back(name, total[f]);
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readRunOptions(MPI_Comm comm, Run &run, RestartOptions *restart)
{
  PetscFunctionBeginUser;
  PetscCall(registerLogEvents(&run.events));
  run.problem.setLogEvents(run.events);
  // The options as given, before poroseam adds its own: what a checkpoint keeps and a restart
  // compares (restart_check.hpp).
  PetscCall(givenOptions(comm, &run.given_options, &run.given_option_files));
  PetscCall(readMeshOptions(comm, run.scene));
  PetscCall(readCheckpointOptions(comm, run, restart));
  PetscCall(readRollingCheckpointOptions(comm, &run.rolling));
  PetscFunctionReturn(0);
}

PetscErrorCode prepareOutputDirectory(MPI_Comm comm, Run &run, const RestartOptions &restart,
                                      RunRecord &record, std::string *checkpoint_path)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // A restart that cannot continue its run is refused before anything in its directory changes.
  if (restart.restart)
    PetscCall(chooseRestartCheckpoint(comm, restart, run.given_options, run.given_option_files,
                                      checkpoint_path));
  { // rank 0 creates it; every rank learns whether that worked, so none waits for the others
    std::error_code failed;
    if (rank == 0) std::filesystem::create_directories(run.scene.output_dir, failed);
    int ok = !failed;
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
    const std::string why = failed ? ": " + failed.message() : "";
    PetscCheck(ok, comm, PETSC_ERR_FILE_OPEN,
               "cannot create the output directory '%s' (option -output_dir)%s",
               run.scene.output_dir.c_str(), why.c_str());
  }
  if (!restart.restart) PetscCall(clearEarlierRun(comm, run.scene.output_dir));
  PetscCall(record.begin(comm, run.scene.output_dir, restart.restart));
  PetscFunctionReturn(0);
}

PetscErrorCode loadMesh(MPI_Comm comm, Run &run)
{
  std::vector<PhysicalName> names;
  int dim;
  PetscFunctionBeginUser;
  PetscCall(beginLogPhase(run.events.mesh));
  PetscCall(loadGmshMesh(comm, run.scene.mesh_file, run.scene.mesh_size_factor,
                         run.scene.output_dir + "/mesh", &run.dm, &names, &dim,
                         run.scene.mesh_geometry_order, run.scene.displacement_order));
  PetscCall(readSceneOptions(comm, names, dim, run.scene));
  PetscCall(splitInterfaces(&run.dm, run.scene));
  PetscCall(checkBodiesSupported(run.dm, run.scene)); // no part free of every support
  PetscCall(markLayoutLabels(run.dm, run.scene));
  // Before distribution: rank 0 holds both sides of every interface face.
  PetscCall(warnAboutPenalties(run.dm, run.scene));
  PetscCall(endLogPhase(run.events.mesh));
  PetscCall(beginLogPhase(run.events.distribution));
  PetscCall(distributeMesh(&run.dm));
  PetscCall(checkCellOrientation(run.dm));
  PetscCall(endLogPhase(run.events.distribution));
  PetscFunctionReturn(0);
}

PetscErrorCode layOutUnknowns(MPI_Comm comm, Run &run, RunRecord &record)
{
  PetscFunctionBeginUser;
  PetscCall(createSolutionSection(run.dm, run.scene));
  PetscCall(run.problem.setup(run.dm, run.scene));
  PetscCall(run.probes.setup(run.dm, run.scene));
  PetscCall(collectBoundaryDofs(run));
  std::vector<std::pair<std::string, long>> fields;
  PetscCall(printFieldSizes(run, &fields));
  PetscCall(record.setUnknowns(comm, fields));
  long unknowns = 0;
  for (const auto &f : fields)
    unknowns += f.second;
  std::string solver;
  PetscCall(
      applySolverPreset(comm, run.scene.dim, run.scene.displacement_order, unknowns, &solver));
  PetscCall(record.setSolver(comm, solver));
  PetscFunctionReturn(0);
}

PetscErrorCode createInitialState(Run &run, const std::string *checkpoint_path, Vec *X,
                                  CheckpointInfo *resumed)
{
  PetscFunctionBeginUser;
  PetscCall(DMCreateLocalVector(run.dm, &run.previous));
  PetscCall(VecDuplicate(run.previous, &run.initial));
  PetscCall(run.problem.initialState(run.initial));
  PetscCall(run.steady.setup(run.dm, run.scene, run.initial));
  PetscCall(VecCopy(run.initial, run.previous));
  PetscCall(DMCreateGlobalVector(run.dm, X));
  PetscCall(PetscObjectSetName((PetscObject)*X, "solution"));
  PetscCall(attachSolutionView(run, *X));
  PetscCall(DMLocalToGlobal(run.dm, run.initial, INSERT_VALUES, *X));
  PetscCall(VecDuplicate(*X, &run.last_increment));
  PetscCall(VecSet(run.last_increment, 0.0));
  if (checkpoint_path) PetscCall(readCheckpoint(run, *checkpoint_path, *X, resumed));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
