#!/usr/bin/python3
"""Checkpoints and restarts (docs/checkpoints.md) on the coarse partially drained axisymmetric
caisson (options/caisson_axisym_partially_drained.opts, -mesh_size_factor 2, dt = 3 s, 60 steps
to 180 s): sliding skirts with committed friction history, an opening lid gap with interface
pressure, fields every 2 steps.

    restart.py --case kill    [--ranks 2] [--seed S]
    restart.py --case signal  [--ranks 2]
    restart.py --case ranks
    restart.py --case stale   [--ranks 2]

kill    the run with -checkpoint_every 2 is killed with SIGKILL (mpiexec and every rank) after
        a random number of steps (5 to 40, from --seed or the clock; printed), possibly while a
        checkpoint is being written; then `-restart <dir>` continues from the latest complete
        checkpoint in the same directory.
signal  the run without -checkpoint_every gets SIGTERM (sent to its ranks, as a batch system
        does) after a random number of steps: it must exit non-zero with "stopped at step N, t = ..."
        and "-restart <dir>", and leave a checkpoint of exactly that step; then the restart.
stale   a new run in the output directory of an earlier one removes the earlier checkpoints,
        field and interface files it does not write itself (nothing of another run is
        mistaken for its own, nor offered to a later -restart).
ranks   a 2-rank checkpoint restarted on 1 rank is refused with a one-line message naming
        the checkpoint and the number of ranks (a checkpoint holds each rank's part of the
        partitioned mesh).
For kill and signal, the continued run's time series (every column but the wall time), field
files (every dataset of fields.h5 and interfaces.h5) and XDMF indexes must equal those of an
uninterrupted run with the same options: the same rows and datasets (none missing, none
duplicated), values within 1e-12 of each quantity's scale (the largest magnitude among the time series
columns of its kind: forces, flows, storage, displacements, pressures; of a dataset, the
largest magnitude of that field over all times). A checkpoint also makes the direct solver
analyse its matrix afresh at the next step, as the restarted run must (the pivot order may
depend on the values of the matrix analysed): the restarted run is then the same computation,
and on a deterministic solver (see SOLVER) measured equal to the last bit.
"""
import argparse
import os
import random
import re
import signal
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402
import h5py  # noqa: E402

SCENE = os.path.join(common.SOURCE, "options", "caisson_axisym_partially_drained.opts")
# The direct solver as a deterministic computation on 2 ranks: the matrix gathered on every rank
# and factored by PETSc's sequential LU (PCREDUNDANT). MUMPS on 2 ranks is not: its dynamic
# scheduling sums contributions in an order that depends on timing, so two runs of the same
# scene differ (measured on this scene: up to 9e-11 of a field's scale in the interface's
# longitudinal flux, a difference of interface pressures). With it this test would measure
# MUMPS, not the restart.
SOLVER = ["-pc_type", "redundant", "-redundant_pc_type", "lu",
          "-redundant_pc_factor_mat_solver_type", "petsc"]
OPTIONS = ["-mesh_size_factor", 2, "-ts_dt", 3, "-ts_max_time", 180, "-ts_max_steps", 100,
           "-output_fields_every", 2] + SOLVER
STEPS = 60
RTOL = 1e-12


def command(out, extra, ranks):
    cmd = [common.EXE, "-options_file", SCENE, "-output_dir", out] + [str(a) for a in OPTIONS + extra]
    return (["mpiexec", "-n", str(ranks)] if ranks > 1 else []) + cmd


def environment():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    return env


def expect(chk, condition, name):
    """A yes/no check in common.Checks' table."""
    chk.check(name, 0.0 if condition else 1.0, 0.0, ok=bool(condition))


def rows(out):
    try:
        with open(os.path.join(out, "timeseries.csv")) as f:
            return sum(1 for _ in f) - 2  # header and row 0
    except OSError:
        return -1


def interrupt(out, extra, ranks, after, sig):
    """Starts the run, sends `sig` once `after` steps are in the time series; returns
    (exit status, output)."""
    log = open(os.path.join(out, "log.txt"), "w")
    proc = subprocess.Popen(command(out, extra, ranks), cwd=common.SOURCE, env=environment(),
                            stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    start = time.time()
    while rows(out) < after and proc.poll() is None and time.time() - start < 300:
        time.sleep(0.001)
    if proc.poll() is not None:
        common.fail(f"the run ended (status {proc.returncode}) before step {after}: nothing to "
                    f"interrupt; see {out}/log.txt")
    if sig == signal.SIGKILL:
        # mpiexec and the ranks (Open MPI puts the ranks in process groups of their own, but
        # they stay in the session): nothing survives to clean up
        for pid in session_processes(proc.pid):
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
    else:
        # To the ranks themselves, as a batch system does (mpiexec would forward a SIGTERM but
        # kill the ranks a second later: docs/checkpoints.md).
        ranks = poroseam_processes(proc.pid)
        if not ranks:
            common.fail("no poroseam process found to signal")
        for pid in ranks:
            os.kill(pid, sig)
    status = proc.wait(timeout=120)
    start = time.time()
    while poroseam_processes(proc.pid) and time.time() - start < 60:
        time.sleep(0.05)
    if poroseam_processes(proc.pid):
        common.fail("poroseam processes of the interrupted run are still alive after 60 s")
    log.close()
    with open(os.path.join(out, "log.txt")) as f:
        return status, f.read()


def poroseam_processes(session):
    """The poroseam processes of a session (the run was started in a new one)."""
    return session_processes(session, "poroseam")


def session_processes(session, name=None):
    """The processes of a session, those of executable `name` only if given."""
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/stat") as f:
                stat = f.read()
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                argv0 = f.read().split(b"\0")[0].decode(errors="replace")
        except OSError:
            continue
        fields = stat[stat.rfind(")") + 2:].split()
        if int(fields[3]) == session and (name is None or os.path.basename(argv0) == name):
            found.append(int(pid))
    return found


def restart(out, extra, ranks):
    cmd = command(out, extra, ranks)
    res = subprocess.run(cmd, cwd=common.SOURCE, env=environment(), capture_output=True, text=True,
                         timeout=600)
    with open(os.path.join(out, "restart_log.txt"), "w") as f:
        f.write(res.stdout + res.stderr)
    return res.returncode, res.stdout + res.stderr


def read_series(out):
    """timeseries.csv as {column: values} (column names as written, dots kept)."""
    path = os.path.join(out, "timeseries.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {h: data[:, i] for i, h in enumerate(header)}


def compare(reference, other, chk):
    a, b = read_series(reference), read_series(other)
    expect(chk, a.keys() == b.keys() and len(a["step"]) == STEPS + 1
           and np.array_equal(a["step"], b["step"]),
           f"time series rows: {len(b['step'])} after the restart, {len(a['step'])} uninterrupted "
           f"(steps 0..{STEPS}, each once)")
    if a.keys() != b.keys() or len(a["step"]) != len(b["step"]):
        return
    worst, where = common.largest_series_difference(a, b)
    chk.check(f"time series: largest difference relative to its kind's scale ({where})",
              worst, RTOL)
    for name in ("fields", "interfaces"):
        fa, fb = h5py.File(os.path.join(reference, name + ".h5")), h5py.File(os.path.join(other, name + ".h5"))
        sets_a, sets_b = [], []
        fa.visititems(lambda k, o: sets_a.append(k) if isinstance(o, h5py.Dataset) else None)
        fb.visititems(lambda k, o: sets_b.append(k) if isinstance(o, h5py.Dataset) else None)
        expect(chk, sorted(sets_a) == sorted(sets_b),
                  f"{name}.h5: the same {len(sets_a)} datasets ({len(sets_b)} after the restart)")
        scale = {}
        for k in sets_a:
            field = k.rsplit("/", 1)[0]
            scale[field] = max(scale.get(field, 0.0), float(np.nanmax(np.abs(fa[k][()]), initial=0.0)))
        worst, where = 0.0, ""
        for k in sets_a:
            if k not in fb:
                continue
            x, y = fa[k][()], fb[k][()]
            if x.shape != y.shape:
                worst, where = np.inf, k + " (shape)"
                break
            if x.size:
                # Pressures are NaN where no porous cell is (the steel): at the same vertices.
                if x.dtype.kind == "f" and not np.array_equal(np.isnan(x), np.isnan(y)):
                    worst, where = np.inf, k + " (NaN elsewhere)"
                    break
                err = float(np.nanmax(np.abs(x - y), initial=0.0)) / max(scale[k.rsplit("/", 1)[0]], 1e-300)
                if err > worst:
                    worst, where = err, k
            for attr in fa[k].attrs:
                if not np.array_equal(fa[k].attrs[attr], fb[k].attrs.get(attr)):
                    worst, where = np.inf, f"{k} attribute {attr}"
        chk.check(f"{name}.h5: largest difference relative to its field's scale ({where or 'none'})",
                  worst, RTOL)
        for index in (["fields"] if name == "fields" else ["interface_cells", "interface_points"]):
            with open(os.path.join(reference, index + ".xmf")) as f1, open(os.path.join(other, index + ".xmf")) as f2:
                expect(chk, f1.read() == f2.read(), f"{index}.xmf: the same index")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", choices=["kill", "signal", "ranks", "stale"], required=True)
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--seed", type=int, default=None)
    args = ap.parse_args()
    seed = args.seed if args.seed is not None else int(time.time())
    after = random.Random(seed).randint(5, 40)
    chk = common.Checks(f"restart, {args.case} ({args.ranks} ranks, seed {seed}: after step {after})")

    if args.case == "stale":
        out = common.output_dir("restart_stale")
        status, _ = restart(out, ["-ts_max_time", 12, "-checkpoint_every", 2], args.ranks)
        expect(chk, status == 0 and os.path.isfile(os.path.join(out, "checkpoints", "step-000004.h5"))
               and os.path.isfile(os.path.join(out, "fields.h5")), "a first run with checkpoints and fields")
        status, _ = restart(out, ["-ts_max_time", 6, "-output_fields_every", 0, "-output_interfaces_every", 0],
                            args.ranks)
        left = [f for f in ("checkpoints", "fields.h5", "fields.xmf", "interfaces.h5", "interface_cells.xmf",
                            "interface_points.xmf") if os.path.exists(os.path.join(out, f))]
        expect(chk, status == 0 and not left,
               f"a second run in the same directory without them leaves none of the first's: {left}")
        expect(chk, rows(out) == 2, f"its time series has its own 2 steps ({rows(out)})")
        chk.finish()
        return

    if args.case == "ranks":
        out = common.output_dir("restart_ranks")
        status, text = restart(out, ["-ts_max_time", 12, "-checkpoint_every", 2], 2)
        expect(chk, status == 0, "a 2-rank run of 4 steps with checkpoints")
        status, text = restart(out, ["-restart", out, "-ts_max_time", 24], 1)
        lines = [l for l in text.splitlines() if "error" in l]
        expect(chk, status != 0 and len(lines) == 1 and "2 MPI ranks" in lines[0]
                  and "step-000004.h5" in lines[0] and "mpiexec -n 2" in lines[0],
                  f"restart on 1 rank refused in one line: {lines[:2]}")
        expect(chk, "PETSC ERROR" not in text and "Segmentation" not in text, "without PETSc's traceback")
        chk.finish()
        return

    reference = common.output_dir(f"restart_{args.case}_uninterrupted")
    common.run(SCENE, reference, OPTIONS, ranks=args.ranks, timeout=600)
    out = common.output_dir(f"restart_{args.case}")
    if args.case == "kill":
        status, text = interrupt(out, ["-checkpoint_every", 2], args.ranks, after, signal.SIGKILL)
        done = rows(out)
        expect(chk, 0 < done < STEPS, f"killed after step {done} of {STEPS}")
        leftovers = [f for f in os.listdir(os.path.join(out, "checkpoints")) if f.endswith(".partial")]
        print(f"checkpoints left: {sorted(os.listdir(os.path.join(out, 'checkpoints')))}")
        status, text = restart(out, ["-restart", out, "-checkpoint_every", 2], args.ranks)
        m = re.search(r"restart from \S+step-(\d+)\.h5: step (\d+)", text)
        expect(chk, status == 0 and m is not None,
                  f"restart from the latest complete checkpoint (step {m.group(2) if m else '?'}; "
                  f"{len(leftovers)} partial file(s) ignored), status {status}")
    else:
        status, text = interrupt(out, [], args.ranks, after, signal.SIGTERM)
        m = re.search(r"stopped at step (\d+), t = (\S+) s.*signal.*continue with -restart (\S+)", text)
        expect(chk, status != 0, f"exit status {status} after SIGTERM (non-zero)")
        expect(chk, m is not None and m.group(3) == out,
                  "the message says where it stopped and how to restart: "
                  + (m.group(0)[:120] if m else text.strip().splitlines()[-1][:200]))
        stopped = int(m.group(1)) if m else -1
        have = sorted(os.listdir(os.path.join(out, "checkpoints"))) if os.path.isdir(os.path.join(out, "checkpoints")) else []
        expect(chk, have == [f"step-{stopped:06d}.h5"], f"one checkpoint, of step {stopped}: {have}")
        expect(chk, rows(out) == stopped, f"time series up to that step ({rows(out)} rows)")
        status, text = restart(out, ["-restart", out], args.ranks)
        expect(chk, status == 0, f"the restart runs to the end (status {status})")
    compare(reference, out, chk)
    chk.finish()


if __name__ == "__main__":
    main()
