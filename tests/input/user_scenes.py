#!/usr/bin/python3
"""The example scenes options/*.opts run as documented (label "input").

    user_scenes.py [--steps 3] [--scene NAME]   every scene, or options/NAME.opts only
    user_scenes.py --list                       the scene names (one ctest each)

Each scene is run from the repository root exactly as its header says
(`build/poroseam -options_file options/<scene>.opts`, only -output_dir and -ts_max_time =
steps x the scene's -ts_dt added, so that it ends early but at its final time), and must exit 0, write timeseries.csv with a row per step, and leave no option
unused ("was given but never used": a misspelt option in an example would teach users the
wrong name).
"""

import argparse
import glob
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=3)
    ap.add_argument("--scene", help="run options/SCENE.opts only")
    ap.add_argument("--list", action="store_true", help="print the scene names")
    a = ap.parse_args()
    scenes = sorted(glob.glob(os.path.join(SOURCE, "options", "*.opts")))
    if a.list:
        print("\n".join(os.path.splitext(os.path.basename(p))[0] for p in scenes))
        return 0
    failures = []
    if a.scene is not None:
        path = os.path.join(SOURCE, "options", a.scene + ".opts")
        if not os.path.isfile(path):
            print(f"== no scene options/{a.scene}.opts")
            return 1
        scenes = [path]
    if not scenes:
        failures.append("no scenes in options/")
    for path in scenes:
        rel = os.path.relpath(path, SOURCE)
        name = os.path.splitext(os.path.basename(path))[0]
        out = os.path.join(OUTPUT_ROOT, "user_scenes", name)
        dt = None
        with open(path) as f:
            for line in f:
                parts = line.split("#", 1)[0].split()
                if len(parts) == 2 and parts[0] == "-ts_dt":
                    dt = float(parts[1])
        if dt is None:
            failures.append(f"{rel}: no -ts_dt")
            continue
        cmd = [EXE, "-options_file", rel, "-output_dir", out, "-ts_max_time", repr(a.steps * dt)]
        t0 = time.time()
        try:
            # A guard against hangs, not a timing test: the 3D caisson scenes run their 37k-
            # unknown default mesh serially here (about 90-130 s on an idle 2-core machine,
            # twice that when the other core is busy with another test).
            p = subprocess.run(cmd, cwd=SOURCE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               timeout=400)
            rc, text = p.returncode, p.stdout.decode(errors="replace")
        except subprocess.TimeoutExpired:
            rc, text = "timeout", ""
        problems = []
        if rc != 0:
            problems.append(f"exit {rc}: " + " | ".join(text.strip().splitlines()[-3:]))
        unused = [l for l in text.splitlines() if "never used" in l]
        problems += unused
        csv = os.path.join(out, "timeseries.csv")
        rows = sum(1 for _ in open(csv)) - 1 if os.path.isfile(csv) else 0
        if rc == 0 and rows != a.steps + 1:
            problems.append(f"timeseries.csv has {rows} rows, expected {a.steps + 1}")
        print(f"  {'FAIL' if problems else 'PASS'}  {rel}: {time.time() - t0:.1f} s, {rows} rows")
        for pr in problems:
            print("        " + pr)
        failures += [f"{rel}: {pr}" for pr in problems]
    if failures:
        print(f"== {len(failures)} problem(s)")
        return 1
    print(f"== all {len(scenes)} example scene(s) run")
    return 0


if __name__ == "__main__":
    sys.exit(main())
