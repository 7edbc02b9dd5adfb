#!/usr/bin/python3
"""PETSc options typed wrong stop the run early, in one line each (issue 24 item 5).

    petsc_options.py --case NAME        one case (one ctest each, label "input")
    petsc_options.py --list             the case names

Misspelt option names: a top-level solver option (-ts_dtt, -snes_montor, -ksp_typ) stops the
run before its first step ("did you mean"); an option read lazily by an inner solver
(-fieldsplit_displacement_pc_typ, -mat_mumps_icntl_144) stops it at its first linear solve,
before the first step is accepted; -options_unused_ok runs on with a warning. Bad values of
PETSc's choice options (-pc_hypre_type boomeramgg, -ksp_type gmress ...) are one error line
naming the option, the value and what PETSc accepts, without PETSc's traceback, on 1 and 2
ranks. The scene is tests/verification/terzaghi_2d.opts (140 unknowns), -ts_max_time 0.4.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")
SCENE = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
FIELDSPLIT = ["-options_file", "options/solvers/fieldsplit.opts"]
STEP = re.compile(r"^step\s+\d+\s+t ", re.M)

# stop: the run fails with these substrings and prints no step line
# ok: the run succeeds with these substrings
# choice: a bad value of a choice option: exactly one error line, these substrings, no traceback
CASES = {
    "ts_dtt": dict(args=["-ts_dtt", "0.1"], stop=[
        "option -ts_dtt: no such option in this run (did you mean -ts_dt?)",
        "before the first step"]),
    "snes_montor": dict(args=["-snes_montor"], stop=[
        "option -snes_montor: no such option in this run (did you mean -snes_monitor?)"]),
    "ksp_typ": dict(args=["-ksp_typ", "gmres"], stop=[
        "option -ksp_typ: no such option in this run (did you mean -ksp_type?)"]),
    "ksp_typ_np2": dict(args=["-ksp_typ", "gmres"], ranks=2, stop=[
        "option -ksp_typ: no such option in this run (did you mean -ksp_type?)"]),
    # two at once: one line each
    "two_typos": dict(args=["-ts_dtt", "0.1", "-snes_montor"], stop=[
        "option -ts_dtt: no such option in this run (did you mean -ts_dt?)",
        "option -snes_montor: no such option in this run (did you mean -snes_monitor?)"]),
    # read when the split preconditioner is set up, inside the first linear solve
    "fieldsplit_pc_typ": dict(args=FIELDSPLIT + ["-fieldsplit_displacement_pc_typ", "jacobi"], stop=[
        "option -fieldsplit_displacement_pc_typ: no such option in this run "
        "(did you mean -fieldsplit_displacement_pc_type?)", "after the first linear solve"]),
    "fieldsplit_pc_typ_np2": dict(args=FIELDSPLIT + ["-fieldsplit_displacement_pc_typ", "jacobi"],
                                  ranks=2, stop=[
        "option -fieldsplit_displacement_pc_typ: no such option in this run "
        "(did you mean -fieldsplit_displacement_pc_type?)", "after the first linear solve"]),
    # a bad value of poroseam's own PC option (vertex_blocks' order coarsening), read when the
    # displacement split is set up
    "order_coarsening_value": dict(
        args=FIELDSPLIT + ["-fieldsplit_displacement_vertex_blocks_order_coarsening", "maybe"],
        stop=["option -fieldsplit_displacement_vertex_blocks_order_coarsening maybe: expected "
              "true or false"]),
    "order_coarsening_value_np2": dict(
        args=FIELDSPLIT + ["-fieldsplit_displacement_vertex_blocks_order_coarsening", "maybe"],
        ranks=2, stop=["option -fieldsplit_displacement_vertex_blocks_order_coarsening maybe: "
                       "expected true or false"]),
    # the stiff bodies' ratio of Young's moduli (src/solve/stiff_bodies.hpp): below 1 every
    # node would be "stiff"
    "stiff_ratio_value": dict(
        args=FIELDSPLIT + ["-fieldsplit_displacement_vertex_blocks_stiff_ratio", "0.5"],
        stop=["option -fieldsplit_displacement_vertex_blocks_stiff_ratio 0.5: expected 0 (off) "
              "or a ratio of Young's moduli >= 1"]),
    "stiff_ratio_value_np2": dict(
        args=FIELDSPLIT + ["-fieldsplit_displacement_vertex_blocks_stiff_ratio", "0.5"],
        ranks=2, stop=["option -fieldsplit_displacement_vertex_blocks_stiff_ratio 0.5: expected "
                       "0 (off) or a ratio of Young's moduli >= 1"]),
    # read by MUMPS at its first factorisation
    "mumps_icntl_144": dict(args=["-mat_mumps_icntl_144", "0"], stop=[
        "option -mat_mumps_icntl_144: no such option in this run", "after the first linear solve"]),
    # the opt-out: warned about, and the run goes on
    "unused_ok": dict(args=["-ts_dtt", "0.1", "-options_unused_ok"], ok=[
        "warning: option -ts_dtt: no such option in this run (did you mean -ts_dt?); running on",
        "poroseam: 2 steps"]),
    # the opt-out misspelt is no opt-out
    "unused_ok_misspelt": dict(args=["-ts_dtt", "0.1", "-options_unsued_ok"], stop=[
        "option -ts_dtt: no such option in this run (did you mean -ts_dt?)",
        "option -options_unsued_ok: no such option in this run (did you mean -options_unused_ok?)"]),
    # the preset's options are not the user's: unused ones (no interface pressure in this
    # scene) are reported at the end only
    "preset_unused_not_typed": dict(args=FIELDSPLIT, ok=["poroseam: 2 steps"]),
}
for ranks in (1, 2):
    tail = "" if ranks == 1 else "_np2"
    CASES.update({
        "hypre_type" + tail: dict(args=["-pc_type", "hypre", "-pc_hypre_type", "boomeramgg"],
                                  ranks=ranks, choice=[
            "option -pc_hypre_type boomeramgg: not a hypre preconditioner; expected one of "
            "euclid, pilut, parasails, boomeramg, ams, ads (did you mean boomeramg?)"]),
        "ksp_type" + tail: dict(args=["-ksp_type", "gmress"], ranks=ranks, choice=[
            "option -ksp_type gmress: not a Krylov method", "fgmres", "(did you mean gmres?)"]),
        "linesearch_type" + tail: dict(args=["-snes_linesearch_type", "bt2"], ranks=ranks, choice=[
            "option -snes_linesearch_type bt2: not a line search", "basic", "(did you mean bt?)"]),
        "ts_type" + tail: dict(args=["-ts_type", "beulerr"], ranks=ranks, choice=[
            "option -ts_type beulerr: not a time stepping method", "(did you mean beuler?)"]),
        # with a solver prefix, and an enum table of PETSc's (any case accepted)
        "split_pc_type" + tail: dict(args=FIELDSPLIT + ["-fieldsplit_pressures_pc_type", "jacobii"],
                                     ranks=ranks, choice=[
            "option -fieldsplit_pressures_pc_type jacobii: not a preconditioner",
            "vertex_blocks", "(did you mean jacobi?)"]),
        "schur_fact_type" + tail: dict(args=FIELDSPLIT + ["-pc_fieldsplit_schur_fact_type", "ful"],
                                       ranks=ranks, choice=[
            "option -pc_fieldsplit_schur_fact_type ful: not a Schur factorization",
            "diag, lower, upper, full"]),
    })


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--case")
    parser.add_argument("--list", action="store_true")
    a = parser.parse_args()
    if a.list:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(OUTPUT_ROOT, "petsc_options", a.case)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    cmd = [EXE, "-options_file", SCENE, "-output_dir", out, "-ts_max_time", "0.4"] + case["args"]
    if case.get("ranks", 1) > 1:
        cmd = ["mpiexec", "-n", str(case["ranks"])] + cmd
    print("run:", " ".join(cmd), flush=True)
    p = subprocess.run(cmd, cwd=SOURCE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=120)
    text = p.stdout
    print(text)
    failures = []
    expected = case.get("stop") or case.get("ok") or case.get("choice")
    for s in expected:
        if s not in text:
            failures.append(f"missing: {s!r}")
    if "ok" in case:
        if p.returncode != 0:
            failures.append(f"exit status {p.returncode}, expected 0")
    else:
        if p.returncode == 0:
            failures.append("exit status 0, expected an error")
        if STEP.search(text):
            failures.append("a step was taken (a 'step N' line): the run was not stopped in time")
        # (mpiexec's own box of dashes around "exited with non-zero status" is no traceback)
        if "PETSC ERROR" in text:
            failures.append("PETSc's traceback was printed")
        errors = [l for l in text.splitlines() if "error" in l.lower()]
        want = 2 if a.case in ("two_typos", "unused_ok_misspelt") else 1
        if len(errors) != want:
            failures.append(f"{len(errors)} error lines, expected {want}: {errors}")
    for f in failures:
        print("FAIL:", f)
    print("PASS" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
