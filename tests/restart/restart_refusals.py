#!/usr/bin/python3
"""Restarts refuse what they cannot honour (docs/checkpoints.md, "What a restart must keep" and
"Damaged checkpoints"; issue 23, item 5). The scene of tests/restart/restart.py (the coarse
partially drained axisymmetric caisson, dt = 3 s, a deterministic direct solver on 2 ranks):
a first run to t = 12 s (4 steps) with -checkpoint_every 2 leaves checkpoints of steps 2 and 4;
then one restart per case.

    restart_refusals.py --case NAME [--ranks N]     one case (one ctest each, label "faults")
    restart_refusals.py --list                      the case names

Refused, with exactly one line "poroseam: error: ..." naming the option (or file) and both
values, exit status 1, no traceback, no HDF5 error stack, and nothing in the output directory
changed (time series, run record and checkpoints byte for byte):
  changed_E          -region_soil_E 3e8 (the run had 2e8)
  changed_penalty    -interface_caisson_KN 1e11 (1e10): an interface's penalty stiffness
  changed_dt         -ts_dt 2 (3)
  changed_mesh       the same -mesh file name, its content changed (a copy of the .geo with one
                     more comment line): compared by content, not by name
  final_time_below   -ts_max_time 6, and 12 (the checkpoint's time): at or before the checkpoint
  all_damaged        a bit flipped in step 4's solution and step 2's file cut short: one error
                     naming both
  missing_fields     fields.h5 deleted: one error naming it
Continued, and equal to the uninterrupted run to t = 24 s (every time series column, relative
to its kind's scale by common.largest_series_difference, and every dataset of fields.h5 and
interfaces.h5, to 1e-12; restart.compare):
  extend             -ts_max_time 24: a later final time extends the run
  flipped_bit        a bit flipped in the solution dataset of the latest checkpoint (step 4):
                     one warning naming it, the restart continues from step 2
  truncated_latest   the latest checkpoint cut to half its size: one warning, from step 2
  solver_free        other solver tolerances (-ksp_rtol, -snes_reference_rtol) are free: the
                     restart runs (not compared with the uninterrupted run: tolerances change
                     the answer within themselves)
"""
import argparse
import hashlib
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(TESTS, "input"))
import restart as base  # noqa: E402  (tests/restart/restart.py: scene, commands, comparison)
import bad_input  # noqa: E402  (crash signatures, the options echo)
import h5py  # noqa: E402

common = base.common
FIRST = ["-ts_max_time", 12, "-checkpoint_every", 2]
STEPS_FIRST, STEPS_LONG = 4, 8  # 12 s and 24 s at dt = 3 s

REFUSED = {
    "changed_E": (["-region_soil_E", "3e8"], ["-region_soil_E", "3e8", "2e8"]),
    "changed_penalty": (["-interface_caisson_KN", "1e11"], ["-interface_caisson_KN", "1e11", "1e10"]),
    "changed_dt": (["-ts_dt", "2"], ["-ts_dt is 2", "was 3"]),
    "changed_mesh": (["-mesh", "{out}/caisson_axisym.geo"], ["-mesh", "caisson_axisym.geo", "content"]),
    "final_time_below": (["-ts_max_time", "6"], ["-ts_max_time 6", "t = 12 s"]),
    "all_damaged": ([], ["step-000004.h5", "step-000002.h5", "checksum", "damaged"]),
    "missing_fields": ([], ["fields.h5", "missing"]),
}
CONTINUED = ["extend", "flipped_bit", "truncated_latest", "solver_free"]
CASES = list(REFUSED) + CONTINUED


def flip_bit(path, dataset="solution"):
    """Flips one bit inside the raw data of `dataset` (a chunked dataset: its first chunk)."""
    with h5py.File(path, "r") as f:
        d = f[dataset]
        offset = d.id.get_offset()
        if offset is None:
            offset = d.id.get_chunk_info(0).byte_offset
        size = d.id.get_storage_size()
    with open(path, "r+b") as f:
        f.seek(offset + size // 2)
        byte = f.read(1)[0]
        f.seek(offset + size // 2)
        f.write(bytes([byte ^ 0x08]))


def truncate(path):
    with open(path, "r+b") as f:
        f.truncate(os.path.getsize(path) // 2)


def snapshot(out):
    """Content hashes of every file in the output directory (the mesh folder aside, and the
    lock file .poroseam.lock, which every run that opens the directory rewrites with its pid:
    docs/outputs.md)."""
    found = {}
    for root, dirs, files in os.walk(out):
        dirs[:] = [d for d in dirs if d != "mesh"]
        for name in files:
            if name.endswith(".txt") or name == ".poroseam.lock":  # this driver's logs; the lock
                continue
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                found[os.path.relpath(path, out)] = hashlib.sha256(f.read()).hexdigest()
    return found


def one_error_line(chk, text, out, expect):
    message = bad_input.strip_option_echo(text).replace(out, "<out>")
    errors = [l for l in message.splitlines() if l.startswith("poroseam: error:")]
    base.expect(chk, len(errors) == 1, f"exactly one error line: {errors[:3]}")
    for s in expect:
        base.expect(chk, any(s in l for l in errors), f"the error names '{s}'")
    no_crash(chk, text)


def no_crash(chk, text):
    found = [s for s in bad_input.CRASH + ["PETSC ERROR", "HDF5-DIAG", "Traceback", "MPI_ABORT"]
             if re.search(s, text)]
    base.expect(chk, not found, f"no crash, traceback or HDF5 error stack: {found}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", choices=CASES)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    if args.list or not args.case:
        print("\n".join(CASES))
        return
    case, ranks = args.case, args.ranks
    chk = common.Checks(f"restart refusals: {case} ({ranks} rank(s))")
    out = common.output_dir(f"restart_refusals_{case}_np{ranks}")
    first = list(FIRST)
    if case == "changed_mesh":
        shutil.copy(os.path.join(common.SOURCE, "meshes", "caisson_axisym.geo"), out)
        first += ["-mesh", os.path.join(out, "caisson_axisym.geo")]
    status, text = base.restart(out, first, ranks)
    base.expect(chk, status == 0 and base.rows(out) == STEPS_FIRST,
                f"the first run: {base.rows(out)} steps to t = 12 s, status {status}")
    checkpoints = os.path.join(out, "checkpoints")
    latest, previous = (os.path.join(checkpoints, f"step-{k:06d}.h5") for k in (4, 2))
    base.expect(chk, os.path.isfile(latest) and os.path.isfile(previous),
                "checkpoints of steps 2 and 4")

    extra = ["-restart", out, "-ts_max_time", 24]
    if case == "changed_mesh":
        with open(os.path.join(out, "caisson_axisym.geo"), "a") as f:
            f.write("// edited after the first run\n")
        extra += ["-mesh", os.path.join(out, "caisson_axisym.geo")]
    elif case in ("all_damaged", "flipped_bit"):
        flip_bit(latest)
        if case == "all_damaged":
            truncate(previous)
    elif case == "truncated_latest":
        truncate(latest)
    elif case == "missing_fields":
        os.remove(os.path.join(out, "fields.h5"))
    elif case == "solver_free":
        extra += ["-ksp_rtol", "1e-7", "-snes_reference_rtol", "1e-10"]
    elif case in REFUSED:
        extra += [a.format(out=out) for a in REFUSED[case][0]]

    if case in REFUSED:
        before = snapshot(out)
        status, text = base.restart(out, extra, ranks)
        base.expect(chk, status == 1, f"exit status {status} (1)")
        one_error_line(chk, text, out, REFUSED[case][1])
        if case == "final_time_below":  # at the checkpoint's time too
            status, text = base.restart(out, ["-restart", out, "-ts_max_time", 12], ranks)
            base.expect(chk, status == 1, f"-ts_max_time 12: exit status {status} (1)")
            one_error_line(chk, text, out, ["-ts_max_time 12", "t = 12 s"])
        changed = sorted(k for k in set(before) | set(snapshot(out))
                         if before.get(k) != snapshot(out).get(k))
        base.expect(chk, not changed, f"nothing in the output directory changed: {changed}")
        chk.finish()

    status, text = base.restart(out, extra, ranks)
    base.expect(chk, status == 0, f"the restart runs to t = 24 s (status {status})")
    m = re.search(r"restart from \S+step-(\d+)\.h5", text)
    start = int(m.group(1)) if m else -1
    warnings = [l for l in text.splitlines() if l.startswith("poroseam: warning:")]
    if case in ("flipped_bit", "truncated_latest"):
        base.expect(chk, start == 2, f"it continues from the checkpoint before the damaged one ({start})")
        base.expect(chk, len(warnings) == 1 and "step-000004.h5" in warnings[0]
                    and "damaged" in warnings[0], f"one warning naming the damaged one: {warnings}")
    else:
        base.expect(chk, start == 4, f"it continues from the latest checkpoint ({start})")
        base.expect(chk, not warnings, f"no warning: {warnings}")
    no_crash(chk, text)
    if case != "solver_free":
        reference = common.output_dir(f"restart_refusals_{case}_np{ranks}_uninterrupted")
        status, _ = base.restart(reference, ["-ts_max_time", 24, "-checkpoint_every", 2], ranks)
        base.expect(chk, status == 0, "the uninterrupted run to t = 24 s")
        base.STEPS = STEPS_LONG  # restart.compare checks the rows 0..STEPS
        base.compare(reference, out, chk)
    chk.finish()


if __name__ == "__main__":
    main()
