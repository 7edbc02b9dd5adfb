#!/usr/bin/python3
"""Bad-input tests: poroseam run on a broken scene must fail cleanly.

    bad_input.py --case NAME [--ranks N]     one case (one ctest each, label "input")
    bad_input.py --list                      the case names

A failure case passes when
  (a) the exit status is non-zero,
  (b) the error text names the offending item (option, file or value): every expected
      substring must occur in the output *without* PETSc's echo of the options
      (the "Option left: ..." lines and the "PETSc Option Table entries" block are removed
      first, since they contain every option and would make any name match),
  (c) there is no crash signature ("Segmentation", "signal", "core dumped", ...),
  (d) it ends within a few seconds (the driver kills it after 60 s and fails: a hang).
Two cases instead check a good run: an unused option is reported as "never used", and
`poroseam -help` exits 0 and prints the scene options of docs/scenes.md.

The base scene is tests/verification/terzaghi_2d.opts (a valid scene); each case adds
command-line options (which override the file) or drops options from a copy of the scene.
"""

import argparse
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
BASE_SCENE = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
TIMEOUT = 60.0        # a run still going after this is a hang
MAX_SECONDS = 15.0    # "finishes in seconds" (the mesh is meshed by gmsh first)
# crash signatures; "signal" as a word (PETSc's -help lists "-no_signal_handler", which is fine)
CRASH = [r"Segmentation", r"(?<![_\w-])signal(?![_\w])", r"core dumped", r"Floating point exception",
         r"std::bad_alloc", r"terminate called", r"SIGSEGV|SIGBUS|SIGFPE|SIGABRT"]

# name: dict(args=[...], drop=[options removed from the scene], expect=[substrings],
#            ranks=1, ok=False (expect success instead of failure))
CASES = {
    "missing_mesh": dict(args=["-mesh", "meshes/does_not_exist.msh"],
                         expect=["meshes/does_not_exist.msh", "does not exist"]),
    # a real Gmsh geometry, copied under a name that is neither .msh nor .geo
    "mesh_extension": dict(args=["-mesh", "{out}/column.txt"], copy=("meshes/terzaghi_column_2d.geo", "column.txt"),
                           expect=["column.txt", ".msh"]),
    "unknown_region": dict(args=["-regions", "soil,rock"], expect=["'rock'", "-regions"]),
    "unknown_boundary": dict(args=["-boundaries", "top,bottom,left,right,roof"],
                             expect=["'roof'", "-boundaries"]),
    # 'right' is a boundary of the mesh, but not listed in -boundaries, and has -bc_right_ux 0
    "bc_unlisted_boundary": dict(args=["-boundaries", "top,bottom,left"], expect=["-bc_right_ux"]),
    "missing_E": dict(drop=["-region_soil_E"], expect=["-region_soil_E", "missing"]),
    "E_zero": dict(args=["-region_soil_E", "0"], expect=["-region_soil_E", "> 0"]),
    "E_negative": dict(args=["-region_soil_E", "-1e6"], expect=["-region_soil_E", "> 0"]),
    "nu_half": dict(args=["-region_soil_nu", "0.5"], expect=["-region_soil_nu", "0.5"]),
    "nu_below_minus_one": dict(args=["-region_soil_nu", "-1.2"], expect=["-region_soil_nu", "-1.2"]),
    "negative_permeability": dict(args=["-region_soil_permeability", "-1e-12"],
                                  expect=["-region_soil_permeability"]),
    "missing_material": dict(drop=["-region_soil_material"], expect=["-region_soil_material"]),
    "unknown_material": dict(args=["-region_soil_material", "clay"],
                             expect=["-region_soil_material", "clay"]),
    # PETSc's own parser rejects the value; the message must still say which option it was
    "non_numeric": dict(args=["-region_soil_E", "abc"], expect=["abc", "-region_soil_E"]),
    "probe_wrong_coords": dict(args=["-probe_bad", "0.05"], expect=["-probe_bad", "expected 2"]),
    "probe_outside": dict(args=["-probe_far", "5,5"], expect=["-probe_far", "outside the mesh"]),
    # meshes/bad_inverted.msh: 2 triangles in the unit square, element 6 is clockwise
    "inverted_element": dict(args=["-mesh", "meshes/bad_inverted.msh"], expect=["inverted element"]),
    # the same failures on 2 ranks: must exit (every rank), not hang
    "probe_outside_np2": dict(args=["-probe_far", "5,5"], expect=["-probe_far", "outside the mesh"],
                              ranks=2),
    "inverted_element_np2": dict(args=["-mesh", "meshes/bad_inverted.msh"],
                                 expect=["inverted element"], ranks=2),
    "missing_E_np2": dict(drop=["-region_soil_E"], expect=["-region_soil_E"], ranks=2),
    # good runs
    "unused_option": dict(args=["-not_an_option", "3", "-ts_max_time", "0.4"], ok=True,
                          expect=["-not_an_option", "never used"]),
    # paths with shell characters are only ever file names: gmsh is run without a shell, so
    # the quote and the $(...) in the mesh path and output directory do nothing but name them
    "shell_characters_in_paths": dict(
        args=["-mesh", "{out}/it's $(touch pwned)/column.geo",
              "-output_dir", "{out}/it's $(touch pwned)/results", "-ts_max_time", "0.2"],
        copy=("meshes/terzaghi_column_2d.geo", "it's $(touch pwned)/column.geo"), ok=True,
        expect=["1 steps"], absent=["pwned", "{out}/pwned", "{out}/it's $(touch pwned)/pwned"],
        present=["{out}/it's $(touch pwned)/results/timeseries.csv"]),
    "help": dict(help=True, ok=True,
                 expect=["-region_<r>_E", "-region_<r>_permeability", "-bc_<b>_traction",
                         "-initial_state", "-probe_<name>", "timeseries.csv"]),
}


def strip_option_echo(text):
    """The output without PETSc's listing of the options (which names every option)."""
    out, in_table = [], False
    for line in text.splitlines():
        body = re.sub(r"^\[\d+\]PETSC ERROR: ", "", line)
        if "PETSc Option Table entries" in body:
            in_table = True
            continue
        if in_table:
            if "End of Error Message" in body:
                in_table = False
            continue
        if body.startswith("Option left:") or body.startswith("Configure options"):
            continue
        out.append(line)
    return "\n".join(out)


def scene_without(options, out_dir):
    """A copy of the base scene with the given options removed; mesh paths stay relative to
    the source tree, where poroseam runs."""
    path = os.path.join(out_dir, "scene.opts")
    with open(BASE_SCENE) as f, open(path, "w") as g:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words and words[0] in options:
                continue
            g.write(line)
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case")
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()
    if a.list or not a.case:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(OUTPUT_ROOT, "input", a.case)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    if "copy" in case:
        target = os.path.join(out, case["copy"][1])
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy(os.path.join(SOURCE, case["copy"][0]), target)
    for path in case.get("absent", []):  # e.g. left by an earlier, broken build
        path = os.path.join(SOURCE, path.format(out=out))
        if os.path.exists(path):
            os.remove(path)
    if case.get("help"):
        cmd = [EXE, "-help"]
    else:
        scene = scene_without(case["drop"], out) if "drop" in case else BASE_SCENE
        cmd = [EXE, "-options_file", scene, "-output_dir", out] + \
              [s.format(out=out) for s in case.get("args", [])]
    ranks = case.get("ranks", 1)
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks)] + cmd
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    print("run:", " ".join(cmd), flush=True)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=SOURCE, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=TIMEOUT)
        rc, text = p.returncode, p.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        rc, text = "timeout", (e.stdout or b"").decode(errors="replace")
    wall = time.time() - t0
    with open(os.path.join(out, "log.txt"), "w") as f:
        f.write(text)
    message = strip_option_echo(text)
    failures = []
    if rc == "timeout":
        failures.append(f"no exit within {TIMEOUT:.0f} s (hang)")
    elif case.get("ok") and rc != 0:
        failures.append(f"exit status {rc}, expected 0")
    elif not case.get("ok") and rc == 0:
        failures.append("exit status 0, expected a failure")
    if wall > MAX_SECONDS:
        failures.append(f"took {wall:.1f} s (> {MAX_SECONDS:.0f} s)")
    for s in case["expect"]:
        if s not in message:
            failures.append(f"the output (options echo removed) does not contain '{s}'")
    for path in case.get("absent", []):
        if os.path.exists(os.path.join(SOURCE, path.format(out=out))):
            failures.append(f"'{path.format(out=out)}' exists: a path was run as a command")
    for path in case.get("present", []):
        if not os.path.exists(path.format(out=out)):
            failures.append(f"'{path.format(out=out)}' was not written")
    for s in CRASH:
        if re.search(s, text):
            failures.append(f"crash signature '{s}' in the output")
    # show the error text (the lines that matter) for the log
    shown = [l for l in message.splitlines()
             if "PETSC ERROR: #" not in l and l.strip()
             and not re.search(r"PETSC ERROR: (See https|Petsc Release|.*named .* by|-----|WARNING! There)", l)]
    print(f"exit {rc} after {wall:.2f} s; output (options echo removed):")
    print("    " + "\n    ".join(shown[:12 if not case.get("help") else 3]))
    if failures:
        print(f"FAIL {a.case}:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
