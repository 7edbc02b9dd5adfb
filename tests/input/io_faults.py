#!/usr/bin/python3
"""I/O faults of the output directory, on 2 ranks: every case must end in one line (or a
correct run), never a hang, a crash or a write outside the output directory.

    io_faults.py --case NAME       one case (one ctest each, label "faults")
    io_faults.py --list            the case names

Cases (docs/input_errors.md, "Output directory and I/O faults"):
  dir_<file>_np2        a directory where the run writes <file> (fields.h5, fields.xmf, ...)
  file_<folder>_np2     a file where the run keeps its folder (checkpoints, mesh)
  readonly_dir_np2      the output directory on a read-only bind mount (chmod does not stop
                        root); skipped (77) where mounting is not allowed
  concurrent_np2        a second run in the directory of a running one is refused at start;
                        the first finishes untouched; a run after it (lock released) works
  killed_lock_np2       a run killed with SIGKILL leaves no stale lock: the next run works
  symlink_<what>_np2    a symbolic link in the output directory (checkpoints, mesh, a file,
                        a file inside checkpoints/): refused, the link's target untouched
                        (its listing, contents and mtimes)
  hdf5_refused_all_np2  an HDF5 write of fields.h5 refused on every rank (test hook
                        -test_io_fail_rank -1): one line, every rank ends, files readable
  hdf5_refused_rank1_np2
                        refused on rank 1 only, while rank 0 waits inside HDF5's collective
                        calls: rank 1 says it in one line and ends the run with MPI_Abort after
                        -io_agreement_timeout (5 s here): no hang
  disk_full_fields_np2, disk_full_csv_np2, disk_full_checkpoint_np2
                        a full disk (small tmpfs; skipped with 77 where it cannot be mounted)
                        ends in one line; fields.h5 opens (h5py), fields.xmf names only
                        datasets that exist, timeseries.csv holds whole rows only

A hang fails: the driver kills a run after TIMEOUT s (and ctest's TIMEOUT backs it up).
"""

import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bad_input import CRASH, EXE, JOINT_SCENE, OUTPUT_ROOT, SOURCE, strip_option_echo  # noqa: E402

BASE_SCENE = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
TIMEOUT = 120.0  # a loaded 2-core machine runs these in seconds; beyond this it is a hang
SKIP = 77

# every file the run writes in its directory (the joint scene writes interfaces too)
FILES = ["fields.h5", "fields.xmf", "interfaces.h5", "interface_cells.xmf",
         "interface_points.xmf", "timeseries.csv", "timeseries.csv.units", "run.yaml",
         "fields.xmf.tmp", "run.yaml.tmp"]
FOLDERS = ["checkpoints", "mesh"]

CASES = {}
for name in FILES:
    CASES["dir_" + name.replace(".", "_") + "_np2"] = dict(kind="directory", name=name)
for name in FOLDERS:
    CASES["file_" + name + "_np2"] = dict(kind="file", name=name)
CASES["readonly_dir_np2"] = dict(kind="readonly")
CASES["concurrent_np2"] = dict(kind="concurrent")
CASES["killed_lock_np2"] = dict(kind="killed")
for what in ["checkpoints", "mesh", "file", "in_checkpoints"]:
    CASES["symlink_" + what + "_np2"] = dict(kind="symlink", what=what)
CASES["disk_full_fields_np2"] = dict(kind="disk_full", fields=True)
CASES["disk_full_csv_np2"] = dict(kind="disk_full", fields=False)
CASES["disk_full_checkpoint_np2"] = dict(kind="disk_full", fields=False, checkpoint=True)
# an HDF5 write refused on every rank / on rank 1 only (test hook -test_io_fail_rank)
CASES["hdf5_refused_all_np2"] = dict(kind="refused", rank="-1")
CASES["hdf5_refused_rank1_np2"] = dict(kind="refused", rank="1")


def env():
    e = dict(os.environ)
    e.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    e.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    e.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    return e


def command(out, scene=JOINT_SCENE, extra=()):
    # the joint scene writes every kind of file: fields, interfaces, series, record, mesh
    return ["mpiexec", "-n", "2", EXE, "-options_file", scene, "-output_dir", out,
            "-output_fields_every", "1", "-ts_max_time", "0.4"] + list(extra)


def run(cmd):
    print("run:", " ".join(cmd), flush=True)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=SOURCE, env=env(), stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=TIMEOUT)
        rc, text = p.returncode, p.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        rc, text = "timeout", (e.stdout or b"").decode(errors="replace")
    print(f"exit {rc} after {time.time() - t0:.1f} s")
    return rc, text


def one_line_failure(rc, text, expect, out, abort_ok=False):
    """The failures of a run that must end in one clear error line naming `expect`."""
    failures = []
    if rc == "timeout":
        return [f"no exit within {TIMEOUT:.0f} s (hang)"]
    if rc == 0:
        failures.append("exit status 0, expected a failure")
    message = strip_option_echo(text)
    errors = [l for l in message.splitlines() if l.startswith("poroseam: error:")]
    print("    " + "\n    ".join(errors or message.splitlines()[-8:]))
    if len(errors) != 1:
        failures.append(f"{len(errors)} 'poroseam: error:' lines, expected exactly 1")
    for s in expect:
        if not any(s in l for l in errors):
            failures.append(f"the error line does not contain '{s}'")
    for s in CRASH:
        if re.search(s, text):
            failures.append(f"crash signature '{s}' in the output")
    for s in ("PETSC ERROR", "Traceback") + (() if abort_ok else ("MPI_ABORT",)):
        if s in text:
            failures.append(f"the output contains '{s}'")
    return failures


def snapshot(root):
    """Every entry under root: relative path -> (kind, bytes, mtime_ns)."""
    seen = {}
    for d, dirs, files in os.walk(root):
        for n in dirs + files:
            p = os.path.join(d, n)
            st = os.lstat(p)
            data = b""
            if os.path.isfile(p) and not os.path.islink(p):
                with open(p, "rb") as f:
                    data = f.read()
            seen[os.path.relpath(p, root)] = (st.st_mode, data, st.st_mtime_ns)
    return seen


def mount(args, where):
    """mount(8) as root; None when it works, else the reason."""
    if os.geteuid() != 0:
        return "not root: cannot mount"
    p = subprocess.run(["mount"] + args + [where], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT)
    return None if p.returncode == 0 else "mount failed: " + p.stdout.decode().strip()


def umount(where):
    subprocess.run(["umount", "-l", where], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def case_directory(out, case):
    os.makedirs(os.path.join(out, "O", case["name"], "keep"))
    rc, text = run(command(os.path.join(out, "O")))
    return one_line_failure(rc, text, [case["name"], "is a directory"], out)


def case_file(out, case):
    os.makedirs(os.path.join(out, "O"))
    with open(os.path.join(out, "O", case["name"]), "w") as f:
        f.write("not a folder\n")
    rc, text = run(command(os.path.join(out, "O")))
    return one_line_failure(rc, text, [case["name"], "ot a directory"], out)


def case_readonly(out, case):
    o = os.path.join(out, "O")
    os.makedirs(o)
    why = mount(["--bind", o], o)
    if why:
        return why
    try:
        why = mount(["-o", "remount,bind,ro"], o)
        if why:
            return why
        rc, text = run(command(o))
        return one_line_failure(rc, text, ["O'", "(option -output_dir)"], out)
    finally:
        umount(o)


def rows(path):
    with open(path) as f:
        return f.read().splitlines()


def ranks_of(session):
    """The poroseam processes of a process group started with start_new_session."""
    pids = []
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            with open(f"/proc/{entry}/comm") as f:
                name = f.read().strip()
        except OSError:
            continue
        if int(fields[3]) == session and name == "poroseam":  # fields[3]: the session id
            pids.append(int(entry))
    return pids


def case_concurrent(out, case):
    o = os.path.join(out, "O")
    # the first run (60 steps) is paused (SIGSTOP to its ranks) once it has written rows, so
    # that it certainly holds the directory while the second starts, however busy the machine
    first_cmd = ["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o,
                 "-ts_max_time", "12"]
    print("run (first, in the background):", " ".join(first_cmd), flush=True)
    log = open(os.path.join(out, "first.txt"), "w+")
    first = subprocess.Popen(first_cmd, cwd=SOURCE, env=env(), stdout=log,
                             stderr=subprocess.STDOUT, start_new_session=True)
    failures = []
    stopped = []
    try:
        t0 = time.time()
        csv = os.path.join(o, "timeseries.csv")
        while not (os.path.exists(csv) and len(rows(csv)) >= 3) and first.poll() is None:
            if time.time() - t0 > TIMEOUT:
                return ["the first run wrote no rows in time"]
            time.sleep(0.01)
        stopped = ranks_of(first.pid)
        for pid in stopped:
            os.kill(pid, signal.SIGSTOP)
        if first.poll() is not None or len(stopped) != 2:
            return [f"the first run ended before it could be paused ({len(stopped)} ranks)"]
        rc, text = run(["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o,
                        "-ts_max_time", "0.4"])
        failures += one_line_failure(rc, text, ["'" + o + "' is in use by another run (pid"], out)
        for pid in stopped:
            os.kill(pid, signal.SIGCONT)
        stopped = []
        first.wait(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return failures + ["the first run did not end (hang)"]
    finally:
        for pid in stopped:
            os.kill(pid, signal.SIGCONT)
        if first.poll() is None:
            os.killpg(first.pid, signal.SIGKILL)
            first.wait()
    log.seek(0)
    text1 = log.read()
    if first.returncode != 0:
        failures.append(f"the first run ended with {first.returncode}:\n" + text1[-2000:])
    # the first run's series is its own: steps 0, 1, 2, ... to its final time, 12 s
    lines = rows(os.path.join(o, "timeseries.csv"))[1:]
    steps = [int(l.split(",")[0]) for l in lines]
    if steps != list(range(len(steps))) or abs(float(lines[-1].split(",")[1]) - 12.0) > 1e-9:
        failures.append(f"the first run's timeseries.csv: steps {steps[:3]}...{steps[-3:]}, "
                        f"last row {lines[-1][:40]}")
    # the lock went with the first run: a third run in the directory works
    rc, text = run(["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o,
                    "-ts_max_time", "0.4"])
    if rc != 0:
        failures.append(f"a run after the first ended with {rc}:\n" + text[-2000:])
    return failures


def case_killed(out, case):
    o = os.path.join(out, "O")
    cmd = ["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o]
    print("run (killed with SIGKILL after 2 rows):", " ".join(cmd), flush=True)
    # its own process group: SIGKILL to mpiexec and the ranks at once, as a node failure would
    p = subprocess.Popen(cmd, cwd=SOURCE, env=env(), stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, start_new_session=True)
    t0 = time.time()
    csv = os.path.join(o, "timeseries.csv")
    while not (os.path.exists(csv) and len(rows(csv)) >= 3) and p.poll() is None:
        if time.time() - t0 > TIMEOUT:
            break
        time.sleep(0.05)
    if p.poll() is None:
        os.killpg(p.pid, signal.SIGKILL)
    p.wait()
    time.sleep(0.5)
    rc, text = run(["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o,
                    "-ts_max_time", "0.4"])
    return [] if rc == 0 else [f"the run after a killed one ended with {rc}:\n" + text[-2000:]]


def case_symlink(out, case):
    o = os.path.join(out, "O")
    target = os.path.join(out, "target")
    os.makedirs(o)
    os.makedirs(target)
    # what a careless user keeps there: files named as poroseam's own
    for n in ["step-000001.h5", "step-000002.h5", "terzaghi_column_2d.msh", "gmsh.log", "x.csv"]:
        with open(os.path.join(target, n), "w") as f:
            f.write("precious " + n + "\n")
    os.utime(os.path.join(target, "x.csv"), (1e9, 1e9))
    what = case["what"]
    if what in ("checkpoints", "mesh"):
        link, expect = os.path.join(o, what), what
        os.symlink(target, link)
    elif what == "file":
        link, expect = os.path.join(o, "timeseries.csv"), "timeseries.csv"
        os.symlink(os.path.join(target, "x.csv"), link)
    else:
        os.makedirs(os.path.join(o, "checkpoints"))
        link, expect = os.path.join(o, "checkpoints", "step-000002.h5"), "step-000002.h5"
        os.symlink(os.path.join(target, "step-000002.h5"), link)
    before = snapshot(target)
    time.sleep(0.01)
    # a run that would write a checkpoint and mesh a .geo (into mesh/)
    rc, text = run(["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o,
                    "-ts_max_time", "0.4", "-checkpoint_every", "1"])
    failures = one_line_failure(rc, text, [expect, "symbolic link"], out)
    after = snapshot(target)
    if after != before:
        changed = sorted(set(before) ^ set(after)) + \
            [k for k in before if k in after and before[k] != after[k]]
        failures.append(f"the link's target changed: {changed}")
    if not os.path.islink(link):
        failures.append("the link itself was removed or replaced")
    return failures


def xdmf_datasets(path):
    """The HDF5 dataset paths a .xmf file names."""
    names = []
    for item in ET.parse(path).iter("DataItem"):
        text = (item.text or "").strip()
        if ":" in text:
            names.append(text.split(":", 1)[1])
    return names


def check_readable(o):
    """After a full disk: every file opens and names only what exists; whole CSV rows."""
    failures = []
    import h5py  # noqa: E402 (only these cases need it)
    h5 = os.path.join(o, "fields.h5")
    xmf = os.path.join(o, "fields.xmf")
    if os.path.exists(h5):
        try:
            with h5py.File(h5, "r") as f:
                missing = [d for d in xdmf_datasets(xmf) if d not in f] \
                    if os.path.exists(xmf) else []
                steps = len(f["fields/displacement"]) if "fields/displacement" in f else 0
                for d in xdmf_datasets(xmf) if os.path.exists(xmf) else []:
                    if d in f:
                        f[d][()]  # the values read
            print(f"    fields.h5: {steps} steps; fields.xmf names "
                  f"{len(xdmf_datasets(xmf)) if os.path.exists(xmf) else 0} datasets")
            if missing:
                failures.append(f"fields.xmf names datasets fields.h5 lacks: {missing[:5]}")
        except Exception as e:  # an unreadable file is the failure this case looks for
            failures.append(f"fields.h5 does not open: {e}")
    csv = os.path.join(o, "timeseries.csv")
    lines = open(csv).read().split("\n")
    if lines[-1] != "":
        failures.append(f"timeseries.csv ends in a partial row: {lines[-1]!r}")
    header = lines[0].split(",")
    for i, line in enumerate(lines[1:-1]):
        values = line.split(",")
        if len(values) != len(header):
            failures.append(f"row {i + 1} of timeseries.csv has {len(values)} values, "
                            f"header {len(header)}")
            break
        try:
            [float(v) for v in values]
        except ValueError:
            failures.append(f"row {i + 1} of timeseries.csv is not numbers: {line!r}")
            break
        if int(values[0]) != i:
            failures.append(f"row {i + 1} of timeseries.csv is step {values[0]}")
            break
    print(f"    timeseries.csv: {len(lines) - 2} whole rows")
    import yaml  # noqa: E402
    try:
        with open(os.path.join(o, "run.yaml")) as f:
            yaml.safe_load(f)
    except Exception as e:
        failures.append(f"run.yaml does not read: {e}")
    return failures


def case_disk_full(out, case):
    # the mesh first, outside the small file system (a .geo would be meshed into it)
    msh = os.path.join(out, "column.msh")
    subprocess.run(["gmsh", "-3", "-v", "1", "-format", "msh22", "-o", msh,
                    os.path.join(SOURCE, "meshes", "terzaghi_column_2d.geo")], check=True,
                   stdout=subprocess.DEVNULL)
    mnt = os.path.join(out, "mnt")
    os.makedirs(mnt)
    why = mount(["-t", "tmpfs", "-o", "size=1m", "tmpfs"], mnt)
    if why:
        return why
    try:
        # leave room for a few steps' fields, or (no fields) some 60 rows of the series
        st = os.statvfs(mnt)
        free = st.f_bavail * st.f_frsize
        room = 300 * 1024 if case["fields"] else 60 * 1024 if case.get("checkpoint") else \
            24 * 1024
        with open(os.path.join(mnt, "filler"), "wb") as f:
            f.write(b"\0" * (free - room))
        o = os.path.join(mnt, "O")
        cmd = ["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-mesh", msh,
               "-output_dir", o, "-output_fields_every", "1" if case["fields"] else "0"]
        if case.get("checkpoint"):
            cmd += ["-checkpoint_every", "1"]
        rc, text = run(cmd)
        expect = "no space left for the checkpoint" if case.get("checkpoint") else \
            "no space left for the fields" if case["fields"] else "No space left on device"
        failures = one_line_failure(rc, text, [expect], out)
        if rc != "timeout":
            failures += check_readable(o)
        return failures
    finally:
        umount(mnt)


def case_refused(out, case):
    o = os.path.join(out, "O")
    t0 = time.time()
    rc, text = run(["mpiexec", "-n", "2", EXE, "-options_file", BASE_SCENE, "-output_dir", o,
                    "-output_fields_every", "1", "-ts_max_time", "0.4", "-test_io_fail_rank",
                    case["rank"], "-io_agreement_timeout", "5"])
    one_rank = case["rank"] != "-1"
    failures = one_line_failure(rc, text, ["fields.h5", "test hook"], out, abort_ok=one_rank)
    if one_rank and time.time() - t0 > 60:
        failures.append(f"took {time.time() - t0:.0f} s with a grace of 5 s")
    if not one_rank and rc != "timeout":
        failures += check_readable(o)
    return failures


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case")
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()
    if a.list or not a.case:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(OUTPUT_ROOT, "faults", a.case)
    for d, _, _ in os.walk(out):  # mounts left by an interrupted earlier run
        if os.path.ismount(d):
            umount(d)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    result = globals()["case_" + {"directory": "directory", "file": "file",
                                  "readonly": "readonly", "concurrent": "concurrent",
                                  "killed": "killed", "symlink": "symlink",
                                  "disk_full": "disk_full",
                                  "refused": "refused"}[case["kind"]]](out, case)
    if isinstance(result, str):
        print(f"SKIP {a.case}: {result}")
        return SKIP
    if result:
        print(f"FAIL {a.case}:\n  " + "\n  ".join(result))
        return 1
    print(f"PASS {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
