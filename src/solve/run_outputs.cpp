// A run's output files (split from simulate, simulation.cpp): timeseries.csv, the field and
// interface files opened (continued on a restart), the initial state's row, and their closing.
// What each step writes into them is in step_record.cpp.
#include "run_steps.hpp"

#include <string>
#include <vector>

namespace poroseam {
namespace simulation_detail {

PetscErrorCode openOutputs(MPI_Comm comm, Run &run, const CheckpointInfo *resumed)
{
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(run.events.output));
  PetscCall(run.series.open(comm, run.scene, run.scene.output_dir, resumed ? resumed->step : -1));
  if (run.scene.output_every > 0) {
    const std::vector<double> *times = resumed ? &resumed->output_times : nullptr;
    PetscCall(run.fields.open(run.dm, run.scene.output_dir, "fields", times));
    std::vector<PetscInt> cells;
    std::vector<int> regions;
    std::vector<std::string> names;
    run.problem.cellRegions(cells, regions);
    for (const Region &r : run.scene.regions)
      names.push_back(r.name);
    {
      CellFields declared; // the names of the cell fields, from the initial state
      PetscCall(run.problem.cellFields(run.initial, declared));
      run.fields.declareCellFields(declared);
    }
    PetscCall(run.fields.writeRegions(cells, regions, names));
  }
  if (run.scene.interface_output_every > 0) {
    const std::vector<double> *times = resumed ? &resumed->interface_output_times : nullptr;
    PetscCall(run.interface_fields.open(comm, run.scene, run.scene.output_dir, times));
  }
  PetscCall(endLogEvent(run.events.output));
  PetscFunctionReturn(0);
}

PetscErrorCode recordInitialState(Run &run)
{
  Vec rate;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(run.dm, &rate));
  PetscCall(VecSet(rate, 0.0));
  PetscCall(recordStep(run, 0.0, 0.0, run.initial, rate, 0, 0, 0, 0.0));
  PetscCall(DMRestoreLocalVector(run.dm, &rate));
  PetscFunctionReturn(0);
}

PetscErrorCode closeOutputs(Run &run)
{
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(run.events.output));
  run.series.close();
  PetscCall(run.fields.close());
  PetscCall(run.interface_fields.close());
  PetscCall(endLogEvent(run.events.output));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
