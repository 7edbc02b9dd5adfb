"""Checks of scripts/study (issue 10; docs/studies.md), ctest label `study`.

    check_study.py --orders        the observed orders of tests/study/terzaghi_orders.toml,
                                   computed by the study driver: spatial (Q1/P1) within 0.15
                                   of 2, backward Euler in time within 0.15 of 1
    check_study.py --perturbation  the error column of a study against a closed form: runs
                                   whose time series are the closed form with known relative
                                   and absolute perturbations (written as cached runs, no
                                   poroseam) give exactly the errors those perturbations mean;
                                   Richardson extrapolation of a known expansion; a bad study
                                   file gives a one-line error naming the file and the key
    check_study.py --cache         a study run twice: the second time runs nothing and leaves
                                   every cached result untouched

The driver is started as `python3 -m study`, not through scripts/study, whose set-up would
rebuild the build tree ctest runs from (POROSEAM_BUILD_DIR names it)."""
import argparse
import csv
import glob
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np

SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
HERE = os.path.join(SOURCE, "tests", "study")
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
SCRATCH = os.path.join(os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output"), "study")
sys.path.insert(0, SOURCE)
from study import analytic as A  # noqa: E402

failures = []


def check(name, ok, detail=""):
    print(f"  {'PASS' if ok else 'FAIL'}  {name}" + (f": {detail}" if detail else ""), flush=True)
    if not ok:
        failures.append(name)


def driver(args, out, exe=EXE, expect_ok=True):
    env = dict(os.environ, POROSEAM_EXE=exe, PYTHONPATH=SOURCE,
               POROSEAM_BUILD_DIR=os.path.dirname(exe))
    cmd = ["/usr/bin/python3", "-m", "study"] + args + ["--output", out]
    print("run: " + " ".join(cmd), flush=True)
    done = subprocess.run(cmd, cwd=SOURCE, env=env, capture_output=True, text=True, timeout=600)
    print(done.stdout + done.stderr, flush=True)
    if expect_ok and done.returncode != 0:
        sys.exit(f"FAIL: the study driver exited with {done.returncode}")
    return done


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def fresh(name):
    d = os.path.join(SCRATCH, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def orders():
    out = fresh("orders")
    driver([os.path.join(HERE, "terzaghi_orders.toml")], out)
    rows = read_csv(os.path.join(out, "study-terzaghi_orders", "orders.csv"))
    get = {(r["path"], r["quantity"]): r for r in rows}
    space = float(get[("space", "p_be")]["error_slope"])
    time_ = float(get[("time", "p_exact")]["observed_order"])
    print(f"  space path, error slope of p_be (against the backward-Euler series): {space:.3f}")
    print(f"  time path, observed order of p_exact (from the changes): {time_:.3f}")
    for r in rows:
        print(f"    {r['path']:6s} {r['quantity']:10s} error slope {r['error_slope']:>8s} "
              f"finest pair {r['error_slope_finest_pair']:>8s} observed {r['observed_order']:>8s}")
    check("Terzaghi spatial order within 0.15 of 2", abs(space - 2.0) <= 0.15, f"{space:.3f}")
    check("backward Euler time order within 0.15 of 1", abs(time_ - 1.0) <= 0.15, f"{time_:.3f}")
    for f in ("study.csv", "study.md", "work_precision.png", "orders.csv"):
        check(f"{f} written", os.path.getsize(os.path.join(out, "study-terzaghi_orders", f)) > 0)


def perturbation():
    out = fresh("perturbation")
    cache = os.path.join(out, "study_cache")
    sys.path.insert(0, SOURCE)
    from study import spec, runs, measure
    st = spec.load(os.path.join(HERE, "terzaghi_orders.toml"))
    exe = sys.executable  # any file: the runs are written by hand, the binary only keys them
    plan = runs.plan(st, exe, cache)
    q, H, Mc, kappa = 1e4, 1.0, A.constrained_modulus(1e7, 0.25), 1e-12 / 1e-3
    at = np.array(st.quantities["p_exact"].at)  # the study file's times
    rel = np.array([0.01, -0.02, 0.03, 0.0, -0.01, 0.02])[:len(at)]  # relative, per time
    ds = 3e-6  # absolute perturbation of the final settlement [m]
    expected = {}
    for r in plan:
        os.makedirs(r.dir, exist_ok=True)
        dt = r.point["dt"]
        n = int(round(10.0 / dt))
        t = dt * np.arange(0, n + 1)
        p = np.empty(n + 1)
        p[0] = 0.0
        p[1:] = np.ravel(A.terzaghi_pressure(0.2, t[1:], q, H, Mc, kappa))
        for k, tk in enumerate(at):
            p[np.argmin(np.abs(t - tk))] *= 1.0 + rel[k]
        s = np.zeros(n + 1)
        s[1:] = A.terzaghi_settlement(t[1:], q, H, Mc, kappa)
        s[-1] += ds
        with open(os.path.join(r.dir, "timeseries.csv"), "w") as f:
            f.write("step,time,dt,load,newton_its,ksp_its,rejected,wall_time,z02.p,top.uy\n")
            for i in range(n + 1):
                f.write(f"{i},{t[i]!r},{dt!r},1,1,1,0,0.01,{p[i]!r},{s[i]!r}\n")
        with open(os.path.join(r.dir, "result.json"), "w") as f:
            json.dump({"status": "ok", "fields": {"displacement": 1, "pressure": 1}, "unknowns": 2,
                       "wall_total_s": 1.0, "peak_memory_mb_per_rank": 1.0, "steps": n,
                       "wall_steps_s": 0.01 * n, "wall_per_step_s": 0.01, "newton": n,
                       "krylov": n, "rejected": 0}, f)
        p_exact = np.ravel(A.terzaghi_pressure(0.2, at, q, H, Mc, kappa))
        s_end = A.terzaghi_settlement(10.0, q, H, Mc, kappa)
        expected[r.key] = {"p_exact": math.sqrt(np.mean((rel * p_exact) ** 2)) / q,
                           "settlement": ds / abs(s_end)}
    d = driver([os.path.join(HERE, "terzaghi_orders.toml"), "--no-plots"], out, exe=exe)
    check("nothing run (every run given)", "0 to run" in d.stdout)
    rows = read_csv(os.path.join(out, "study-terzaghi_orders", "study.csv"))
    worst = 0.0
    for row in rows:
        for name, e in expected[row["key"]].items():
            got = float(row[f"{name}_error"])
            worst = max(worst, abs(got - e) / e)
            print(f"    {row['path']} {row['parameter_value']}: {name} error {got:.6e}, expected {e:.6e}")
    check("error columns equal the known perturbations (relative 1e-8)", worst < 1e-8, f"{worst:.1e}")
    # Richardson: Q(h) = 3 + 2 h^2 - h^3 on h = 0.4, 0.2, 0.1
    hs = [0.4, 0.2, 0.1]
    vals = [np.array([3 + 2 * h * h - h ** 3]) for h in hs]
    ref, p_used, p_obs, est = measure.richardson(hs, vals, order=2.0)
    exact_err = abs(ref[0] - 3.0)
    # what is left of the h^3 term after the extrapolation of the pair 0.2, 0.1
    left = -0.1 ** 3 - (0.1 ** 3 - 0.2 ** 3) / 3.0
    check("Richardson with order 2 removes the h^2 term exactly",
          abs((ref[0] - 3.0) - left) < 1e-12,
          f"R - 3 = {ref[0] - 3.0:.6e}, expected {left:.6e}; observed order {p_obs:.3f}")
    check("Richardson's estimated error covers its true error", est[0] >= exact_err,
          f"estimate {est[0]:.2e}, true {exact_err:.2e}")
    # a bad study file: one line naming file and key
    bad = os.path.join(out, "bad.toml")
    with open(os.path.join(HERE, "terzaghi_orders.toml")) as f:
        text = f.read()
    with open(bad, "w") as f:
        f.write(text.replace('dt = [1.0, 0.5, 0.25]', 'dt = [1.0, 0.3, 0.25]'))
    d = driver(["--check", bad], out, exe=exe, expect_ok=False)
    msg = d.stderr.strip()
    check("bad study file: non-zero exit, one line naming file and key",
          d.returncode != 0 and len(msg.splitlines()) == 1 and "bad.toml" in msg
          and "paths.time.dt" in msg and "divide end_time" in msg, msg)


def cache():
    out = fresh("cache")
    toml = os.path.join(HERE, "cache_test.toml")
    d1 = driver([toml, "--no-plots"], out)
    check("first run: 2 to run", "0 cached, 2 to run" in d1.stdout)
    results = sorted(glob.glob(os.path.join(out, "study_cache", "*", "result.json")))
    check("two cached runs", len(results) == 2, str(len(results)))
    before = {f: os.stat(f).st_mtime_ns for f in results}
    d2 = driver([toml, "--no-plots"], out)
    check("second run: everything cached, nothing run", "2 cached, 0 to run" in d2.stdout)
    after = {f: os.stat(f).st_mtime_ns for f in results}
    check("cached results untouched", before == after)
    rows = read_csv(os.path.join(out, "study-cache_test", "study.csv"))
    check("study.csv has both runs with an error", len(rows) == 2
          and all(float(r["p_mid_error"]) > 0 for r in rows))


def main():
    ap = argparse.ArgumentParser()
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--orders", action="store_true")
    g.add_argument("--perturbation", action="store_true")
    g.add_argument("--cache", action="store_true")
    a = ap.parse_args()
    if a.orders:
        orders()
    elif a.perturbation:
        perturbation()
    else:
        cache()
    if failures:
        sys.exit(f"FAIL: {len(failures)} check(s): " + "; ".join(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
