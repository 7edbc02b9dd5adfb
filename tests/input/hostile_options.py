#!/usr/bin/python3
"""Hostile options files and option values (issue 23 items 3 and 4, issue 24 item 2).

    hostile_options.py --case NAME     one case (one ctest each, label "input")
    hostile_options.py --list          the case names

A failure case passes as in tests/input/bad_input.py (whose helpers it uses): a non-zero exit,
exactly one "poroseam: error:" line that contains every expected substring (the file, line or
option named), no crash signature, no PETSc traceback, no hang (a FIFO or /dev/zero that PETSc
would read forever is killed after TIMEOUT and fails the case).

The good runs check what must still work: a scene copied with its mesh, a nested options file
and a time table to a temporary folder and run from a third folder finds all of them next to
the files that name them (not in the working directory, where decoys of the same names wait),
and gives the same time series as the scene with the load halved directly; a scene that
names its preset as options/solvers/direct.opts, run from another folder, finds it by name;
PETSc's
-prefix_push and the order of the command line against an options file keep their meaning; a
path longer than 255 characters is fine.
"""

import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bad_input  # noqa: E402  (EXE, SOURCE, OUTPUT_ROOT, CRASH, strip_option_echo)

SOURCE, EXE = bad_input.SOURCE, bad_input.EXE
SCENE = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
EXAMPLE = os.path.join(SOURCE, "options", "terzaghi_2d.opts")
TIMEOUT = 20.0  # every case ends in about a second; a hang is killed and fails
LONG_E = "1." + "0" * 300 + "1e7"  # 305 characters: PETSc's 256-byte buffer made E = 1 Pa


def write(path, text, mode="w"):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, mode) as f:
        f.write(text)
    return path


def probes(out, n):
    """An options file of n probes (PETSc 3.18 holds at most 512 options)."""
    return write(os.path.join(out, "probes.opts"),
                 "".join(f"-probe_p{i} 0.05,{(i + 0.5) / n:.6f}\n" for i in range(n)))


def fixture(name, out):
    """Writes the files of a case into `out`; returns the arguments after the executable."""
    base = ["-options_file", SCENE, "-output_dir", os.path.join(out, "results")]
    if name == "self_include":
        # relative: the nested name is found next to the file, so this is the file itself
        write(os.path.join(out, "self.opts"), "-ts_dt 0.2\n-options_file self.opts\n")
        return base + ["-options_file", os.path.join(out, "self.opts")]
    if name in ("include_cycle", "include_cycle_np2"):
        write(os.path.join(out, "a.opts"), "# a\n-options_file sub/b.opts\n")
        write(os.path.join(out, "sub", "b.opts"), "-ts_dt 0.2\n-options_file ../c.opts\n")
        write(os.path.join(out, "c.opts"), "-options_file a.opts\n")
        return base + ["-options_file", os.path.join(out, "a.opts")]
    if name == "include_doubling":
        # no cycle, but each file names the next twice: 2^30 files to read
        for i in range(30):
            write(os.path.join(out, f"f{i}.opts"), f"-options_file f{i + 1}.opts\n" * 2)
        write(os.path.join(out, "f30.opts"), "-ts_dt 0.2\n")
        return base + ["-options_file", os.path.join(out, "f0.opts")]
    if name == "binary_file":
        with open(EXE, "rb") as f:
            write(os.path.join(out, "scene.opts"), f.read(4096), "wb")
        return ["-options_file", os.path.join(out, "scene.opts")]
    if name == "binary_nested":
        write(os.path.join(out, "data.bin"), bytes(range(256)) * 4, "wb")
        write(os.path.join(out, "scene.opts"), "-ts_dt 0.2\n-options_file data.bin\n")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "not_utf8":
        write(os.path.join(out, "scene.opts"), "-ts_dt 0.2\n# \xe9t\xe9 (Latin-1)\n".encode("latin-1"), "wb")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "petsc_options_fifo":
        os.mkfifo(os.path.join(out, "pipe.opts"))
        return base
    if name in ("dev_zero", "dev_zero_np2"):
        return base + ["-options_file", "/dev/zero"]
    if name in ("fifo", "fifo_np2", "fifo_nested"):
        fifo = os.path.join(out, "pipe.opts")
        os.mkfifo(fifo)
        if name == "fifo_nested":
            write(os.path.join(out, "scene.opts"), "-options_file pipe.opts\n")
            return base + ["-options_file", os.path.join(out, "scene.opts")]
        return base + ["-options_file", fifo]
    if name == "too_large":
        write(os.path.join(out, "big.opts"), ("# " + "x" * 1000 + "\n") * 1100)
        return base + ["-options_file", os.path.join(out, "big.opts")]
    if name == "nested_missing":
        write(os.path.join(out, "scene.opts"), "-ts_dt 0.2\n\n-options_file more/missing.opts\n")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "two_values_on_a_line":
        write(os.path.join(out, "scene.opts"), "-ts_dt 0.2\n-bc_top_traction 0, -1e4\n")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "unclosed_quote":
        write(os.path.join(out, "scene.opts"), f'-output_dir "{out}/results\n')
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name in ("probes_600", "probes_600_np2"):
        return base + ["-options_file", probes(out, 600)]
    if name == "probes_600_command_line":
        args = []
        for i in range(600):
            args += [f"-probe_c{i}", f"0.05,{(i + 0.5) / 600:.6f}"]
        return base + args
    if name == "output_dir_newline":
        return ["-options_file", SCENE, "-output_dir", os.path.join(out, "a\nb")]
    if name == "output_dir_control_in_file":
        write(os.path.join(out, "scene.opts"), f'-output_dir "{out}/res\x1bults"\n')
        return ["-options_file", SCENE, "-options_file", os.path.join(out, "scene.opts")]
    if name in ("long_value", "long_value_np2"):
        return base + ["-region_soil_E", LONG_E]
    if name == "long_value_in_file":
        write(os.path.join(out, "scene.opts"), f"-ts_dt 0.2\n-region_soil_E {LONG_E}\n")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "long_value_petsc_option":
        return base + ["-ksp_type", "preonly" + "y" * 300]
    if name in ("int_overflow_checkpoint_every", "int_overflow_checkpoint_every_np2"):
        return base + ["-checkpoint_every", "4294967297"]
    if name == "int_overflow_in_file":
        write(os.path.join(out, "scene.opts"), "-ts_max_steps 2147483648\n")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "int_overflow_negative":
        return base + ["-snes_max_it", "-2147483649"]
    if name == "int_overflow_prefixed":
        return base + ["-fieldsplit_displacement_ksp_max_it", "3000000000"]
    if name == "int_overflow_mumps":
        return base + ["-mat_mumps_icntl_14", "99999999999999999999"]
    if name == "int_overflow_output_every":
        write(os.path.join(out, "scene.opts"), "-output_fields_every 4294967297\n")
        return base + ["-options_file", os.path.join(out, "scene.opts")]
    if name == "checkpoints_is_a_file":
        write(os.path.join(out, "results", "checkpoints"), "not a folder\n")
        return base + ["-checkpoint_every", "2", "-ts_max_time", "1"]
    if name == "long_path_ok":
        deep = os.path.join(out, "d" * 120, "e" * 120, "f" * 60)
        return ["-options_file", SCENE, "-output_dir", deep, "-ts_max_time", "0.4"]
    if name == "prefix_push_in_file":
        # -ts_max_time 0.4 spelt through a prefix; popped before the next option
        write(os.path.join(out, "short.opts"),
              "-prefix_push ts_\n-max_time 0.4 # = -ts_max_time\n-prefix_pop\n-output_fields_every 0\n")
        return base + ["-options_file", os.path.join(out, "short.opts")]
    if name == "command_line_order":
        # PETSc's order: an option before the file is overridden by it (dt 0.2 of the scene,
        # 2 steps to t = 0.4), one after it wins
        return ["-ts_dt", "0.4", "-options_file", SCENE, "-output_dir", os.path.join(out, "results"),
                "-ts_max_time", "0.4"]
    if name == "preset_by_old_path":
        # a scene written for the source tree (-options_file options/solvers/direct.opts), copied
        # and run elsewhere: the preset is found by its name
        with open(SCENE) as f:
            kept = [l for l in f if l.split("#", 1)[0].split()[:1] not in
                    (["-mesh"], ["-ksp_type"], ["-pc_type"], ["-pc_factor_mat_solver_type"])]
        write(os.path.join(out, "scene", "column.opts"), "".join(kept) +
              f"-mesh {SOURCE}/meshes/terzaghi_column_2d.geo\n"
              "-options_file options/solvers/direct.opts\n")
        return ["-options_file", "scene/column.opts", "-ts_max_time", "0.4",
                "-output_dir", "results"]
    raise KeyError(name)


# name: dict(expect=[substrings of the error line], ranks=1, ok=False, check=function(out))
CASES = {
    "self_include": dict(expect=["self.opts", "includes itself"]),
    "include_cycle": dict(expect=["cycle", "a.opts' -> ", "sub/b.opts", "c.opts", "line 1"]),
    "include_cycle_np2": dict(expect=["cycle", "sub/b.opts"], ranks=2),
    "include_doubling": dict(expect=["more than 256 options files read", "line 2 of"]),
    "binary_file": dict(expect=["scene.opts", "not a text file"]),
    "binary_nested": dict(expect=["data.bin", "line 2 of", "scene.opts"]),
    "not_utf8": dict(expect=["scene.opts", "not UTF-8", "line 2"]),
    "dev_zero": dict(expect=["/dev/zero", "device"]),
    "dev_zero_np2": dict(expect=["/dev/zero", "device"], ranks=2),
    "fifo": dict(expect=["pipe.opts", "FIFO"]),
    "fifo_np2": dict(expect=["pipe.opts", "FIFO"], ranks=2),
    "fifo_nested": dict(expect=["pipe.opts", "FIFO", "line 1 of"]),
    # PETSc reads the environment's options (and their files) before the command line's
    "petsc_options_fifo": dict(expect=["pipe.opts", "FIFO", "in PETSC_OPTIONS"],
                               env={"PETSC_OPTIONS": "-ts_dt 0.2 -options_file {out}/pipe.opts"}),
    "too_large": dict(expect=["big.opts", "bytes", "1048576"]),
    "nested_missing": dict(expect=["more/missing.opts", "does not exist", "line 3 of",
                                   "relative to that file's folder"]),
    "two_values_on_a_line": dict(expect=["scene.opts' line 2", "-bc_top_traction", "'-1e4'"]),
    "unclosed_quote": dict(expect=["scene.opts' line 1", "quote"]),
    "probes_600": dict(expect=["600 of them are probes", "512", "options given"]),
    "probes_600_np2": dict(expect=["600 of them are probes", "512"], ranks=2),
    "probes_600_command_line": dict(expect=["600 of them are probes", "512"]),
    "output_dir_newline": dict(expect=["-output_dir", "a\\nb", "line break"],
                               check=lambda out: [] if not os.listdir(out) else
                               [f"created {os.listdir(out)} in the case's folder"]),
    "output_dir_control_in_file": dict(expect=["-output_dir", "line 1 of", "0x1b"]),
    "long_value": dict(expect=["-region_soil_E", "305 characters", "255", "command line"]),
    "long_value_np2": dict(expect=["-region_soil_E", "305 characters"], ranks=2),
    "long_value_in_file": dict(expect=["-region_soil_E", "line 2 of", "scene.opts", "255"]),
    "long_value_petsc_option": dict(expect=["-ksp_type", "307 characters"]),
    "int_overflow_checkpoint_every": dict(expect=["-checkpoint_every 4294967297", "2147483647"]),
    "int_overflow_checkpoint_every_np2": dict(expect=["-checkpoint_every 4294967297"], ranks=2),
    "int_overflow_in_file": dict(expect=["-ts_max_steps 2147483648", "line 1 of", "2147483647"]),
    "int_overflow_negative": dict(expect=["-snes_max_it -2147483649", "-2147483648"]),
    "int_overflow_prefixed": dict(expect=["-fieldsplit_displacement_ksp_max_it 3000000000"]),
    "int_overflow_mumps": dict(expect=["-mat_mumps_icntl_14 99999999999999999999"]),
    "int_overflow_output_every": dict(expect=["-output_fields_every 4294967297", "line 1 of", "2147483647"]),
    "checkpoints_is_a_file": dict(expect=["results/checkpoints", "not a directory"]),
    # good runs
    "long_path_ok": dict(ok=True, expect=["2 steps"]),
    "prefix_push_in_file": dict(ok=True, expect=["2 steps"]),
    "command_line_order": dict(ok=True, expect=["2 steps"]),
    "scene_elsewhere": dict(ok=True, expect=["5 steps"]),
    "preset_by_old_path": dict(ok=True, cwd=True, expect=["2 steps"],
                               check=lambda out: record_has(out, '"-pc_type": "lu"')),
}


def record_has(out, text):
    """[] when <out>/results/run.yaml holds `text`, else the failure."""
    path = os.path.join(out, "results", "run.yaml")
    if not os.path.isfile(path):
        return [f"no {path}"]
    with open(path) as f:
        return [] if text in f.read() else [f"run.yaml does not hold {text}"]


def run(cmd, cwd, ranks=1, extra_env=None):
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks)] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", **(extra_env or {}))
    try:
        p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=TIMEOUT)
        return p.returncode, p.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        return "timeout", (e.stdout or b"").decode(errors="replace")


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in r] for r in rows[1:]]


def scene_elsewhere(out):
    """options/terzaghi_2d.opts copied to <out>/scene/ with its mesh in geometry/, its top load
    in loads/top_load.opts (nested), scaled by 0.5 by loads/tables/half.csv (named in the
    nested file, so relative to loads/), and its solver by -options_file solvers/direct.opts
    (found by name: <out>/scene/ has no solvers/). Run from <out>/run/, which holds decoys of
    the same relative names (a broken mesh, a table of factor 1). Compared with the example
    scene run from the source tree with -bc_top_traction 0,-5e3: the same linear problem."""
    scene_dir, run_dir = os.path.join(out, "scene"), os.path.join(out, "run")
    with open(EXAMPLE) as f:
        lines = f.read().splitlines()
    text = []
    for line in lines:
        words = line.split("#", 1)[0].split()
        if words[:1] == ["-mesh"]:
            line = "-mesh geometry/column.geo"
        elif words[:1] == ["-bc_top_traction"]:
            line = "-options_file loads/top_load.opts"
        elif words[:1] == ["-options_file"] and words[1] != "solvers/direct.opts":
            return 1, f"{EXAMPLE} no longer names solvers/direct.opts: {line}"
        text.append(line)
    write(os.path.join(scene_dir, "terzaghi.opts"), "\n".join(text) + "\n")
    os.makedirs(os.path.join(scene_dir, "geometry"))
    shutil.copy(os.path.join(SOURCE, "meshes", "terzaghi_column_2d.geo"),
                os.path.join(scene_dir, "geometry", "column.geo"))
    write(os.path.join(scene_dir, "loads", "top_load.opts"),
          "-bc_top_traction 0,-1e4\n-bc_top_traction_table tables/half.csv\n")
    write(os.path.join(scene_dir, "loads", "tables", "half.csv"), "time,factor\n0,0.5\n100,0.5\n")
    write(os.path.join(run_dir, "geometry", "column.geo"), "this is not a geometry\n")
    write(os.path.join(run_dir, "tables", "half.csv"), "0,1\n100,1\n")
    write(os.path.join(run_dir, "loads", "tables", "half.csv"), "0,1\n100,1\n")
    rc, text = run([EXE, "-options_file", "../scene/terzaghi.opts", "-ts_max_time", "1"], run_dir)
    log = f"[copied scene, run from {run_dir}]\n{text}"
    if rc != 0:
        return rc, log
    ref_out = os.path.join(out, "reference")
    rc_ref, ref_text = run([EXE, "-options_file", EXAMPLE, "-bc_top_traction", "0,-5e3",
                            "-ts_max_time", "1", "-output_dir", ref_out], SOURCE)
    log += f"\n[reference]\n{ref_text}"
    if rc_ref != 0:
        return rc_ref, log
    got = os.path.join(run_dir, "output", "terzaghi_2d", "timeseries.csv")  # -output_dir: cwd
    if not os.path.isfile(got):
        return 1, log + f"\nno {got}: -output_dir of the scene is relative to the working directory"
    h1, a = read_csv(got)
    h2, b = read_csv(os.path.join(ref_out, "timeseries.csv"))
    if h1 != h2 or len(a) != len(b):
        return 1, log + f"\ncolumns or rows differ: {h1} / {h2}, {len(a)} / {len(b)} rows"
    worst = 0.0
    for j, name in enumerate(h1):
        if "." not in name:  # step, time, load factor, iterations, wall time
            continue
        scale = max(abs(r[j]) for r in b) or 1.0
        # From step 1 on: row 0 is the initial state, where the table's factor (0.5 at t = 0)
        # and the step load of the reference (0 at t = 0, the value from t = 0+) differ by
        # definition, and the boundary columns report the applied load (tests/outputs/books.py).
        for ra, rb in zip(a[1:], b[1:]):
            worst = max(worst, abs(ra[j] - rb[j]) / scale)
    log += f"\nlargest difference of a probe or boundary column / its largest value: {worst:.2e}"
    if worst > 1e-9:
        return 1, log + " (> 1e-9)"
    with open(os.path.join(run_dir, "output", "terzaghi_2d", "run.yaml")) as f:
        record = f.read()
    for s in ("scene_file: \"../scene/terzaghi.opts\"", os.path.join("geometry", "column.geo"),
              os.path.join("loads", "tables", "half.csv"), "\"-pc_type\": \"lu\""):
        if s not in record:
            return 1, log + f"\nrun.yaml does not contain '{s}'"
    return 0, log


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case")
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()
    if a.list or not a.case:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(bad_input.OUTPUT_ROOT, "input_hostile", a.case)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    t0 = time.time()
    if a.case == "scene_elsewhere":
        rc, text = scene_elsewhere(out)
    else:
        cmd = [EXE] + fixture(a.case, out)
        print("run:", " ".join(cmd).replace("\n", "\\n")[:300], flush=True)
        env = {k: v.format(out=out) for k, v in case.get("env", {}).items()}
        rc, text = run(cmd, out if case.get("cwd") else SOURCE, case.get("ranks", 1), env)
    wall = time.time() - t0
    with open(os.path.join(out + ".log"), "w") as f:
        f.write(text)
    message = bad_input.strip_option_echo(text).replace(out, "<out>")
    failures = []
    if rc == "timeout":
        failures.append(f"no exit within {TIMEOUT:.0f} s (hang)")
    elif case.get("ok") and rc != 0:
        failures.append(f"exit status {rc}, expected 0")
    elif not case.get("ok") and rc == 0:
        failures.append("exit status 0, expected a failure")
    errors = [l for l in message.splitlines() if l.startswith("poroseam: error:")]
    if not case.get("ok"):
        if len(errors) != 1:
            failures.append(f"{len(errors)} 'poroseam: error:' lines, expected exactly 1")
        for s in case["expect"]:
            if not any(s in e for e in errors):
                failures.append(f"the error line does not contain '{s}'")
        for s in ("PETSC ERROR", "MPI_ABORT", "Traceback"):
            if s in text:
                failures.append(f"the output contains '{s}'")
    else:
        for s in case["expect"]:
            if s not in message:
                failures.append(f"the output does not contain '{s}'")
    for s in bad_input.CRASH:
        if re.search(s, text):
            failures.append(f"crash signature '{s}' in the output")
    if "check" in case:
        failures += case["check"](out)
    print(f"exit {rc} after {wall:.2f} s; output:")
    shown = [l for l in message.splitlines() if l.strip() and "PETSC ERROR: #" not in l]
    print("    " + "\n    ".join(l[:400] for l in shown[-12:]))
    if failures:
        print(f"FAIL {a.case}:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
