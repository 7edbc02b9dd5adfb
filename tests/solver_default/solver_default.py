#!/usr/bin/python3
"""A scene that names no solver gets -solver_preset auto; a failed linear solve is reported as
such (issue 24, item 1; docs/scenes.md, "Time stepping and solvers"). Label "solvers".

--case interfaces_2d: options/crack_jacking_2d.opts (a buried crack carrying water in
  porous rock, contact and flow) copied with its solver lines (-ksp_type, -pc_type,
  -pc_factor_mat_solver_type) removed, 10 steps. It must run to its final time, print
  'solver preset direct (auto, the default: 2D, ...)' and record the same in run.yaml
  ('solver'), and its time series must equal, to 1e-9 of each quantity's scale (the shared
  run-vs-run comparison of tests/verification/common.py), those of the original scene with its
  own MUMPS LU lines and of the stripped scene with an explicit -solver_preset direct.
--case scene_3d: tests/verification/terzaghi_3d.opts stripped of its solver lines, 5 steps: runs, says auto chose direct (3D, 400
  unknowns), equals the scene with its own lines to 1e-9; and with -solver_auto_threshold 100
  auto chooses the iterative fieldsplit preset, which must equal MUMPS to 1e-6 (the bound of
  tests/mpi/solver_presets.py).
--case linear_failure: the joint column (options/joint_column_2d.opts) with a solver
  that cannot work, -ksp_type gmres -pc_type none -ksp_max_it 2. The run must exit non-zero
  after three attempts of its first step (two cuts for a failed linear solve), with a message
  naming DIVERGED_LINEAR_SOLVE and the Krylov reason DIVERGED_ITS, advising the direct solver
  and giving no advice about -ts_dt; run.yaml says 'failed step', exit status 1, that message
  and 3 rejected attempts. The same with a factorisation that fails (PETSc's LU with
  -pc_factor_zeropivot 1e30: every pivot counts as zero): KSP DIVERGED_PC_FAILED, PC
  FACTOR_NUMERIC_ZEROPIVOT, and the advice for a singular matrix. (Before issue 24 it said "Newton did not converge ... even after 8
  cuts of the time step ... a smaller -ts_dt ... may help" after 9 attempts.)
"""
import argparse
import os
import re
import subprocess
import sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "verification"))
import common  # noqa: E402  (run, read_timeseries, largest_series_difference, Checks)

TESTS = os.path.join(common.SOURCE, "tests")
SOLVER_LINE = re.compile(r"^\s*-(ksp_type|pc_type|pc_factor_mat_solver_type|solver_preset)\b"
                         r"|^\s*-options_file\s+(options/)?solvers/")


def stripped_scene(scene, out):
    """The scene without its solver lines, its relative mesh path made absolute, written to
    OUT/scene.opts; returns that path and the lines removed."""
    kept, removed = [], []
    with open(scene) as f:
        for line in f:
            if SOLVER_LINE.match(line):
                removed.append(line.strip())
                continue
            m = re.match(r"^(\s*-mesh\s+)(\S+)(.*)$", line)
            if m and not os.path.isabs(m.group(2)):
                path = os.path.normpath(os.path.join(os.path.dirname(scene), m.group(2)))
                if not os.path.isfile(path):  # a scene of the days when -mesh was relative to cwd
                    path = os.path.join(common.SOURCE, m.group(2))
                line = m.group(1) + path + m.group(3) + "\n"
            kept.append(line)
    path = os.path.join(out, "scene.opts")
    with open(path, "w") as f:
        f.writelines(kept)
    return path, removed


def record(out):
    with open(os.path.join(out, "run.yaml")) as f:
        return yaml.safe_load(f)["segments"][-1]


def log(out):
    with open(os.path.join(out, "log.txt")) as f:
        return f.read()


def same_as(checks, name, a, b, tolerance, skip=("wall_time",)):
    ta, tb = common.read_timeseries(a), common.read_timeseries(b)
    if ta["time"].size != tb["time"].size or set(ta) != set(tb):
        checks.check(f"{name}: same steps and columns", 1, 0, ok=False)
        return
    diff, where = common.largest_series_difference(ta, tb, skip=skip)
    checks.check(f"{name} (largest at {where})", diff, tolerance)


def default_chosen(checks, out, preset, dim):
    printed = re.search(r"^solver preset (\w+) \(auto, the default: (\d)D, (\d+) unknowns", log(out), re.M)
    checks.check(f"stdout says auto, the default, chose {preset} in {dim}D", 0, 0,
                 ok=bool(printed) and printed.group(1) == preset and printed.group(2) == str(dim))
    seg = record(out)
    solver = str(seg.get("solver"))
    checks.check(f"run.yaml solver: '{solver[:60]}...'", 0, 0,
                 ok=solver.startswith(f"preset {preset} (auto, the default: {dim}D"))
    checks.check("run.yaml ending success, exit status 0", 0, 0,
                 ok=seg.get("ending") == "success" and seg.get("exit_status") == 0)


def interfaces_2d():
    checks = common.Checks("no solver line: 2D, a crack carrying water in porous rock")
    scene = os.path.join(common.SOURCE, "options", "crack_jacking_2d.opts")
    steps = ["-ts_max_time", "0.1", "-ts_max_steps", "10"]
    plain = common.output_dir("solver_default_2d")
    path, removed = stripped_scene(scene, plain)
    checks.check(f"solver lines removed: {removed}", 0, 0, ok=len(removed) == 3)
    common.run(path, plain, steps)
    default_chosen(checks, plain, "direct", 2)
    own = common.output_dir("solver_default_2d_own")
    common.run(scene, own, steps)
    same_as(checks, "time series equal the scene's own MUMPS LU", own, plain, 1e-9)
    named = common.output_dir("solver_default_2d_named")
    common.run(path, named, steps + ["-solver_preset", "direct"])
    same_as(checks, "time series equal -solver_preset direct", named, plain, 1e-9)
    checks.finish()


def scene_3d():
    checks = common.Checks("no solver line: 3D Terzaghi column")
    scene = os.path.join(TESTS, "verification", "terzaghi_3d.opts")
    steps = ["-ts_max_time", "1", "-ts_max_steps", "5"]
    plain = common.output_dir("solver_default_3d")
    path, removed = stripped_scene(scene, plain)
    checks.check(f"solver lines removed: {removed}", 0, 0, ok=len(removed) >= 1)
    common.run(path, plain, steps)
    default_chosen(checks, plain, "direct", 3)
    own = common.output_dir("solver_default_3d_own")
    common.run(scene, own, steps)
    same_as(checks, "time series equal the scene's own MUMPS LU", own, plain, 1e-9)
    # The other branch of auto: above the threshold (lowered here) the iterative preset.
    iterative = common.output_dir("solver_default_3d_fieldsplit")
    common.run(path, iterative, steps + ["-solver_auto_threshold", "100"])
    printed = re.search(r"^solver preset fieldsplit \(auto, the default: 3D, (\d+) unknowns > 100\)",
                        log(iterative), re.M)
    checks.check("auto above -solver_auto_threshold chose fieldsplit", 0, 0, ok=bool(printed))
    same_as(checks, "fieldsplit equals MUMPS LU", own, iterative, 1e-6,
            skip=("wall_time", "newton_its", "ksp_its"))
    checks.finish()


def linear_failure():
    checks = common.Checks("a failed linear solve is reported as such")
    scene = os.path.join(common.SOURCE, "options", "joint_column_2d.opts")
    out = common.output_dir("solver_default_linear_failure")
    path, _ = stripped_scene(scene, out)
    cmd = [common.EXE, "-options_file", path, "-output_dir", out, "-ts_max_time", "2",
           "-ksp_type", "gmres", "-pc_type", "none", "-ksp_max_it", "2"]
    print("run:", " ".join(cmd), flush=True)
    res = subprocess.run(cmd, cwd=common.SOURCE, capture_output=True, text=True, timeout=120)
    text = res.stdout + res.stderr
    error = [line for line in text.splitlines() if "error" in line]
    message = error[-1] if error else ""
    print("     " + (message or "(no error line)"), flush=True)
    checks.check(f"exit status {res.returncode} != 0", 0, 0, ok=res.returncode != 0)
    checks.check("the message names DIVERGED_LINEAR_SOLVE and KSP DIVERGED_ITS after 2 iterations", 0, 0,
                 ok="DIVERGED_LINEAR_SOLVE" in message and "KSP DIVERGED_ITS after 2 iterations" in message)
    checks.check("it names the solver and advises the direct one", 0, 0,
                 ok="-ksp_type gmres, -pc_type none" in message and "-solver_preset direct" in message)
    checks.check("no advice about the time step (-ts_dt)", 0, 0, ok="-ts_dt" not in text)
    checks.check("no 'Newton did not converge'", 0, 0, ok="Newton did not converge" not in text)
    seg = record(out)
    checks.check("run.yaml: ending 'failed step', exit status 1", 0, 0,
                 ok=seg.get("ending") == "failed step" and seg.get("exit_status") == 1)
    checks.check("run.yaml message is the error line", 0, 0,
                 ok=bool(message) and seg.get("message", "") in message and "DIVERGED_LINEAR_SOLVE" in seg.get("message", ""))
    rejected = seg.get("summary", {}).get("rejected_attempts")
    checks.check(f"attempts of the step: {rejected} (the first and two cuts)", 0, 0, ok=rejected == 3)
    checks.check("run.yaml solver: as given", 0, 0,
                 ok=seg.get("solver") == "as given (-ksp_type gmres, -pc_type none)")
    # A factorisation that fails (PETSc's LU told that every pivot is zero, as a singular
    # matrix's would be): the reason, and the advice for a singular matrix.
    out = common.output_dir("solver_default_zero_pivot")
    cmd = [common.EXE, "-options_file", path, "-output_dir", out, "-ts_max_time", "2",
           "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "petsc",
           "-pc_factor_zeropivot", "1e30"]
    print("run:", " ".join(cmd), flush=True)
    res = subprocess.run(cmd, cwd=common.SOURCE, capture_output=True, text=True, timeout=120)
    text = res.stdout + res.stderr
    error = [line for line in text.splitlines() if "error" in line]
    message = error[-1] if error else ""
    print("     " + (message or "(no error line)"), flush=True)
    checks.check(f"zero pivot: exit status {res.returncode} != 0", 0, 0, ok=res.returncode != 0)
    checks.check("zero pivot: KSP DIVERGED_PC_FAILED, PC FACTOR_NUMERIC_ZEROPIVOT", 0, 0,
                 ok="KSP DIVERGED_PC_FAILED" in message and "PC FACTOR_NUMERIC_ZEROPIVOT" in message)
    checks.check("zero pivot: advice for a singular matrix (boundary conditions)", 0, 0,
                 ok="singular" in message and "boundary conditions" in message)
    checks.check("zero pivot: no advice about the time step (-ts_dt)", 0, 0, ok="-ts_dt" not in text)
    checks.finish()


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", required=True, choices=["interfaces_2d", "scene_3d", "linear_failure"])
    case = parser.parse_args().case
    {"interfaces_2d": interfaces_2d, "scene_3d": scene_3d, "linear_failure": linear_failure}[case]()
