// run.yaml: the record of a run in its output directory (docs/scenes.md, "Run record").
#pragma once

#include <petscsys.h>
#include <string>
#include <utility>
#include <vector>

namespace poroseam {

/// How a run ended: describeEnding's outcomes, an error before or outside the time loop, or
/// not yet (the record written at the start, or left by a killed run).
enum class RunEnding { running, success, failed_step, step_limit, signal, error };
const char *runEndingName(RunEnding ending);

/// Totals of one run (or one segment of a restarted run).
struct RunSummary {
  int steps = 0;          ///< steps taken by this run
  int first_step = 0;     ///< the step it started from (0, or the checkpoint's)
  int last_step = 0;      ///< the last accepted step
  double time = 0.0;      ///< simulated time reached [s]
  int steps_cut_back = 0; ///< accepted steps that needed at least one cut-back
  long rejected = 0;      ///< attempts rejected (cut back), the last failed step's included
  long newton = 0, krylov = 0;
  double wall = 0.0;                  ///< from the record's start to the end [s]
  double stepping_wall = 0.0;         ///< of that, the time loop [s]
  std::vector<double> peak_memory_mb; ///< per rank: the high-water mark of its resident memory
};

/// Where a running run has got: its last accepted step, recorded after each one so that the
/// record of a run killed later says what survived and how to continue.
struct RunProgress {
  int step = 0;           ///< the last accepted step
  double time = 0.0;      ///< its time [s]
  std::string checkpoint; ///< the checkpoint of that step ("": none)
};

/// The record of a run, written by rank 0 as YAML under a temporary name and renamed, so a
/// reader never sees half a file: at the start (ending: running), when the unknowns are known,
/// after each accepted step (progress: what a killed run leaves), and at the end, also when
/// the run ends in an error. A restarted run appends its segment to
/// the interrupted run's record.
class RunRecord {
public:
  /// Notes the start time, the options as PETSc holds them (scene file and command line), the
  /// versions and the ranks, and writes the record. Collective.
  PetscErrorCode begin(MPI_Comm comm, const std::string &output_dir, bool restart);
  /// Unknowns per field (the 'field ... unknowns' lines), written at once. Collective.
  PetscErrorCode setUnknowns(MPI_Comm comm, const std::vector<std::pair<std::string, long>> &f);
  /// The linear solver taken (the 'solver ...' line: "preset direct (auto, the default: ...)",
  /// "as given (-pc_type lu)"), written at once. Collective.
  PetscErrorCode setSolver(MPI_Comm comm, const std::string &solver);
  /// The end of a run that reached its time loop's end: gathers the peak memory of every rank
  /// (collective), writes the final record and prints the summary. `stop_signal`: the
  /// signal that stopped the run (0: none).
  PetscErrorCode finish(MPI_Comm comm, RunEnding ending, const std::string &message,
                        RunSummary summary, int stop_signal = 0);
  /// Rank 0, no communication: records the last accepted step (a 'progress' block, the run
  /// still 'running') and writes the record; false if it could not.
  bool progress(const RunProgress &progress);
  /// The whole file as it would be if a stop signal (written where `signal_mark` is) ended the
  /// run during the step after the last progress(): for StopRequest's handler.
  std::string textIfStopped(char signal_mark) const;
  /// The end of a run stopped by an error (on any one rank): rank 0 writes what it knows, without
  /// communication, since the other ranks may not be there. No-op if begin() did not run or
  /// finish() did.
  void abandon(PetscErrorCode error);
  /// run.yaml's path.
  const std::string &path() const { return path_; }
  /// Wall time since begin() [s].
  double elapsed() const;

private:
  std::string text() const;
  std::string stoppedMessage(const std::string &signal) const;
  bool write() const; ///< rank 0: the whole file, atomically; false if it could not
  /// Collective: rank 0 writes; every rank fails together, naming the reason, if it could not.
  PetscErrorCode writeOnRankZero(MPI_Comm comm) const;
  mutable std::string write_error_; ///< why the last write() failed

  int rank_ = 0, size_ = 1;
  bool begun_ = false, finished_ = false;
  std::string path_, output_dir_;
  std::string earlier_; ///< the interrupted run's record (segments before this one)
  bool restart_ = false;
  double start_wall_ = 0.0;
  std::string start_, end_;
  std::string command_line_, scene_files_;
  std::vector<std::pair<std::string, std::string>> options_; ///< name, value ("\x01": none)
  std::vector<std::pair<std::string, long>> unknowns_;
  std::string solver_; ///< "" until known
  RunEnding ending_ = RunEnding::running;
  int exit_status_ = 0;
  std::string message_;
  RunSummary summary_;
  bool has_summary_ = false;
  RunProgress progress_;
  bool has_progress_ = false;
  std::string progress_at_; ///< when the last accepted step was recorded (UTC)
  std::string signal_;      ///< the signal that stopped the run (in an armed record)
};

} // namespace poroseam
