"""The benchmark runs end to end: scripts/bench's driver (bench/bench.py) in --smoke mode (the
axisymmetric caisson at -mesh_size_factor 2, one step, every solver preset, 1 and 2 ranks,
the triad and the reference solve) writes bench.csv with the expected columns, a finite
number in every measured column of every run, scaling.csv, machine.csv and the plots.
Not a timing test: nothing here depends on how fast the machine is.

The driver is started directly, not through scripts/bench, whose set-up would rebuild the
build tree that ctest is running from (POROSEAM_BUILD_DIR names it instead)."""
import csv
import math
import os
import subprocess
import sys

SOURCE = os.environ.get("POROSEAM_SOURCE", os.getcwd())
sys.path.insert(0, os.path.join(SOURCE, "bench"))
import report  # noqa: E402

build = os.path.dirname(os.environ["POROSEAM_EXE"])
out = os.path.join(os.environ.get("POROSEAM_TEST_OUTPUT", os.path.join(build, "test-output")),
                   "bench")
env = dict(os.environ, POROSEAM_BUILD_DIR=build)
done = subprocess.run(["/usr/bin/python3", os.path.join(SOURCE, "bench", "bench.py"), "--smoke",
                       "--output", out], env=env, cwd=SOURCE)
failures = []
if done.returncode != 0:
    sys.exit(f"FAIL: bench.py --smoke exited with {done.returncode}")


def read(name):
    path = os.path.join(out, name)
    if not os.path.exists(path):
        failures.append(f"{name} was not written")
        return [], []
    with open(path) as f:
        r = csv.DictReader(f)
        return r.fieldnames, list(r)


columns, rows = read("bench.csv")
if columns and columns != report.COLUMNS:
    failures.append(f"bench.csv columns {columns} != {report.COLUMNS}")
presets = sorted(p[:-5] for p in os.listdir(os.path.join(SOURCE, "options", "solvers"))
                 if p.endswith(".opts"))
expected = {(p, r) for p in presets for r in ("1", "2")}
found = {(r["preset"], r["ranks"]) for r in rows}
if found != expected:
    failures.append(f"runs (preset, ranks) {sorted(found)}, expected {sorted(expected)}")
# Every column from the unknowns on is a measurement of a run that finished.
measured = report.COLUMNS[report.COLUMNS.index("unknowns"):]
measured.remove("unknowns_predicted")  # only for runs that were skipped or failed
for r in rows:
    if r["status"] != "ok":
        failures.append(f"{r['preset']} on {r['ranks']} rank(s): {r['status']} {r['note']}")
        continue
    bad = [k for k in measured if not (r[k] and math.isfinite(float(r[k])))]
    if bad:
        failures.append(f"{r['preset']} on {r['ranks']} rank(s): not finite: {bad}")
    if not float(r["unknowns"]) > 0 or not float(r["steps"]) == 1:
        failures.append(f"{r['preset']} on {r['ranks']} rank(s): unknowns {r['unknowns']}, "
                        f"steps {r['steps']}")
columns, scaling = read("scaling.csv")
if columns and (columns != report.SCALING_COLUMNS or len(scaling) != len(presets)):
    failures.append(f"scaling.csv: columns {columns}, {len(scaling)} rows for {len(presets)} "
                    "presets")
for s in scaling:
    bad = [k for k in report.SCALING_COLUMNS[3:] if not math.isfinite(float(s[k]))]
    if bad:
        failures.append(f"scaling.csv {s['preset']}: not finite: {bad}")
_, machine = read("machine.csv")
if machine and not float(machine[0]["bandwidth_ratio_2_1"]) > 0:
    failures.append(f"machine.csv: bandwidth ratio {machine[0]['bandwidth_ratio_2_1']}")
for png in ("time_per_step.png", "phases.png", "strong_scaling.png", "cost_per_unknown.png"):
    if not os.path.exists(os.path.join(out, png)):
        failures.append(f"{png} was not written")

if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print(f"bench --smoke: {len(rows)} runs, bench.csv, scaling.csv, machine.csv and 4 plots in {out}")
