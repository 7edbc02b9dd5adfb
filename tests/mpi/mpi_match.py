#!/usr/bin/python3
"""1 rank vs 2 ranks: the same scene must give the same results (label "mpi").

    mpi_match.py --case terzaghi_2d | terzaghi_3d | two_regions_2d  [--ranks 2] [--rtol 1e-8]

Runs the scene on 1 rank and on --ranks ranks with the direct solver (MUMPS LU, the scenes'
own -pc_type lu), then checks

  timeseries.csv: same header, same number of rows; the integer columns (step, newton_its,
      ksp_its, rejected) equal; every other column except wall_time agrees to rtol relative
      to the column's largest magnitude over both runs.  That reference is floored at 1e-6
      times the largest magnitude of the same quantity over all columns (forces .Fx/.Fy/.Fz,
      fluxes .flux, probe displacements .ux/.uy/.uz, probe pressures .p), so that columns
      which are pure round-off (e.g. a horizontal force of 1e-10 N on a column loaded with
      1e3 N) are not compared at 1e-8 of their own noise.  NaN (pressure of a probe in an
      elastic region) must be NaN in both.
  fields.h5 (via tests/support/fields_reader.py): same times; vertices matched by
      coordinates (the order differs with the partition); displacement, pressure and
      excess_pressure agree to rtol relative to the field's largest magnitude (pressures: NaN at
      the same vertices, those of non-porous regions only).
  two_regions_2d also: every probe in or on the soil (biot region) has a finite pressure,
      including the probe 'contact' on the soil-block contact.
"""

import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(SOURCE, "tests", "verification"))
sys.path.insert(0, os.path.join(SOURCE, "tests", "support"))
import common  # noqa: E402  (run, output_dir, Checks, fail)
from fields_reader import read_fields  # noqa: E402

CASES = {
    # Terzaghi 2D column (quadrilaterals), the full 125 steps; probes at 4 depths.
    "terzaghi_2d": dict(
        scene="tests/verification/terzaghi_2d.opts",
        args=["-probe_p25", "0.05,0.75", "-probe_p50", "0.05,0.5", "-probe_p75", "0.05,0.25",
              "-probe_top", "0.1,1", "-output_fields_every", "25"],
        soil_probes=[]),
    # Terzaghi 3D column (hexahedra), 25 steps (t = 5 s).
    "terzaghi_3d": dict(
        scene="tests/verification/terzaghi_3d.opts",
        args=["-ts_max_steps", "25", "-ts_max_time", "5", "-probe_mid", "0.05,0.05,0.5",
              "-probe_edge", "0.1,0,0.9", "-output_fields_every", "5"],
        soil_probes=[]),
    # Soil (biot) + elastic footing, gravity, geostatic initial state (options/two_regions_2d.opts).
    "two_regions_2d": dict(
        scene="options/two_regions_2d.opts",
        args=["-probe_contact", "0.5,2", "-output_fields_every", "10"],
        soil_probes=["under", "deep", "far", "contact"]),
}
INTEGER_COLUMNS = ["step", "newton_its", "ksp_its", "rejected"]
SKIP_COLUMNS = ["wall_time"]


def read_csv(out_dir):
    path = os.path.join(out_dir, "timeseries.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
    return header, data


def quantity(name):
    """Group of a column for the noise floor of its reference magnitude."""
    suffix = name.rsplit(".", 1)[-1] if "." in name else name
    if suffix in ("Fx", "Fy", "Fz"):
        return "force"
    if suffix in ("ux", "uy", "uz"):
        return "displacement"
    if suffix in ("flux", "flux1", "flux2", "storage_rate", "outflow", "interface_outflow"):
        return "water flow"  # all m3/s: a flow that is physically zero is judged on this scale
    return suffix  # p, storage, time, dt, load


def vertex_order(coordinates):
    """Permutation sorting the vertices by their coordinates (rounded to 1e-9 of the extent)."""
    scale = np.max(np.abs(coordinates))
    return np.lexsort(np.round(coordinates / scale, 9).T[::-1])


def compare_fields(checks, label, f1, f2, rtol, names=("displacement", "pressure", "excess_pressure")):
    """Fields of two runs whose vertex order may differ (other partition): matched by
    coordinates; each field relative to its largest magnitude in f1."""
    c1, c2 = f1.coordinates, f2.coordinates
    if len(c1) != len(c2) or len(f1.times) != len(f2.times):
        checks.check(f"{label}: same number of vertices and of outputs", 1, 0)
        return
    o1, o2 = vertex_order(c1), vertex_order(c2)
    coord_diff = np.max(np.abs(c1[o1] - c2[o2])) / np.max(np.abs(c1))
    checks.check(f"{label}: vertex coordinates match after sorting (relative)", coord_diff, 1e-12)
    if coord_diff > 1e-12:
        return
    for name in names:
        if name not in f1.fields[0]:
            continue
        # Pressures are NaN at vertices of non-porous regions only: the same vertices in both
        # runs, and compared where they are numbers.
        nan_mismatch = sum(int(np.sum(np.isnan(s1[name][o1]) != np.isnan(s2[name][o2])))
                           for s1, s2 in zip(f1.fields, f2.fields))
        if np.any(np.isnan(f1.fields[0][name])) or nan_mismatch:
            checks.check(f"{label}: {name} NaN at vertices of one run only", nan_mismatch, 0)
        ref = max(max(np.nanmax(np.abs(s[name]), initial=0.0) for s in f1.fields), 1e-300)
        rel = max(np.nanmax(np.abs(s1[name][o1] - s2[name][o2]), initial=0.0)
                  for s1, s2 in zip(f1.fields, f2.fields)) / ref
        checks.check(f"{label}: {name} max relative difference (ref {ref:.3g})", rel, rtol)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=1e-8)
    a = ap.parse_args()
    case = CASES[a.case]
    scene = os.path.join(SOURCE, case["scene"])
    dirs = {}
    for n in (1, a.ranks):
        dirs[n] = common.output_dir(f"mpi_{a.case}_np{n}")
        common.run(scene, dirs[n], case["args"], ranks=n, timeout=120)

    checks = common.Checks(f"mpi match {a.case}: 1 vs {a.ranks} ranks")
    h1, d1 = read_csv(dirs[1])
    h2, d2 = read_csv(dirs[a.ranks])
    checks.check("timeseries headers equal", 0 if h1 == h2 else 1, 0, ok=h1 == h2)
    checks.check("timeseries row counts equal", abs(len(d1) - len(d2)), 0)
    if h1 != h2 or len(d1) != len(d2):
        print("  header 1 rank:", h1, "\n  header n ranks:", h2)
        checks.finish()

    # integer columns: equal
    for name in INTEGER_COLUMNS:
        if name not in h1:
            continue
        i = h1.index(name)
        bad = np.nonzero(d1[:, i] != d2[:, i])[0]
        for r in bad[:5]:
            print(f"    {name} differs at step {int(d1[r, 0])}: {d1[r, i]:g} (1 rank) vs "
                  f"{d2[r, i]:g} ({a.ranks} ranks)")
        checks.check(f"{name}: rows that differ", len(bad), 0)

    # real columns: relative difference
    group_max = {}
    for i, name in enumerate(h1):
        if name in INTEGER_COLUMNS or name in SKIP_COLUMNS:
            continue
        m = np.nanmax(np.abs(np.r_[d1[:, i], d2[:, i]])) if np.any(np.isfinite(d1[:, i])) else 0.0
        group_max[quantity(name)] = max(group_max.get(quantity(name), 0.0), m)
    worst = (0.0, "")
    for i, name in enumerate(h1):
        if name in INTEGER_COLUMNS or name in SKIP_COLUMNS:
            continue
        x, y = d1[:, i], d2[:, i]
        nan_mismatch = int(np.sum(np.isnan(x) != np.isnan(y)))
        if nan_mismatch:
            checks.check(f"{name}: rows NaN on one run only", nan_mismatch, 0)
            continue
        ok = np.isfinite(x)
        if not np.any(ok):
            continue
        ref = max(np.max(np.abs(np.r_[x[ok], y[ok]])), 1e-6 * group_max[quantity(name)])
        if ref == 0.0:
            continue
        rel = np.max(np.abs(x[ok] - y[ok])) / ref
        if rel > worst[0] or not worst[1]:
            worst = (rel, name)
        if rel > a.rtol:
            checks.check(f"timeseries column {name}: max relative difference", rel, a.rtol)
    checks.check(f"timeseries: largest relative difference of all columns ({worst[1]})",
                 worst[0], a.rtol)

    # probes that must see the soil pressure
    for p in case["soil_probes"]:
        col = p + ".p"
        if col not in h1:
            checks.check(f"probe column {col} exists", 1, 0)
            continue
        i = h1.index(col)
        finite = bool(np.all(np.isfinite(d1[:, i])) and np.all(np.isfinite(d2[:, i])))
        checks.check(f"probe {p} (in or on the soil) has a finite pressure", 0 if finite else 1, 0,
                      ok=finite)

    # fields
    f1 = read_fields(dirs[1])
    f2 = read_fields(dirs[a.ranks])
    checks.check("fields: same number of outputs", abs(len(f1.times) - len(f2.times)), 0)
    checks.check("fields: same times", float(np.max(np.abs(f1.times - f2.times))) if
                 len(f1.times) == len(f2.times) else np.inf, 1e-12 * max(1.0, f1.times.max()))
    compare_fields(checks, "fields", f1, f2, a.rtol)
    checks.finish()


if __name__ == "__main__":
    main()
