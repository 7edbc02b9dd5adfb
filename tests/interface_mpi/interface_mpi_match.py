#!/usr/bin/python3
"""Interfaces on several ranks: 1 rank vs N ranks with a chosen partitioner (labels
"interface;mpi").

    interface_mpi_match.py --case shear_2d | shear_3d | shear_3d_tet | buried_crack_2d |
                                  buried_crack_3d
                           --partitioner simple | metis | ptscotch  [--ranks 2] [--rtol 1e-8]

Runs the scene on 1 rank and on --ranks ranks with -partitioner <p> -partitioner_report
(direct solver, MUMPS LU, from the scene), then checks

  partition: the report line of the N-rank run ("cohesive cells with a bulk neighbour on
      another rank: k of n"): n equals the 1-rank count; with simple, k > 0 (the partition
      cuts through the interface, so the assembly over cohesive cells whose bulk neighbour
      is on another rank is exercised); with metis, k == 0 (heavy cohesive-bulk edges).
  unknowns: the printed displacement unknown counts are equal.
  timeseries.csv: the comparison of tests/mpi/mpi_match.py (imported): same header and rows,
      integer columns (step, newton_its, ksp_its, rejected) equal, every other column except
      wall_time to rtol of the column's largest magnitude over both runs, floored at 1e-6 of
      the largest magnitude of the same quantity (forces, displacements, ...).

The shear cases are options/block_shear_2d.opts and block_shear_3d.opts (the tet case with
meshes/block_on_base_3d_tet.geo), shortened to 12 steps (t = 6 s: stick, spreading slip and
full sliding) and with Newton converged to round-off (-snes_rtol 1e-12 -snes_reference_rtol
1e-12), so that the values compare the solutions and not where Newton happened to stop (at
the default tolerances columns that are zero up to round-off, such as the y forces of the
3D scene, differ by 1e-11 of the force scale, which the 1e-6 floor does not absorb); the
buried cracks are tests/interface_mpi/buried_crack_*.opts with the interface added.
Newton and Krylov iteration counts must be equal per step, as in tests/mpi/mpi_match.py.
"""

import argparse
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(SOURCE, "tests", "verification"))
sys.path.insert(0, os.path.join(SOURCE, "tests", "mpi"))
import common  # noqa: E402  (run, output_dir, Checks, fail)
import mpi_match  # noqa: E402  (read_csv, quantity, INTEGER_COLUMNS, SKIP_COLUMNS)

CRACK_INTERFACE = ["-interfaces", "crack", "-interface_crack_side1", "rock",
                   "-interface_crack_KN", "1e10", "-interface_crack_KT", "1e10",
                   "-interface_crack_friction", "0.5"]
SHORT = ["-ts_max_steps", "12", "-ts_max_time", "6", "-output_fields_every", "0",
         "-snes_rtol", "1e-12", "-snes_reference_rtol", "1e-12"]
CASES = {
    "shear_2d": dict(scene="options/block_shear_2d.opts", args=SHORT),
    "shear_3d": dict(scene="options/block_shear_3d.opts", args=SHORT),
    "shear_3d_tet": dict(scene="options/block_shear_3d.opts",
                         args=SHORT + ["-mesh", "meshes/block_on_base_3d_tet.geo"]),
    "buried_crack_2d": dict(scene="tests/interface_mpi/buried_crack_2d.opts",
                            args=CRACK_INTERFACE),
    "buried_crack_3d": dict(scene="tests/interface_mpi/buried_crack_3d.opts",
                            args=CRACK_INTERFACE),
}
REPORT = re.compile(r"partition: (\w+), (\d+) ranks?, cells per rank ([\d ]+); cohesive cells "
                    r"with a bulk neighbour on another rank: (\d+) of (\d+)")
UNKNOWNS = re.compile(r"field (\w+)\s+(\d+) unknowns")


def read_log(out_dir):
    with open(os.path.join(out_dir, "log.txt")) as f:
        text = f.read()
    m = REPORT.search(text)
    report = None
    if m:
        report = dict(partitioner=m.group(1), ranks=int(m.group(2)),
                      cells=[int(x) for x in m.group(3).split()],
                      separated=int(m.group(4)), cohesive=int(m.group(5)))
    unknowns = {name: int(n) for name, n in UNKNOWNS.findall(text)}
    return report, unknowns


def compare_timeseries(checks, dir1, dir2, rtol, label):
    """tests/mpi/mpi_match.py's comparison of two timeseries.csv."""
    h1, d1 = mpi_match.read_csv(dir1)
    h2, d2 = mpi_match.read_csv(dir2)
    checks.check("timeseries headers equal", 0 if h1 == h2 else 1, 0, ok=h1 == h2)
    checks.check("timeseries row counts equal", abs(len(d1) - len(d2)), 0)
    if h1 != h2 or len(d1) != len(d2):
        print("  header 1 rank:", h1, "\n  header", label, ":", h2)
        return
    for name in mpi_match.INTEGER_COLUMNS:
        if name not in h1:
            continue
        i = h1.index(name)
        bad = np.nonzero(d1[:, i] != d2[:, i])[0]
        for r in bad[:5]:
            print(f"    {name} differs at step {int(d1[r, 0])}: {d1[r, i]:g} (1 rank) vs "
                  f"{d2[r, i]:g} ({label})")
        checks.check(f"{name}: rows that differ", len(bad), 0)
    skip = set(mpi_match.INTEGER_COLUMNS) | set(mpi_match.SKIP_COLUMNS)
    group_max = {}
    for i, name in enumerate(h1):
        if name in skip:
            continue
        col = np.r_[d1[:, i], d2[:, i]]
        m = np.nanmax(np.abs(col)) if np.any(np.isfinite(col)) else 0.0
        group_max[mpi_match.quantity(name)] = max(group_max.get(mpi_match.quantity(name), 0.0), m)
    worst = (0.0, "")
    for i, name in enumerate(h1):
        if name in skip:
            continue
        x, y = d1[:, i], d2[:, i]
        nan_mismatch = int(np.sum(np.isnan(x) != np.isnan(y)))
        if nan_mismatch:
            checks.check(f"{name}: rows NaN on one run only", nan_mismatch, 0)
            continue
        ok = np.isfinite(x)
        if not np.any(ok):
            continue
        ref = max(np.max(np.abs(np.r_[x[ok], y[ok]])), 1e-6 * group_max[mpi_match.quantity(name)])
        if ref == 0.0:
            continue
        rel = np.max(np.abs(x[ok] - y[ok])) / ref
        if rel > worst[0] or not worst[1]:
            worst = (rel, name)
        if rel > rtol:
            checks.check(f"timeseries column {name}: max relative difference", rel, rtol)
    checks.check(f"timeseries: largest relative difference of all columns ({worst[1]})",
                 worst[0], rtol)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--partitioner", required=True, choices=["simple", "metis", "ptscotch"])
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=1e-8)
    a = ap.parse_args()
    case = CASES[a.case]
    scene = os.path.join(SOURCE, case["scene"])
    label = f"{a.ranks} ranks ({a.partitioner})"
    dir1 = common.output_dir(f"interface_mpi_{a.case}_np1_{a.partitioner}")
    dirn = common.output_dir(f"interface_mpi_{a.case}_np{a.ranks}_{a.partitioner}")
    common.run(scene, dir1, case["args"] + ["-partitioner_report"], ranks=1, timeout=180)
    common.run(scene, dirn, case["args"] + ["-partitioner", a.partitioner, "-partitioner_report"],
               ranks=a.ranks, timeout=180)

    checks = common.Checks(f"interface mpi match {a.case}: 1 rank vs {label}")
    r1, u1 = read_log(dir1)
    rn, un = read_log(dirn)
    if r1 is None or rn is None:
        common.fail("no 'partition: ...' report line in the log (option -partitioner_report)")
    print(f"  partition ({label}): cells per rank {rn['cells']}, cohesive cells with a bulk "
          f"neighbour on another rank: {rn['separated']} of {rn['cohesive']}")
    checks.check("cohesive cells: same number on 1 and N ranks",
                 abs(r1["cohesive"] - rn["cohesive"]), 0)
    checks.check("the scene has cohesive cells", 0 if rn["cohesive"] > 0 else 1, 0)
    checks.check(f"partition over {a.ranks} ranks (every rank has cells)",
                 0 if len(rn["cells"]) == a.ranks and min(rn["cells"]) > 0 else 1, 0)
    if a.partitioner == "simple":
        checks.check("simple: the partition cuts through the interface (cohesive cells apart "
                     "from a bulk neighbour > 0)", rn["separated"], 0, ok=rn["separated"] > 0)
    elif a.partitioner == "metis":
        checks.check("metis: cohesive cells apart from a bulk neighbour", rn["separated"], 0)
    checks.check("displacement unknowns equal on 1 and N ranks",
                 abs(u1.get("displacement", -1) - un.get("displacement", -2)), 0)
    compare_timeseries(checks, dir1, dirn, a.rtol, label)
    checks.finish()


if __name__ == "__main__":
    main()
