// What one step leaves in the outputs (split from simulation.cpp): its row of timeseries.csv
// (the probes with the steady and excess pore pressure, steady_pressure.hpp), and, when due,
// the fields and the interfaces.

#include "run.hpp"

#include <petscsnes.h>
#include <vector>

namespace poroseam {
namespace simulation_detail {

/// One row of timeseries.csv and, every output_every steps and at the `last` step of the run,
/// the fields; the interfaces likewise every interface_output_every steps.
PetscErrorCode recordStep(Run &run, double t, double dt, Vec local, Vec rate, PetscInt newton,
                          PetscInt ksp, PetscInt rejected, double wall, bool last)
{
  std::vector<double> resultants, probes, interface;
  PetscFunctionBeginUser;
  PetscCall(beginLogEvent(run.events.output));
  PetscCall(boundaryResultants(run, t, dt, local, rate, resultants));
  PetscCall(interfaceResultants(run, local, InterfaceRates{rate, dt}, interface));
  PetscCall(run.probes.evaluate(local, probes));
  // The steady pore pressure (steady_pressure.hpp), for the probes and the fields.
  const bool fields_due =
      run.scene.output_every > 0 && (run.step % run.scene.output_every == 0 || last);
  Vec steady = nullptr;
  if (fields_due || !run.scene.probes.empty()) {
    SNES snes;
    Mat J;
    PetscCall(TSGetSNES(run.ts, &snes));
    PetscCall(SNESGetJacobian(snes, nullptr, &J, nullptr, nullptr));
    PetscCall(run.steady.compute(run.problem, t, local, J, &steady));
  }
  if (steady && !run.scene.probes.empty()) {
    std::vector<double> at_steady, both;
    PetscCall(run.probes.evaluate(steady, at_steady));
    const size_t per = run.probes.valuesPerProbe();
    for (size_t i = 0; i < probes.size(); i += per) {
      both.insert(both.end(), probes.begin() + i, probes.begin() + i + per);
      const double p = probes[i + per - 1], p_steady = at_steady[i + per - 1];
      both.push_back(p_steady);
      both.push_back(p - p_steady);
    }
    probes.swap(both);
  }
  PetscCall(run.series.write(run.scene,
                             StepRow{run.step, t, dt, run.problem.loadFactor(t), (int)newton,
                                     (int)ksp, (int)rejected, wall},
                             resultants, interface, probes));
  // The final state always: after cut-backs the step count need not be a multiple of
  // output_every (a run to 3000 s ended with its last field at 2920 s).
  if (fields_due) {
    CellFields cells;
    PetscCall(run.problem.cellFields(local, cells));
    PetscCall(run.fields.write(t, local, steady ? steady : run.initial, &cells));
  }
  const int interface_every = run.scene.interface_output_every;
  if (interface_every > 0 && (run.step % interface_every == 0 || last))
    PetscCall(
        run.interface_fields.write(t, run.problem.interfaces(), local, InterfaceRates{rate, dt}));
  PetscCall(endLogEvent(run.events.output));
  PetscFunctionReturn(0);
}

} // namespace simulation_detail
} // namespace poroseam
