"""run.yaml, the record of a run (docs/scenes.md, "Run record").

--case rerun: Terzaghi (tests/verification/terzaghi_2d.opts, 5 steps) on 1 rank; run.yaml must
  be valid YAML with ending success, exit status 0, the unknowns of the 'field ... unknowns'
  lines, as many steps as the time series has rows after row 0 and the versions and times
  filled in. Then the scene is run again from the recorded options alone (an options file
  written from run.yaml, another -output_dir): its time series must equal the first run's in
  every column but wall_time, as printed (to the last digit written: the same computation).
--case step_limit: the same scene with -ts_max_steps 2 before its final time: the run exits
  non-zero and run.yaml says ending 'step limit', exit status 1, 2 steps; restarted from its
  checkpoint, the record has a second segment (success, steps 2 to 5); a run with a region
  the mesh lacks records ending 'error' with the error line.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

import yaml

SOURCE = os.environ.get(
    "POROSEAM_SOURCE", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")
SCENE = "tests/verification/terzaghi_2d.opts"
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)


def fresh(name):
    d = os.path.join(OUTPUT_ROOT, "record", name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def run(args, out_dir):
    cmd = [EXE] + args + ["-output_dir", out_dir]
    print("run:", " ".join(cmd), flush=True)
    res = subprocess.run(cmd, cwd=SOURCE, capture_output=True, text=True, timeout=300)
    with open(os.path.join(out_dir, "log.txt"), "w") as f:
        f.write(res.stdout + res.stderr)
    return res


def segment(out_dir):
    """The last segment of DIR/run.yaml (a new run has one)."""
    with open(os.path.join(out_dir, "run.yaml")) as f:
        record = yaml.safe_load(f)
    return record["segments"][-1], len(record["segments"])


def rows(out_dir):
    """timeseries.csv as its header and rows of text fields."""
    with open(os.path.join(out_dir, "timeseries.csv")) as f:
        lines = [l.rstrip("\n").split(",") for l in f]
    return lines[0], lines[1:]


def case_rerun():
    first = fresh("first")
    res = run(["-options_file", SCENE, "-ts_max_time", "1"], first)
    check(res.returncode == 0, f"the run succeeds (exit {res.returncode})")
    seg, n = segment(first)
    check(n == 1, f"one segment ({n})")
    check(seg["status"] == "ended" and seg["ending"] == "success", f"ending {seg['ending']}")
    check(seg["exit_status"] == 0, f"exit_status {seg.get('exit_status')}")
    printed = {m[0]: int(m[1]) for m in re.findall(r"^field (\w+)\s+(\d+) unknowns", res.stdout, re.M)}
    recorded = {k: v for k, v in seg["unknowns"].items() if k != "total"}
    check(printed and printed == recorded, f"unknowns {recorded} == printed {printed}")
    check(seg["unknowns"]["total"] == sum(printed.values()), "total unknowns")
    header, data = rows(first)
    s = seg["summary"]
    check(s["steps"] == len(data) - 1 == s["last_step"] == 5,
          f"steps {s['steps']}, last_step {s['last_step']} == time series rows after row 0 ({len(data) - 1})")
    newton = sum(int(r[header.index("newton_its")]) for r in data)
    krylov = sum(int(r[header.index("ksp_its")]) for r in data)
    check(s["newton_iterations"] == newton and s["krylov_iterations"] == krylov,
          f"Newton {s['newton_iterations']} / Krylov {s['krylov_iterations']} == sums of the time series ({newton} / {krylov})")
    check(s["time"] == 1.0, f"time reached {s['time']}")
    check(len(s["peak_memory_mb_per_rank"]) == 1 and s["peak_memory_mb_per_rank"][0] > 1,
          f"peak memory {s['peak_memory_mb_per_rank']}")
    check(seg["ranks"] == 1 and seg["petsc_version"].startswith("3.") and seg["poroseam_version"],
          "ranks, versions")
    check(re.fullmatch(r"[0-9a-f]{40}(-dirty)?|unknown", seg["git_commit"]) is not None,
          f"git commit {seg['git_commit']}")
    iso = r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ"
    check(re.fullmatch(iso, seg["start"]) and re.fullmatch(iso, seg["end"]) and seg["start"] <= seg["end"],
          f"start {seg['start']}, end {seg['end']}")
    check(seg["scene_file"] == SCENE, f"scene file {seg['scene_file']}")
    opts = seg["options"]
    check(opts.get("-ts_max_time") == "1" and opts.get("-mesh") == "meshes/terzaghi_column_2d.geo",
          "options of the scene file and the command line")
    summary = [l for l in res.stdout.splitlines() if l.startswith("summary:")]
    last = res.stdout.strip().splitlines()[-1]
    check(len(summary) == 2 and last.startswith("poroseam: 5 steps"), "the summary printed before the last line")

    # The same scene from the record alone.
    second = fresh("second")
    opts_file = os.path.join(second, "recorded.opts")
    with open(opts_file, "w") as f:
        for name, value in opts.items():
            if name in ("-output_dir", "-restart", "-restart_step"):
                continue
            f.write(name + ("" if value is None else " " + value) + "\n")
    res2 = run(["-options_file", opts_file], second)
    check(res2.returncode == 0, f"the run from the recorded options succeeds (exit {res2.returncode})")
    header2, data2 = rows(second)
    check(header2 == header, "same columns")
    wall = header.index("wall_time")
    strip = lambda rs: [r[:wall] + r[wall + 1:] for r in rs]
    same = strip(data2) == strip(data)
    check(same, f"same time series in every column but wall_time ({len(data2)} rows)")


def case_step_limit():
    out = fresh("step_limit")
    res = run(["-options_file", SCENE, "-ts_max_time", "1", "-ts_max_steps", "2"], out)
    check(res.returncode != 0, f"the run fails (exit {res.returncode})")
    seg, _ = segment(out)
    check(seg["ending"] == "step limit", f"ending {seg['ending']}")
    check(seg["exit_status"] == 1, f"exit_status {seg['exit_status']}")
    check("step limit" in seg["message"], "the message says why")
    check(seg["summary"]["steps"] == 2, f"steps {seg['summary']['steps']}")
    lines = (res.stdout + res.stderr).strip().splitlines()
    check(any(l.startswith("summary:") for l in lines), "the summary is printed")

    # Restarted from its checkpoint, the run appends its segment to the record.
    res = run(["-options_file", SCENE, "-ts_max_time", "1", "-restart", out], out)
    check(res.returncode == 0, f"the restart succeeds (exit {res.returncode})")
    with open(os.path.join(out, "run.yaml")) as f:
        segs = yaml.safe_load(f)["segments"]
    check([s["ending"] for s in segs] == ["step limit", "success"] and segs[1]["restart"],
          f"two segments: {[s['ending'] for s in segs]}")
    check((segs[1]["summary"]["first_step"], segs[1]["summary"]["last_step"]) == (2, 5),
          "the restart's segment goes from step 2 to 5")

    # An error after the start (bad input found once the mesh is read) is recorded too.
    bad = fresh("error")
    res = run(["-options_file", SCENE, "-regions", "soil,nowhere"], bad)
    seg, _ = segment(bad)
    check(res.returncode != 0 and seg["ending"] == "error" and seg["exit_status"] == 1
          and "nowhere" in seg["message"], f"bad input: ending {seg['ending']}, {seg['message']!r}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--case", choices=["rerun", "step_limit"], required=True)
    a = p.parse_args()
    {"rerun": case_rerun, "step_limit": case_step_limit}[a.case]()
    if failures:
        print(f"{len(failures)} check(s) failed", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
