// timeseries.csv: one row per step (docs/scenes.md, "Output"), written by rank 0.
#pragma once

#include "poroseam/scene.hpp"

#include <cstdio>
#include <petscsys.h>
#include <string>
#include <vector>

namespace poroseam {

/// What the time loop knows of one step, before the scene's quantities.
struct StepRow {
  int step = 0;
  double time = 0.0, dt = 0.0, load = 0.0;
  int newton = 0, krylov = 0, rejected = 0; ///< iterations and cut-backs of this step
  double wall = 0.0;                        ///< wall time of this step [s]
};

/// The time series of a run: owns the CSV file (open on rank 0 only; other ranks hold none and
/// write nothing), so that the time loop hands it rows and never sees a FILE*.
class TimeSeries {
public:
  TimeSeries() = default;
  TimeSeries(const TimeSeries &) = delete;
  TimeSeries &operator=(const TimeSeries &) = delete;
  ~TimeSeries() { close(); }

  /// A column of timeseries.csv and its unit (SI, UDUNITS spelling; "1": a number).
  struct Column {
    std::string name, unit;
  };
  /// The columns of timeseries.csv for this scene, in order.
  static std::vector<Column> columns(const Scene &scene);
  /// The header line of timeseries.csv for this scene.
  static std::string header(const Scene &scene);
  /// Opens `<dir>/timeseries.csv` for a new run (resume_step < 0), or, restarting from the
  /// checkpoint of step resume_step, keeps the interrupted run's rows of steps 0..resume_step
  /// (its later rows are dropped: the restarted run writes them again) and appends.
  /// Rank 0 also writes `<dir>/timeseries.csv.units`: the line "column,unit", then one line
  /// "<column>,<unit>" per column. Collective on comm: every rank learns whether rank 0 could.
  PetscErrorCode open(MPI_Comm comm, const Scene &scene, const std::string &dir, int resume_step);
  /// One row: the step's own columns, then the boundary resultants (per boundary: dim forces,
  /// the flux with pressure, the interface outflow with interface pressure, then one outflow
  /// per interface with flow), the interface blocks and the probe values. Rank 0 writes and
  /// flushes (a crashed run keeps its rows). Collective on open()'s comm: a row that rank 0
  /// cannot write whole (a full disk) is taken back and every rank fails with one line.
  PetscErrorCode write(const Scene &scene, const StepRow &row,
                       const std::vector<double> &boundaries, const std::vector<double> &interfaces,
                       const std::vector<double> &probes);
  void close();

private:
  /// Rank 0: `text` at the end of the file with write(2); on failure the file is cut back to
  /// its length before, and the reason returned ("" when written).
  std::string appendRow(const std::string &text);

  FILE *file_ = nullptr;
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string path_;
};

} // namespace poroseam
