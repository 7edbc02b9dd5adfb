#!/usr/bin/python3
"""`poroseam -options_file <scene> -help` lists the scene's options (label "input").

    scene_help.py --case NAME     one case: terzaghi, joint_np2, bad_value
    scene_help.py --list          the case names

With a scene, -help reads and checks the scene and sets the solvers up, so PETSc's -help
prints each option with its current value and description, one section per scene part, and
stops before the first step. A case passes when
  (a) the exit status is 0 (bad_value: 1, with poroseam's one-line error naming the option),
  (b) for a few options of every class (scene lists, physics, region, interface, boundary with
      a time function, probe, output, checkpoint, Newton, PETSc's own), the output has the
      PETSc-style line "  -<name> <now VALUE : formerly DEFAULT>: description (...)" with the
      value the scene file or command line gives and a description with its unit,
  (c) every such line appears once, also on 2 ranks: rank 0 prints, and no other rank prints
      anything (mpiexec --output-filename keeps each rank's output apart; lines of a second
      rank once landed inside rank 0's listing and cut one of its lines in two),
  (d) the run took no step and wrote nothing: neither -output_dir nor any scratch directory
      (TMPDIR is the case's own directory, which must be left empty) exists afterwards,
  (e) it ends within a few seconds (no hang).
"""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")
TERZAGHI = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
JOINT = os.path.join(SOURCE, "options", "joint_column_2d.opts")
TIMEOUT = 60.0
MAX_SECONDS = 15.0

# (option, value shown after "now", default shown after "formerly" or None for any,
#  a word the description must contain). Values are the scene's text as given.
TERZAGHI_LINES = [
    ("-mesh", "meshes/terzaghi_column_2d.geo", "(none)", "Gmsh"),
    ("-regions", "soil", "(none)", "regions"),
    ("-boundaries", "top,bottom,left,right", "(none)", "boundaries"),
    ("-gravity", "0", "0", "[m/s2]"),
    ("-initial_state", "none", "none", "geostatic"),
    ("-region_soil_material", "biot", "(none)", "elastic"),
    ("-region_soil_E", "1e7", "(none)", "[Pa]"),
    ("-region_soil_nu", "0.25", "(none)", "Poisson"),
    ("-region_soil_permeability", "1e-12", "(none)", "[m2]"),
    ("-region_soil_storage", "0", "0", "[1/Pa]"),
    ("-bc_top_traction", "0,-1e4", "(none)", "[Pa]"),
    ("-bc_top_traction_ramp", "2", None, "[s]"),
    ("-bc_top_p", "0", "none", "[Pa]"),
    ("-bc_bottom_uy", "0", "none", "[m]"),
    ("-bc_left_uy", "none", "none", "[m]"),
    ("-output_fields_every", "0", "1", "steps"),
    ("-probe_mid", "0.05,0.5", "(none)", "[m]"),
    ("-checkpoint_every", "3", "0", "steps"),
]
JOINT_LINES = [
    ("-interfaces", "joint", "(none)", "interfaces"),
    ("-interface_joint_side1", "lower", "(none)", "side 1"),
    ("-interface_joint_KN", "1e12", "(none)", "[Pa/m]"),
    ("-interface_joint_friction", "0.5", "(none)", "friction"),
    ("-interface_joint_D0", "1e-5", "(none)", "[m]"),
    ("-interface_joint_T1", "1e-3", "(none)", "[m/(Pa s)]"),
    ("-region_upper_E", "1e7", "(none)", "[Pa]"),
    ("-bc_top_p3", "none", "none", "[Pa]"),
]
# poroseam's and PETSc's own options read with PetscOptionsReal: "<value : default>"
PLAIN_LINES = {
    "terzaghi": [("-snes_reference_rtol", "1e-09", "1e-09"), ("-ts_dt", "0.2", None),
                 ("-drained:", "FALSE", "FALSE")],
    # PETSc prints a flag as <default : value>
    "joint_np2": [("-interface_joint_flow:", "FALSE", "TRUE")],
}
SECTIONS = {
    "terzaghi": ["poroseam region soil (-region_soil_*):", "poroseam boundary top (-bc_top_*):",
                 "poroseam scene: physics and initial state:",
                 "poroseam output: fields and probes (-probe_<name>):",
                 "poroseam checkpoints and restarts:"],
    "joint_np2": ["poroseam interface joint (-interface_joint_*):",
                  "poroseam region lower (-region_lower_*):"],
}

CASES = {
    "terzaghi": dict(scene=TERZAGHI, args=["-bc_top_traction_ramp", "2", "-probe_mid", "0.05,0.5",
                                           "-checkpoint_every", "3"], ranks=1,
                     lines=TERZAGHI_LINES),
    "joint_np2": dict(scene=JOINT, args=[], ranks=2, lines=JOINT_LINES),
    # validation still applies under -help: the same one-line error as a run's
    "bad_value": dict(scene=TERZAGHI, args=["-region_soil_E", "abc"], ranks=1, lines=[],
                      error="option -region_soil_E abc: expected a number"),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case")
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()
    if a.list or not a.case:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(OUTPUT_ROOT, "scene_help", a.case)
    shutil.rmtree(out, ignore_errors=True)
    scratch = os.path.join(out, "tmp")
    os.makedirs(scratch)
    results = os.path.join(out, "results")
    cmd = [EXE, "-options_file", case["scene"], "-output_dir", results, "-help"] + case["args"]
    if case["ranks"] > 1:
        # each rank's output in its own file (--output-filename): --tag-output, tried first,
        # tags the chunks Open MPI forwards, and those can end mid-line
        cmd = ["mpiexec", "--output-filename", os.path.join(out, "ranks"), "-n",
               str(case["ranks"])] + cmd
    env = dict(os.environ, TMPDIR=scratch)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    print("run:", " ".join(cmd), flush=True)
    t0 = time.time()
    failures = []
    try:
        p = subprocess.run(cmd, cwd=SOURCE, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=TIMEOUT)
        rc, text = p.returncode, p.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        rc, text = "timeout", (e.stdout or b"").decode(errors="replace")
        failures.append(f"no exit within {TIMEOUT:.0f} s (hang)")
    wall = time.time() - t0
    with open(os.path.join(out, "log.txt"), "w") as f:
        f.write(text)
    lines = text.splitlines()
    if case["ranks"] > 1:  # ranks/<job>/rank.<r>/{stdout,stderr}
        files = sorted(glob.glob(os.path.join(out, "ranks", "*", "rank.*", "std*")))
        rank_text = {}
        for path in files:
            rank = int(os.path.basename(os.path.dirname(path)).split(".")[1])
            with open(path, errors="replace") as f:
                rank_text[rank] = rank_text.get(rank, "") + f.read()
        others = [r for r, t in rank_text.items() if r != 0 and t.strip()]
        if others:
            failures.append(f"ranks {others} printed, e.g. '{rank_text[others[0]].splitlines()[0]}'")
        text = rank_text.get(0, "")  # (mpiexec also echoes it, possibly interleaved)
        lines = text.splitlines()
    expected_rc = 1 if "error" in case else 0
    if rc != expected_rc:
        failures.append(f"exit status {rc}, expected {expected_rc}")
    if wall > MAX_SECONDS:
        failures.append(f"took {wall:.1f} s (> {MAX_SECONDS:.0f} s)")
    if "error" in case:
        errors = [l for l in lines if l.startswith("poroseam: error:")]
        if errors != ["poroseam: error: " + case["error"]]:
            failures.append(f"error lines {errors}, expected one: '{case['error']}'")
    else:
        closing = [l for l in lines if l.startswith("poroseam: -help:")]
        if len(closing) != 1:
            failures.append(f"{len(closing)} closing 'poroseam: -help:' lines, expected 1")
    for option, now, default, word in case["lines"]:
        pattern = re.compile(r"^  " + re.escape(option) + r" <now " + re.escape(now) + " : formerly " +
                             (re.escape(default) if default is not None else r"[^>]*") +
                             r">: (.+) \(\S+\)$")
        found = [m for m in map(pattern.match, lines) if m]
        if len(found) != 1:
            failures.append(f"{len(found)} lines '  {option} <now {now} : formerly "
                            f"{default if default is not None else '...'}>: ...', expected 1")
        elif word not in found[0].group(1):
            failures.append(f"the description of {option} ('{found[0].group(1)}') lacks '{word}'")
    for option, now, default in PLAIN_LINES.get(a.case, []):
        prefix = f"  {option} <{now} : " + (f"{default}>" if default is not None else "")
        count = sum(1 for l in lines if l.startswith(prefix))
        if count != 1:
            failures.append(f"{count} lines starting '{prefix}', expected 1")
    for title in SECTIONS.get(a.case, []):
        count = lines.count(title)
        if count != 1:
            failures.append(f"{count} section titles '{title}', expected 1")
    # no step taken, nothing written
    for l in lines:
        if re.match(r"^\s*step\s+\d+", l) or "results in" in l:
            failures.append(f"a step was taken: '{l}'")
            break
    if os.path.exists(results):
        failures.append(f"the output directory {results} was written")
    left = os.listdir(scratch)
    if left:
        failures.append(f"left in TMPDIR: {left}")
    if failures:  # all of it, to see what took the place of a missing line
        print("\n".join(lines))
    else:
        print("\n".join(l for l in lines if "poroseam" in l or "-region_" in l or "-interface_" in l))
    print(f"wall {wall:.1f} s, exit status {rc}")
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("PASSED")
    return 0


if __name__ == "__main__":
    sys.exit(main())
