#!/usr/bin/python3
"""A small plastic scene through the whole program (tests/plasticity/footing_block.opts: an
elastic block pressed into a porous Mohr-Coulomb layer with the geostatic state, 20 steps):

    scene.py --case newton    Newton's residual histories: quadratic near convergence
    scene.py --case ranks     2 ranks equal 1 rank
    scene.py --case restart   a run stopped at step 12 and restarted from its checkpoint equals
                              the uninterrupted run

newton  the run needs no cut-back, at most 8 Newton iterations a step, and the order of the last
        iteration above the round-off floor (1e-5 N: the converged residuals level off at
        ~5e-7 N on this scene), log(r_k+1 / r_k) / log(r_k / r_k-1), has a median >= 1.7 over the
        steps (the consistent tangent; a single triplet is noisy, measured 1.3 to 4.9, median 2.1).
        The soil must have yielded: some cells on a face of the cone and plastic strain > 0.
ranks   the time series (forces, probes) and every cell field of the last step (stresses,
        strain, equivalent plastic strain, yield state; cells matched by their centroids) of
        2 ranks equal 1 rank's within 1e-9 of each quantity's scale (MUMPS on 2 ranks sums in
        an order that depends on timing: round-off differences, amplified by nothing larger
        than the Newton tolerance). The yield states must be identical.
restart the plastic history is in the checkpoint: the restarted run's time series (all but the
        wall time) and fields.h5 (every dataset of every step) equal the uninterrupted run's
        within 1e-12 of each quantity's scale (1 rank: the same computation; a checkpoint makes
        the direct solver analyse its matrix afresh, as the restarted run must).
--order 2: every run with -displacement_order 2 (the history of more integration points per
        cell in the checkpoint, the probes on the quadratic field).
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, HERE)
import common  # noqa: E402
import fields_reader  # noqa: E402  (tests/support, on common's path)
import h5py  # noqa: E402
import newton_history  # noqa: E402

SCENE = os.path.join(HERE, "footing_block.opts")
FLOOR = 1e-5
ORDER = []  # -displacement_order 2 with --order 2
TAG = ""  # output directory suffix with --order 2


def orders(residuals, floor):
    """Observed orders log(r_k+1 / r_k) / log(r_k / r_k-1) for the iterations whose residuals
    are all above `floor` (below it round-off, not Newton, sets the residual) and falling."""
    q = []
    for k in range(1, len(residuals) - 1):
        r0, r1, r2 = residuals[k - 1], residuals[k], residuals[k + 1]
        if min(r0, r1, r2) <= floor or r1 >= r0:
            continue
        q.append(math.log(r2 / r1) / math.log(r1 / r0))
    return q


def read_fields(out):
    try:
        return fields_reader.read_fields(out)
    except fields_reader.FieldsError as e:
        common.fail(f"{out}: {e}")


def by_centroid(f, index=-1):
    c = f.coordinates[f.connectivity].mean(axis=1)
    key = [tuple(np.round(x, 9)) for x in c]
    order = sorted(range(len(key)), key=lambda i: key[i])
    return np.array([key[i] for i in order]), {n: v[order] for n, v in f.cell_fields[index].items()}


def case_newton(chk):
    out = common.output_dir("plastic_scene_newton" + TAG)
    common.run(SCENE, out, ["-snes_monitor"] + ORDER)
    ts = common.read_timeseries(out)
    chk.check("steps cut back", float(np.sum(common.column(ts, "rejected"))), 0)
    chk.check("most Newton iterations of a step", float(np.max(common.column(ts, "newton_its"))), 8)
    last = []
    for step, res in newton_history.histories(os.path.join(out, "log.txt")):
        measured = orders(res, FLOOR)
        print("  " + newton_history.describe(step, res) +
              ("  orders " + ", ".join(f"{o:.2f}" for o in measured) if measured else ""))
        if measured:
            last.append(measured[-1])
    chk.check("steps with an order measured (of 20)", -float(len(last)), -15)
    chk.check("median order of the last iteration above 1e-5 N", -float(np.median(last)), -1.7)
    f = read_fields(out)
    cells = f.cell_fields[-1]
    states = np.bincount(cells["yield_state"].astype(int).ravel(), minlength=5)
    print(f"  last step: cells elastic {states[0]}, face {states[1]}, edge {states[2]}, "
          f"apex {states[3]}, tension {states[4]}; max equivalent plastic strain "
          f"{np.max(cells['equivalent_plastic_strain']):.3g}")
    chk.check("cells on a face of the cone at the last step", -float(states[1]), -1)
    chk.check("max equivalent plastic strain", -float(np.max(cells["equivalent_plastic_strain"])),
              -1e-6)
    region = cells["region"].astype(int).ravel()
    block = f.region_names.index("block") if "block" in f.region_names else 1
    chk.check("plastic state in the elastic block (cells)",
              float(np.sum(cells["yield_state"].ravel()[region == block] != 0)), 0)


def case_ranks(chk):
    runs = []
    for ranks in (1, 2):
        out = common.output_dir(f"plastic_scene_np{ranks}" + TAG)
        common.run(SCENE, out, ["-output_fields_every", 20] + ORDER, ranks=ranks)
        runs.append((common.read_timeseries(out), read_fields(out)))
    (t1, f1), (t2, f2) = runs
    # Scale of a column: the largest magnitude among the columns of its kind (forces, flows,
    # displacements, pressures), so that a column of round-off (the flow through an impervious
    # boundary, the force on a free surface) is compared with the quantities it is noise of.
    kinds = {".Fx": "force", ".Fy": "force", ".Fz": "force", ".flux": "flow", ".ux": "u",
             ".uy": "u", ".uz": "u", ".p": "p"}
    kind = {n: next((k for s_, k in kinds.items() if n.endswith(s_)), n) for n in t1}
    scale = {}
    for n, k in kind.items():
        scale[k] = max(scale.get(k, 1e-300), np.max(np.abs(t1[n])))
    worst = {}
    for name in t1:
        if name in ("wall_time", "ksp_its", "newton_its") or name not in t2:
            continue
        d = np.max(np.abs(t2[name] - t1[name])) / scale[kind[name]]
        if d >= worst.get(kind[name], (-1, ""))[0]:
            worst[kind[name]] = (d, name)
    for k, (d, name) in worst.items():
        chk.check(f"timeseries {k} (worst column {name}): max |2 ranks - 1 rank| / scale", d, 1e-9)
    (k1, c1), (k2, c2) = by_centroid(f1), by_centroid(f2)
    chk.check("cells of 2 ranks not at the places of 1 rank's",
              float(len(k1) != len(k2) or not np.array_equal(k1, k2)), 0)
    for name in ("effective_stress", "total_stress", "strain", "equivalent_plastic_strain"):
        scale = max(np.max(np.abs(c1[name])), 1e-300)
        chk.check(f"{name}: max |2 ranks - 1 rank| / scale", np.max(np.abs(c2[name] - c1[name])) /
                  scale, 1e-9)
    chk.check("cells whose yield state differs", float(np.sum(c2["yield_state"] != c1["yield_state"])),
              0)


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.__setitem__(n, o[...]) if isinstance(o, h5py.Dataset) else None)
    return out


def case_restart(chk):
    full = common.output_dir("plastic_scene_full" + TAG)
    common.run(SCENE, full, ["-checkpoint_every", 6] + ORDER)
    part = common.output_dir("plastic_scene_part" + TAG)
    # Stops at step 12 (exit non-zero, a checkpoint of step 12), then continues.
    cmd = [common.EXE, "-options_file", SCENE, "-output_dir", part, "-ts_max_steps", "12",
           "-checkpoint_every", "6"] + [str(a) for a in ORDER]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with open(os.path.join(part, "log_first.txt"), "w") as log:
        rc = subprocess.run(cmd, cwd=common.SOURCE, env=env, stdout=log,
                            stderr=subprocess.STDOUT).returncode
    chk.check("the stopped run exits non-zero", float(rc == 0), 0)
    chk.check("checkpoint of step 12 written",
              float(not os.path.isfile(os.path.join(part, "checkpoints", "step-000012.h5"))), 0)
    with h5py.File(os.path.join(part, "checkpoints", "step-000012.h5"), "r") as f:
        history = f["skeleton_history"][...] if "skeleton_history" in f else np.zeros(0)
    chk.check("plastic history in the checkpoint (max value)", -float(np.max(np.abs(history),
                                                                             initial=0.0)), -1e-9)
    common.run(SCENE, part, ["-restart", part, "-checkpoint_every", 6] + ORDER)
    a, b = common.read_timeseries(full), common.read_timeseries(part)
    chk.check("rows", float(len(a["step"]) != len(b["step"])), 0)
    worst = 0.0
    for name in a:
        if name == "wall_time":
            continue
        scale = max(np.max(np.abs(a[name])), 1e-300)
        worst = max(worst, np.max(np.abs(a[name] - b[name])) / scale)
    chk.check("timeseries: max |restarted - uninterrupted| / scale", worst, 1e-12)
    da, db = datasets(os.path.join(full, "fields.h5")), datasets(os.path.join(part, "fields.h5"))
    chk.check("fields.h5 datasets missing or extra", float(set(da) != set(db)), 0)
    worst, where = 0.0, ""
    for name in da:
        if name not in db or da[name].shape != db[name].shape:
            worst, where = np.inf, name
            continue
        x, y = np.nan_to_num(da[name].astype(float)), np.nan_to_num(db[name].astype(float))
        scale = max(np.max(np.abs(x)), 1e-300)
        d = np.max(np.abs(x - y)) / scale if x.size else 0.0
        if d > worst:
            worst, where = d, name
    chk.check(f"fields.h5: max |restarted - uninterrupted| / scale (worst: {where})", worst, 1e-12)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=["newton", "ranks", "restart"])
    ap.add_argument("--order", type=int, default=1, choices=(1, 2), help="-displacement_order")
    args = ap.parse_args()
    case = args.case
    global TAG
    if args.order == 2:
        ORDER.extend(["-displacement_order", 2])
        TAG = "_order2"
    chk = common.Checks(f"plastic scene, {case}" + (", displacement order 2" if ORDER else ""))
    {"newton": case_newton, "ranks": case_ranks, "restart": case_restart}[case](chk)
    chk.finish()


if __name__ == "__main__":
    main()
