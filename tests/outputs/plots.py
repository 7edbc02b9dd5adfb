#!/usr/bin/python3
"""The time-series plots draw what the run has, and nothing empty (scripts/plot_timeseries).

    plots.py --case drained|interface_flow

drained: the drained axisymmetric caisson (3 steps) has probes but no pore pressure (every
  probe's pressure is NaN) and no flow: no probes_pressure.png and no boundary_flux.png may be
  written, and every written figure has a curve on every axes.
interface_flow: crack jacking (options/crack_jacking_2d.opts, 20 steps): the crack's
  flow columns are drawn (interfaces_flow.png with flux1, flux2 and the storage rate, the
  stored water and the p3 force), again with no empty axes.
The expected files follow from the run's own timeseries.csv (which columns hold finite,
non-zero values), not from a list kept here.
"""
import argparse
import importlib.machinery
import importlib.util
import os
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")

CASES = {
    "drained": dict(scene="options/caisson_axisym_drained.opts", args=["-ts_max_steps", "3"],
                    absent=["probes_pressure.png", "boundary_flux.png", "interfaces_flow.png"]),
    "interface_flow": dict(scene="options/crack_jacking_2d.opts",
                           args=["-ts_max_time", "0.2"], present=["interfaces_flow.png"]),
}


def load_plotter():
    path = os.path.join(SOURCE, "scripts", "plot_timeseries")
    loader = importlib.machinery.SourceFileLoader("plot_timeseries", path)
    spec = importlib.util.spec_from_loader("plot_timeseries", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    a = ap.parse_args()
    case = CASES[a.case]
    out = os.path.join(OUTPUT_ROOT, "plots", a.case)
    shutil.rmtree(out, ignore_errors=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    cmd = ["mpiexec", "-n", "2", EXE, "-options_file", os.path.join(SOURCE, case["scene"]),
           "-output_dir", out] + case["args"]
    p = subprocess.run(cmd, cwd=SOURCE, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=300)
    text = p.stdout.decode(errors="replace")
    if not os.path.isfile(os.path.join(out, "timeseries.csv")):
        print(text)
        print("FAIL: the run wrote no timeseries.csv")
        return 1
    written = load_plotter().main(out)
    failures = []
    for name, curves in written.items():
        if not os.path.isfile(os.path.join(out, name)):
            failures.append(f"{name} reported but not on disk")
        if not curves or min(curves) == 0:
            failures.append(f"{name} has an axes without a curve: {curves}")
    for name in case.get("absent", []):
        if name in written:
            failures.append(f"{name} was drawn although the run has nothing for it")
    for name in case.get("present", []):
        if name not in written:
            failures.append(f"{name} was not drawn")
    # cross-check with the data: a pressure plot exactly when some probe has a finite pressure
    with open(os.path.join(out, "timeseries.csv")) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(os.path.join(out, "timeseries.csv"), delimiter=",", skiprows=1, ndmin=2)
    wet = any(np.any(np.isfinite(data[:, i])) for i, c in enumerate(header) if c.endswith(".p"))
    if wet != ("probes_pressure.png" in written):
        failures.append(f"probes_pressure.png drawn: {'probes_pressure.png' in written}, "
                        f"a probe with a pressure: {wet}")
    print("figures and curves per axes:", written)
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
