#!/usr/bin/python3
"""A stop from outside keeps the work (issue 23, item 1; docs/checkpoints.md, "A stop from
outside"): a signal sent to `mpiexec` (as a batch scheduler or a terminal does) while a 2-rank
run steps must leave its work up to the last accepted step on disk and a run.yaml that says it
was stopped by a signal, and `-restart` must continue it to the same end as an uninterrupted run.

    stop_signals.py --case NAME        one case (one ctest each, label "faults")
    stop_signals.py --list             the case names

The scene is the joint column of tests/hydraulics (2 layers, a joint with flow) with the run of
the issue: -bc_left_p3 0 -ts_dt 0.25 -ts_max_time 50, here ended by -ts_max_steps 40 (status 1,
as the issue's run ends on the scene's 125), fields
every 5 steps so that fields.h5 and interfaces.h5 are written too, and PETSc's sequential LU on
the gathered matrix (a deterministic direct solver: MUMPS on 2 ranks sums in an order that
depends on timing, docs/checkpoints.md, so the comparison would measure MUMPS, not the stop).

Open MPI's mpiexec answers SIGTERM, SIGINT and SIGHUP by sending the ranks SIGCONT, SIGTERM one
second later and SIGKILL one second after that (odls_base_sigkill_timeout = 1, measured): the
ranks have about a second. A case passes when
  (a) mpiexec exits within 10 s of the signal and no poroseam process is left;
  (b) the output is complete: every row of timeseries.csv has every column, steps 0..k each
      once; fields.h5 and interfaces.h5 open with h5py and hold every output time up to the
      last row (fields every 5 steps);
  (c) run.yaml is valid YAML and its segment says ending "signal" with the signal (never
      "running"), and no step recorded in the time series is lost: the latest checkpoint is of
      step k, the last row, or (a SIGKILL while step k's checkpoint was being written, seen at
      load 18: the row is written before the checkpoint) of step k - 1, which run.yaml names;
  (d) `-restart <dir>` continues it to the end (status and rows as the uninterrupted run) and
      the time series and both HDF5 files equal the uninterrupted run's to 1e-12 of each
      quantity's scale (restart.py's comparison, itself common.largest_series_difference).
Cases: term_np2, int_np2, hup_np2 (the signal after step 20); long_step_np2 (SIGTERM after
step 20 while each later step waits 2.5 s (-test_step_delay): the step in progress cannot end
before mpiexec's SIGKILL, so what survives is what was on disk when the signal came: the
rolling checkpoint of step 20 and the run.yaml the signal handler writes);
stalled_stdout_np2 (SIGTERM after step 20 while nobody reads mpiexec's stdout, a pipe of 4 kB:
the step lines must not hold the run up).
The same functions serve scripts/stop_trials (many trials per signal, idle and busy).
"""
import argparse
import fcntl
import glob
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(TESTS, "verification"))
sys.path.insert(0, os.path.join(TESTS, "restart"))
sys.path.insert(0, HERE)
import bad_input  # noqa: E402  (CRASH: the signatures of a crash in a run's output)
import common  # noqa: E402
import h5py  # noqa: E402
import restart as restart_test  # noqa: E402  (session_processes, the file comparison)
import yaml  # noqa: E402

SCENE = os.path.join(common.SOURCE, "options", "joint_column_2d.opts")
# The run of issue 23 (it ends on the scene's -ts_max_steps 125 at t = 31.25 s, status 1).
RUN = ["-bc_left_p3", "0", "-ts_dt", "0.25", "-ts_max_time", "50", "-output_fields_every", "0"]
DETERMINISTIC = ["-pc_type", "redundant", "-redundant_pc_type", "lu",
                 "-redundant_pc_factor_mat_solver_type", "petsc"]
FIELDS = ["-output_fields_every", "5"]
# The rolling checkpoint after every step (its default, -1, skips steps while a checkpoint
# costs more than a tenth of the steps, as on this tiny scene): then no step may be lost
# whether the run reaches its stop before mpiexec's SIGKILL or not.
EVERY_STEP = ["-checkpoint_rolling_interval", "0"]
# The test stops at step 40 (the trials of scripts/stop_trials run the whole 125 steps).
STEPS = 40
AFTER = 20
EXIT_SECONDS = 10.0
RTOL = 1e-12
SIGNALS = {"TERM": signal.SIGTERM, "INT": signal.SIGINT, "HUP": signal.SIGHUP}
# A step that cannot end before mpiexec's SIGKILL (2 s after the signal): each residual
# evaluation of the steps after AFTER waits this long.
LONG_STEP = ["-test_step_delay", "2.5", "-test_step_delay_after", str(AFTER)]
# ... after fast steps: the rolling checkpoint's automatic interval writes it after each step of
# a model whose steps are long, not after a fast step followed by a long one; this says every
# step, as a model with long steps gets.
LONG_STEP_CHECKPOINTS = ["-checkpoint_rolling_interval", "0"]

# Still running when the signal reaches the ranks: Open MPI forwards SIGTERM 1 s after mpiexec
# gets it, and on a quiet machine the 20 steps after AFTER took less (the stalled-stdout case
# ended at its step limit before the stop: ctest, 2026-11-27). 0.05 s per residual evaluation
# makes them last 2 s at least; the restart and the reference run without it.
STILL_RUNNING = ["-test_step_delay", "0.05", "-test_step_delay_after", str(AFTER)]

CASES = {
    "term_np2": dict(sig="TERM", extra=STILL_RUNNING),
    "int_np2": dict(sig="INT", extra=STILL_RUNNING),
    "hup_np2": dict(sig="HUP", extra=STILL_RUNNING),
    "long_step_np2": dict(sig="TERM", extra=LONG_STEP),
    "stalled_stdout_np2": dict(sig="TERM", stall=True, extra=STILL_RUNNING),
}


def command(out, extra=(), ranks=2):
    return ["mpiexec", "-n", str(ranks), common.EXE, "-options_file", SCENE, "-output_dir", out] \
        + RUN + list(extra)


def environment():
    return restart_test.environment()


def kill_session(session):
    for pid in restart_test.session_processes(session):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


def stop_run(out, extra, sig, after=AFTER, stall=False, timeout=300.0):
    """Starts the run, sends `sig` to mpiexec once rank 0 has printed step `after`, waits for
    it to end. stall: mpiexec's stdout is a pipe of 4 kB that nobody reads after the signal.
    Returns dict(status, exit_seconds (None: still running after EXIT_SECONDS, then killed),
    left (poroseam processes left), log)."""
    proc = subprocess.Popen(command(out, extra), cwd=common.SOURCE, env=environment(),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            start_new_session=True)
    if stall:
        fcntl.fcntl(proc.stdout.fileno(), 1031, 4096)  # F_SETPIPE_SZ: the smallest pipe
    text, reached = [b""], threading.Event()
    stop_reading = threading.Event()
    pattern = re.compile(rb"^step +%d " % after, re.M)

    def read():
        while True:
            if stop_reading.is_set():
                return
            chunk = proc.stdout.read1(65536)
            if not chunk:
                return
            text[0] += chunk
            if not reached.is_set() and pattern.search(text[0]):
                reached.set()
                if stall:
                    stop_reading.set()  # nobody reads mpiexec's stdout from here on
                    return

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    start = time.time()
    while not reached.is_set() and proc.poll() is None and time.time() - start < timeout:
        reached.wait(0.01)
    if not reached.is_set():
        kill_session(proc.pid)
        proc.wait()
        return dict(status=proc.returncode, exit_seconds=None, left=[], log="",
                    error=f"the run ended or stalled before step {after}")
    os.kill(proc.pid, sig)
    signalled = time.time()
    exit_seconds = None
    try:
        proc.wait(timeout=EXIT_SECONDS)
        exit_seconds = time.time() - signalled
    except subprocess.TimeoutExpired:
        kill_session(proc.pid)
        proc.wait()
    deadline = time.time() + 5
    while restart_test.poroseam_processes(proc.pid) and time.time() < deadline:
        time.sleep(0.05)
    left = restart_test.poroseam_processes(proc.pid)
    kill_session(proc.pid)
    if not stall:
        reader.join(timeout=5)
    stop_reading.set()
    try:  # what is left in the pipe (all of it when nobody read after the signal)
        fcntl.fcntl(proc.stdout.fileno(), fcntl.F_SETFL, os.O_NONBLOCK)
        text[0] += proc.stdout.read() or b""
    except (OSError, TypeError):
        pass
    proc.stdout.close()
    return dict(status=proc.returncode, exit_seconds=exit_seconds, left=left,
                log=text[0].decode(errors="replace"), error="")


def series_rows(out):
    """(complete, steps): every row of timeseries.csv has the header's columns and parses."""
    path = os.path.join(out, "timeseries.csv")
    try:
        with open(path) as f:
            lines = f.read().split("\n")
    except OSError:
        return False, []
    if not lines or lines[-1] != "":
        return False, []  # a partial last row (no newline)
    header = lines[0].split(",")
    steps = []
    for line in lines[1:-1]:
        cells = line.split(",")
        if len(cells) != len(header):
            return False, steps
        try:
            [float(c) for c in cells]
        except ValueError:
            return False, steps
        steps.append(int(cells[0]))
    return steps == list(range(len(steps))), steps


def checkpoint_steps(out):
    names = glob.glob(os.path.join(out, "checkpoints", "step-*.h5"))
    return sorted(int(re.search(r"step-(\d+)\.h5$", n).group(1)) for n in names)


def last_segment(out):
    """The last segment of run.yaml (None: missing or not YAML)."""
    try:
        with open(os.path.join(out, "run.yaml")) as f:
            return yaml.safe_load(f)["segments"][-1]
    except (OSError, yaml.YAMLError, KeyError, TypeError, IndexError):
        return None


def h5_times(out, name):
    """Output times in DIR/name.h5 (None: not readable), from the time attributes of its
    datasets, or the number of time groups."""
    path = os.path.join(out, name + ".h5")
    try:
        with h5py.File(path, "r") as f:
            times = set()

            def visit(key, obj):
                if isinstance(obj, h5py.Dataset):
                    obj[()]  # every dataset reads
                    if "time" in obj.attrs:
                        times.add(float(np.ravel(obj.attrs["time"])[0]))
            f.visititems(visit)
            return sorted(times)
    except (OSError, KeyError, ValueError) as e:
        return None


def restart_run(out, extra=()):
    res = subprocess.run(command(out, list(extra) + ["-restart", out]), cwd=common.SOURCE,
                         env=environment(), capture_output=True, text=True, timeout=600)
    with open(os.path.join(out, "restart_log.txt"), "w") as f:
        f.write(res.stdout + res.stderr)
    return res.returncode, res.stdout + res.stderr


def reference(out, extra=()):
    res = subprocess.run(command(out, extra), cwd=common.SOURCE, env=environment(),
                         capture_output=True, text=True, timeout=600)
    if not os.path.isfile(os.path.join(out, "timeseries.csv")):
        common.fail(f"the uninterrupted run wrote no time series:\n{res.stdout[-2000:]}{res.stderr[-2000:]}")
    return res.returncode


def series_difference(a_dir, b_dir):
    """(difference, column, same rows): common.largest_series_difference of two time series."""
    a, b = restart_test.read_series(a_dir), restart_test.read_series(b_dir)
    if a.keys() != b.keys() or len(a["step"]) != len(b["step"]) \
            or not np.array_equal(a["step"], b["step"]):
        return np.inf, "rows", False
    worst, where = common.largest_series_difference(a, b)
    return worst, where, True


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", choices=sorted(CASES))
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    if args.list:
        print("\n".join(CASES))
        return
    if not args.case:
        ap.error("--case or --list")
    case = CASES[args.case]
    sig = SIGNALS[case["sig"]]
    chk = common.Checks(f"stop from outside: SIG{case['sig']} to mpiexec after step {AFTER} "
                        f"({args.case}, 2 ranks)")
    ref = common.output_dir(f"stop_signals_{args.case}_reference")
    short = ["-ts_max_steps", str(STEPS)]
    ref_status = reference(ref, FIELDS + DETERMINISTIC + short)
    out = common.output_dir(f"stop_signals_{args.case}")
    r = stop_run(out, FIELDS + DETERMINISTIC + short + EVERY_STEP + case.get("extra", []), sig,
                 stall=case.get("stall", False))
    with open(os.path.join(out, "log.txt"), "w") as f:
        f.write(r["log"])
    if r["error"]:
        common.fail(r["error"])
    # (a)
    restart_test.expect(chk, r["exit_seconds"] is not None,
                        f"mpiexec exits within {EXIT_SECONDS:g} s of the signal "
                        f"({'%.2f s' % r['exit_seconds'] if r['exit_seconds'] is not None else 'no'})")
    restart_test.expect(chk, not r["left"], f"no poroseam process left ({len(r['left'])})")
    # (mpiexec's "exited on signal 9" when its SIGKILL came first is not a crash of ours)
    crash = [p for p in bad_input.CRASH[:1] + bad_input.CRASH[2:] if re.search(p, r["log"])]
    restart_test.expect(chk, not crash, f"no crash signature in the output ({crash})")
    ended = (last_segment(out) or {}).get("exit_status")
    print(f"  (info) {r['exit_seconds'] or 0:.2f} s from the signal to mpiexec's exit; the run "
          + ("wrote its own record (ended before mpiexec's SIGKILL)" if ended == 1 else
             "was killed first: run.yaml is the one its signal handler wrote"))
    # (b)
    complete, steps = series_rows(out)
    k = steps[-1] if steps else -1
    restart_test.expect(chk, complete and AFTER <= k < STEPS,
                        f"timeseries.csv complete: steps 0..{k}, every row whole")
    for name in ("fields", "interfaces"):
        times = h5_times(out, name)
        expected = [0.25 * s for s in range(0, k + 1, 5)]
        restart_test.expect(chk, times is not None and np.allclose(times, expected),
                            f"{name}.h5 reads, with its {len(expected)} output times up to step {k} "
                            f"({None if times is None else len(times)})")
    # (c)
    seg = last_segment(out)
    restart_test.expect(chk, seg is not None and seg.get("ending") == "signal"
                        and "SIGTERM" in str(seg.get("signal")),
                        "run.yaml: ending 'signal' with the signal (mpiexec forwards SIGTERM), got "
                        + (f"{seg.get('status')}/{seg.get('ending')}/{seg.get('signal')}" if seg else "none"))
    ckpt = checkpoint_steps(out)
    latest = ckpt[-1] if ckpt else -1
    # A step's row is written before its checkpoint (the row's quantities need the state before
    # the history is committed, the checkpoint the state after): a SIGKILL while that checkpoint
    # is written leaves the row without it, and the handler's run.yaml names the one before.
    said = seg is not None and (seg.get("exit_status") == 1 or
                                f"step-{latest:06d}.h5" in str(seg.get("message")))
    restart_test.expect(chk, latest == k or (latest == k - 1 and said),
                        f"the latest checkpoint is of the last recorded step {k}, or of step {k - 1}"
                        f" if the SIGKILL came while step {k}'s was written and run.yaml names it"
                        f" (latest {latest}; run.yaml names it: {said})")
    # (d)
    status, text = restart_run(out, FIELDS + DETERMINISTIC + short)
    restart_test.expect(chk, status == ref_status and f"restart from" in text,
                        f"-restart continues it (status {status}, uninterrupted {ref_status})")
    restart_test.STEPS = STEPS
    restart_test.RTOL = RTOL
    restart_test.compare(ref, out, chk)
    chk.finish()


if __name__ == "__main__":
    main()
