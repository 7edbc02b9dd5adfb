"""Shared helpers of the verification drivers: run poroseam on a scene, read its outputs,
collect pass/fail checks.

Environment (set by ctest, see tests/CMakeLists.txt; defaults for running a driver by hand
from the source tree):
    POROSEAM_EXE          the executable            (default <source>/build/poroseam)
    POROSEAM_SOURCE       the source tree           (default: two levels above this file)
    POROSEAM_TEST_OUTPUT  scratch directory         (default /tmp/poroseam-test-output)
    POROSEAM_SOLVER       a preset of options/solvers/ (e.g. fieldsplit) added after every
                          run's options, so a driver checks its closed form with that solver;
                          outputs then go to a sub-directory solver-<preset> of the scratch one
"""

import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")
SOLVER = os.environ.get("POROSEAM_SOLVER", "")
SOLVER_OPTIONS = []
if SOLVER:
    SOLVER_OPTIONS = ["-options_file", os.path.join(SOURCE, "options", "solvers", SOLVER + ".opts")]
    if not os.path.isfile(SOLVER_OPTIONS[1]):
        sys.exit(f"POROSEAM_SOLVER={SOLVER}: no preset {SOLVER_OPTIONS[1]}")
    OUTPUT_ROOT = os.path.join(OUTPUT_ROOT, "solver-" + SOLVER)

sys.path.insert(0, os.path.join(SOURCE, "tests", "support"))
sys.path.append(SOURCE)
from study import analytic  # noqa: E402  (study/analytic.py, shared with scripts/study)


def scene_path(name):
    """Absolute path of a scene file of tests/verification/."""
    return os.path.join(HERE, name)


def read_scene(path):
    """The options of a PETSc options file as a dict {'-name': 'value' or ''}."""
    opts = {}
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            parts = line.split(None, 1)
            opts[parts[0]] = parts[1].strip() if len(parts) > 1 else ""
    return opts


def output_dir(name):
    """A fresh scratch directory POROSEAM_TEST_OUTPUT/verification/<name>."""
    d = os.path.join(OUTPUT_ROOT, "verification", name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def run(scene, out_dir, args=(), ranks=1, timeout=300):
    """Runs `[mpiexec -n ranks] poroseam -options_file scene -output_dir out_dir args...` from
    the source tree (so that scene paths such as meshes/x.geo resolve).  Returns the wall time.
    Exits the driver with a message (and the end of the log) when the run fails."""
    if not os.path.isfile(EXE):
        fail(f"poroseam executable not found: {EXE} (set POROSEAM_EXE)")
    cmd = [EXE, "-options_file", scene, "-output_dir", out_dir] + [str(a) for a in args]
    cmd += SOLVER_OPTIONS
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks)] + cmd
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    log = os.path.join(out_dir, "log.txt")
    shown = " ".join(cmd)
    print("run:", shown if len(shown) < 400 else shown[:400] + f" ... ({len(cmd)} arguments)",
          flush=True)
    t0 = time.time()
    with open(log, "w") as f:
        try:
            rc = subprocess.run(cmd, cwd=SOURCE, env=env, stdout=f, stderr=subprocess.STDOUT,
                                timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            rc = "timeout"
    wall = time.time() - t0
    if rc != 0:
        with open(log) as f:
            tail = f.readlines()[-30:]
        fail(f"poroseam failed (exit {rc}) after {wall:.1f} s; log {log}:\n" + "".join(tail))
    print(f"     done in {wall:.1f} s", flush=True)
    return wall


def read_timeseries(out_dir):
    """DIR/timeseries.csv as a dict column name -> numpy array, one entry per time step.

    The row of step 0 (the initial state at t = 0, written before the first step) is
    dropped, so that entry i is the state after step i + 1."""
    path = os.path.join(out_dir, "timeseries.csv")
    if not os.path.isfile(path):
        fail(f"no time series written: {path}")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.shape[0] == 0:
        fail(f"{path} has no rows")
    cols = {name.strip(): data[:, i] for i, name in enumerate(header)}
    if "step" in cols:
        keep = cols["step"] > 0
        cols = {k: v[keep] for k, v in cols.items()}
    return cols


def series_kind(column):
    """The quantity a time-series column is judged against: its last name part with the
    component dropped (Fx, Fy, Fz -> F; ux, uy, uz -> u), so all forces share one scale."""
    return re.sub(r"^(F|u)[xyz]$", r"\1", column.rsplit(".", 1)[-1])


def largest_series_difference(a, b, skip=("wall_time",)):
    """Largest difference between two time series ({column: values}, the same rows) over
    their columns, each relative to the largest magnitude of its kind (series_kind) in a.
    Returns (difference, column), column "none" when every difference is zero."""
    names = [n for n in a if n not in skip]
    scales = {}
    for n in names:
        scales[series_kind(n)] = max(scales.get(series_kind(n), 0.0), np.max(np.abs(a[n])))
    worst, where = 0.0, "none"
    for n in names:
        err = np.max(np.abs(a[n] - b[n])) / max(scales[series_kind(n)], 1e-300)
        if err > worst:
            worst, where = err, n
    return worst, where


def column(ts, name):
    if name not in ts:
        fail(f"timeseries.csv has no column '{name}' (columns: {', '.join(ts)})")
    return ts[name]


def step_index(ts, t, rtol=1e-6):
    """Index of the row whose time equals t (to rtol of t); fails if there is none."""
    times = column(ts, "time")
    i = int(np.argmin(np.abs(times - t)))
    if abs(times[i] - t) > rtol * max(abs(t), 1e-300):
        fail(f"no step at t = {t} (nearest {times[i]}); was the time step cut?")
    return i


def vertex_fields(out_dir, index=-1):
    """(time, coordinates (Nv, dim), {field: values}) of one output time of DIR/fields.xmf+h5,
    read with tests/support/fields_reader.py (fields: displacement (Nv, 3), pressure (Nv,),
    excess_pressure (Nv,)).  The run must have written fields (-output_fields_every 1)."""
    import fields_reader  # tests/support/fields_reader.py
    try:
        f = fields_reader.read_fields(out_dir)
    except fields_reader.FieldsError as e:
        fail(f"cannot read the field output of {out_dir}: {e}")
    if not f.fields:
        fail(f"no field output in {out_dir}")
    return f.times[index], np.asarray(f.coordinates), f.fields[index]


class Checks:
    """Collects named checks, prints a table, exits non-zero if any failed."""

    def __init__(self, title):
        self.title = title
        self.rows = []
        print(f"== {title}", flush=True)

    def check(self, name, measured, tolerance, ok=None, unit=""):
        """Passes when measured <= tolerance (or when `ok` is given, when ok is True)."""
        passed = bool(measured <= tolerance) if ok is None else bool(ok)
        if not np.isfinite(measured):
            passed = False
        self.rows.append((name, measured, tolerance, passed))
        print(f"  {'PASS' if passed else 'FAIL'}  {name}: {measured:.4g}  (tolerance {tolerance:.4g}{unit})",
              flush=True)
        return passed

    def finish(self):
        failed = [r for r in self.rows if not r[3]]
        if failed:
            print(f"== {self.title}: {len(failed)} of {len(self.rows)} checks FAILED:")
            for name, m, tol, _ in failed:
                print(f"   {name}: {m:.4g} > {tol:.4g}")
            sys.exit(1)
        print(f"== {self.title}: all {len(self.rows)} checks passed")
        sys.exit(0)


def fail(message):
    print("ERROR: " + message, file=sys.stderr, flush=True)
    sys.exit(1)


def time_table(out, name, times, values):
    """Writes a time function table (-bc_<b>_<q>_table: "time,factor" rows) into out and
    returns its path."""
    path = os.path.join(out, name)
    with open(path, "w") as f:
        f.write("time,factor\n")
        for t, v in zip(times, values):
            f.write(f"{t},{v!r}\n")
    return path
