"""Running things for the benchmark: building the two helper programs, running an MPI job with
a time limit (killing its whole process group when it overruns), the triad and the reference
solve."""

import os
import signal
import subprocess
import time

import parse

PETSC_PKGCONFIG = "/usr/lib/petscdir/petsc3.18/x86_64-linux-gnu-real/lib/pkgconfig"


def build(source, target, petsc=False):
    """Compiles a helper with mpicc when the binary is missing or older than its source."""
    if os.path.exists(target) and os.path.getmtime(target) >= os.path.getmtime(source):
        return target
    os.makedirs(os.path.dirname(target), exist_ok=True)
    flags = []
    if petsc:
        env = dict(os.environ)
        env["PKG_CONFIG_PATH"] = PETSC_PKGCONFIG + ":" + env.get("PKG_CONFIG_PATH", "")
        flags = subprocess.run(["pkg-config", "--cflags", "--libs", "PETSc"], env=env,
                               check=True, capture_output=True, text=True).stdout.split()
    subprocess.run(["mpicc", "-O2", "-o", target, source] + flags + ["-lm"], check=True)
    return target


def run(command, log_path, timeout, cwd=None):
    """Runs `command` (an mpiexec line) writing stdout and stderr to log_path. Returns
    (status, wall seconds, output) with status 'ok', 'failed' or 'timeout'. On timeout the job's
    process group (mpiexec and its ranks, started here) is terminated, then killed."""
    start = time.monotonic()
    with open(log_path, "w") as log:
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, cwd=cwd,
                                   start_new_session=True)
        try:
            process.wait(timeout=timeout)
            status = "ok" if process.returncode == 0 else "failed"
        except subprocess.TimeoutExpired:
            status = "timeout"
            os.killpg(process.pid, signal.SIGTERM)
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
    wall = time.monotonic() - start
    with open(log_path) as log:
        return status, wall, log.read()


def triad(executable, ranks, doubles, work_dir, attempts=2):
    """Best total bandwidth [GB/s] of `ranks` concurrent triad processes over `attempts` runs
    (each already the best of 10 repetitions)."""
    best = None
    for attempt in range(attempts):
        log = os.path.join(work_dir, f"stream_r{ranks}_{attempt}.txt")
        status, _, out = run(["mpiexec", "-n", str(ranks), executable, str(doubles), "10"], log,
                             timeout=300)
        result = parse.triad(out) if status == "ok" else None
        if result and (best is None or result["total_gbs"] > best["total_gbs"]):
            best = result
    return best


def reference(executable, ranks, unknowns, repeat, work_dir, timeout):
    """The reference elasticity solve with about `unknowns` unknowns on `ranks` ranks."""
    log = os.path.join(work_dir, f"reference_n{unknowns}_r{ranks}.txt")
    status, _, out = run(["mpiexec", "-n", str(ranks), executable, "-unknowns", str(unknowns),
                          "-repeat", str(repeat)], log, timeout=timeout)
    return parse.reference(out) if status == "ok" else None
